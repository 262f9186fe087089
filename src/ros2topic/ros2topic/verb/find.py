from ros2topic.verb import VerbExtension


class FindVerb(VerbExtension):
    VERB = 'find'
