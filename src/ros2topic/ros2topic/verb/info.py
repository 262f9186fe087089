from ros2topic.verb import VerbExtension


class InfoVerb(VerbExtension):
    VERB = 'info'
