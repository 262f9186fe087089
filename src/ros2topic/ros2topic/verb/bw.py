from ros2topic.verb import VerbExtension


class BwVerb(VerbExtension):
    VERB = 'bw'
