"""Nav2 map server, map saver and map_io (Python stand-in for upstream's C++ package)."""
