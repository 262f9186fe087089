"""Nav2's costmap_2d in Python: grids, layers and footprints with upstream's names and values."""
