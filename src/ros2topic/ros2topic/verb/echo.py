from ros2topic.verb import VerbExtension


class EchoVerb(VerbExtension):
    VERB = 'echo'
