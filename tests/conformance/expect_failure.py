"""Runs a loader on a perturbed conformance kit and passes only if it fails
the way a wrong expected value must: a non-zero exit and a line naming the
perturbed case and quantity (docs/conformance.md, "Proving a loader").

    expect_failure.py REGEX COMMAND [ARGS...]
"""
import re
import subprocess
import sys


def main(argv):
    if len(argv) < 2:
        print("usage: expect_failure.py REGEX COMMAND [ARGS...]", file=sys.stderr)
        return 2
    pattern, command = re.compile(argv[0]), argv[1:]
    run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, errors="replace")
    hits = [line for line in run.stdout.splitlines() if pattern.search(line)]
    if run.returncode == 0:
        print(run.stdout[-3000:])
        print(f"expect_failure: {command[0]} passed on the perturbed kit (exit 0): the loader does not check")
        return 1
    if not hits:
        print(run.stdout[-3000:])
        print(f"expect_failure: {command[0]} failed (exit {run.returncode}) but no line matches {argv[0]!r}")
        return 1
    print(f"expect_failure: exit {run.returncode}, as expected: {hits[0].strip()}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
