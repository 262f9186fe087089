from node_runtime import quiet_ctrl_c_while_starting

# Ctrl-C while dummy_sensors still imports: exit 130 without a traceback.
quiet_ctrl_c_while_starting('dummy_sensors')
