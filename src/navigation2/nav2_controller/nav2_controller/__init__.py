"""Nav2 controller_server and its goal and progress checkers (Python stand-in)."""
