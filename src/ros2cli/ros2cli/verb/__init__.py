"""The `ros2 daemon` command's verbs (ros2cli.verb.daemon), one module each, in the shape of every
command's verbs: HELP, add_arguments(parser), main(args, context). What a verb gets and gives
back is in ros2cli.verb_context; the graph verbs' common options in ros2cli.command.
"""
