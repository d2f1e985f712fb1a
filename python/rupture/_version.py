# The package's version: the project's (CMakeLists.txt, project(... VERSION)); a test checks that
# `rupture --version` prints the same.
__version__ = "0.1.0"
