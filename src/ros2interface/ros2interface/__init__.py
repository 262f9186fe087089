"""ros2interface: the `ros2 interface` command (command/interface.py), one module per verb
(verb/), and what other code may import (api/)."""
