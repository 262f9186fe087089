from ros2topic.verb import VerbExtension


class PubVerb(VerbExtension):
    VERB = 'pub'
