"""Nav2 Regulated Pure Pursuit controller (Python stand-in)."""
