"""Nav2 MPPI controller (Python stand-in, numpy)."""
