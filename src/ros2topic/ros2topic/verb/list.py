from ros2topic.verb import VerbExtension


class ListVerb(VerbExtension):
    VERB = 'list'
