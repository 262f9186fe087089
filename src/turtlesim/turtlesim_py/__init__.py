"""Python implementation of the turtlesim simulator and its tutorial executables.

The generated interface package is called `turtlesim`; this code lives in `turtlesim_py`.
"""

from node_runtime import quiet_ctrl_c_while_starting

quiet_ctrl_c_while_starting('turtlesim')
