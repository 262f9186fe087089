"""FilePath: what launch accepts as a file path."""

import os

FilePath = str | bytes | os.PathLike
