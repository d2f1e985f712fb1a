#!/usr/bin/python3
"""`rupture plot DIR`: the figures of a run or a sweep (rupture/plot.py, the package's module;
this file only finds the package: beside it in the checkout, or in the build tree's python/
folder next to bin/, where CMake copies it)."""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
for folder in (here, os.path.join(here, "..", "python")):
    if os.path.isfile(os.path.join(folder, "rupture", "plot.py")):
        sys.path.insert(0, os.path.abspath(folder))
        break

from rupture.plot import main  # noqa: E402

if __name__ == "__main__":
    main()
