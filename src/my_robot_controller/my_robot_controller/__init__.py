"""The course's nodes: turtle_controller, the AddTwoInts server and client, the demo."""


from node_runtime import quiet_ctrl_c_while_starting

quiet_ctrl_c_while_starting('my_robot_controller')
