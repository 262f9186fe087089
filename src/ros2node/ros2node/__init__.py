"""ros2node: the `ros2 node` command (command/node.py), one module per verb
(verb/), and what other code may import (api/)."""
