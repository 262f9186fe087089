"""`ros2 run demo_nodes_cpp use_logger_service`: the same demo as demo_nodes_py's (node names,
topic, services and lines are the same in both)."""
import sys

from demo_nodes_py.logging.use_logger_service import main

if __name__ == '__main__':
    sys.exit(main())
