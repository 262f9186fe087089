"""Nav2 lifecycle manager (Python stand-in for upstream's C++ package)."""
