"""The node a command line tool talks to the graph with: the daemon's or its own."""

# The name prefix of the CLI's hidden nodes (`_ros2cli_<pid>`), as upstream's.
NODE_NAME_PREFIX = '_ros2cli'
