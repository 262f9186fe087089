from ros2topic.verb import VerbExtension


class HzVerb(VerbExtension):
    VERB = 'hz'
