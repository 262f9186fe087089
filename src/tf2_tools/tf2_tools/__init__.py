from node_runtime import quiet_ctrl_c_while_starting

# Ctrl-C while view_frames still imports: exit 130 without a traceback.
quiet_ctrl_c_while_starting('tf2_tools')
