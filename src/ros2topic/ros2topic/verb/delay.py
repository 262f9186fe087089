from ros2topic.verb import VerbExtension


class DelayVerb(VerbExtension):
    VERB = 'delay'
