"""Nav2 Jazzy's AMCL in Python: the particle filter core (see the package README)."""
