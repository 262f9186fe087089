"""SubstitutionFailure: a substitution could not be worked out (missing variable, ...)."""


class SubstitutionFailure(RuntimeError):
    pass
