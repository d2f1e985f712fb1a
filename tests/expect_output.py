#!/usr/bin/python3
"""A ctest that checks both the exit status and the output of a command.

    expect_output.py EXIT_CODE REGEX COMMAND [ARG ...]

Runs COMMAND, echoes its standard output and error (merged, as ctest shows them), and passes
only when the command exited with EXIT_CODE and the output matches REGEX (Python's re, searched,
'.' matching newlines too, as CMake's PASS_REGULAR_EXPRESSION matched). CTest's own
PASS_REGULAR_EXPRESSION ignores the exit code: a run that printed its line and then failed
passed. Exit status: 0 pass; 1 otherwise, with the reason on the last line.
"""
import re
import subprocess
import sys


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    expected, pattern, command = int(argv[1]), argv[2], argv[3:]
    try:
        r = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    except OSError as e:
        print(f"expect_output: cannot run {command[0]}: {e}")
        return 1
    text = r.stdout.decode("utf-8", errors="replace")
    sys.stdout.write(text)
    if not text.endswith("\n"):
        sys.stdout.write("\n")
    problems = []
    if r.returncode != expected:
        problems.append(f"exit status {r.returncode}, expected {expected}")
    if not re.search(pattern, text, re.DOTALL):
        problems.append(f"the output does not match {pattern!r}")
    if problems:
        print("expect_output: FAILED: " + "; ".join(problems))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
