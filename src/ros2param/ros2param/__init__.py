"""ros2param: the `ros2 param` command (command/param.py), one module per verb
(verb/), and what other code may import (api/)."""
