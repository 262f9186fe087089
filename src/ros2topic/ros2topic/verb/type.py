from ros2topic.verb import VerbExtension


class TypeVerb(VerbExtension):
    VERB = 'type'
