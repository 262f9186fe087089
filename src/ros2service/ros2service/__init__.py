"""ros2service: the `ros2 service` command (command/service.py), one module per verb
(verb/), and what other code may import (api/)."""
