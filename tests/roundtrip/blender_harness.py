"""What every headless-Blender test script shares: the numpy patch Blender
3.4's glTF importer needs, the failure list and check(), the script's own
arguments (after "--") and the exit protocol. Blender exits 0 after a
script that raised, so run(main) turns any exception into exit 1, and
finish() exits 1 when any check failed (os._exit: Blender's own shutdown
must not change the status).

    sys.dont_write_bytecode = True  # before the import: no __pycache__ in the source tree
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import blender_harness as harness

    def main():
        args = parse(harness.script_args())
        harness.check(value <= tol, "what went wrong")
        harness.finish()

    if __name__ == "__main__":
        harness.run(main)
"""
import os
import sys
import traceback

import numpy as np

np.bool = bool  # Debian's numpy removed np.bool; Blender 3.4's glTF importer uses it

failures = []


def check(ok, message):
    """Records (and prints) `message` as a failure unless `ok`; returns `ok`."""
    if not ok:
        failures.append(message)
        print("FAIL:", message)
    return ok


def script_args():
    """The command-line words after Blender's "--" (none without it)."""
    return sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []


def finish(ok_message="OK"):
    """Prints the summary and exits: 1 if any check failed, else 0."""
    print("%d check(s) failed" % len(failures) if failures else ok_message)
    sys.stdout.flush()
    os._exit(1 if failures else 0)


def run(main):
    """Calls main(); any exception (argparse's SystemExit included) exits 1 with its traceback."""
    try:
        main()
    except BaseException:  # never leave Blender at exit 0 after an error
        traceback.print_exc()
        sys.stdout.flush()
        os._exit(1)
    finish()
