"""ros2lifecycle: the `ros2 lifecycle` command (command/lifecycle.py), one module per verb
(verb/), and what other code may import (api/)."""
