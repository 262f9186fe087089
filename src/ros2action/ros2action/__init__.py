"""ros2action: the `ros2 action` command (command/action.py), one module per verb
(verb/), and what other code may import (api/)."""
