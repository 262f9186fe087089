from node_runtime import quiet_ctrl_c_while_starting

# Ctrl-C while joint_state_publisher still imports: exit 130 without a traceback.
quiet_ctrl_c_while_starting('joint_state_publisher')
