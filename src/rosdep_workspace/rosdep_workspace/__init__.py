"""rosdep for this workspace: PyPI's rosdep with local sources (see docs/rosdep.md)."""
