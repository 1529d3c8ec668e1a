#!/usr/bin/env python3
"""Fails when a source or test file cites an issue ("issue 25", "(issue
"Speed and size")", "Issue 13's goal"): comments say why, and issue numbers
mean nothing to a reader of the repository. Usage: check-issue-refs.py [ROOT]"""
import os
import re
import sys

PATTERN = re.compile(r"\b[Ii]ssues? ?#?\d+|\([Ii]ssue \"|\b[Ii]ssue \"[A-Z]")
EXTENSIONS = (".cpp", ".h", ".py", ".sh", ".cmake", ".mjs", ".js", ".cs", ".gd")
SKIP_DIRS = {".git", "node_modules", "dist"}


def main(root):
    if len(sys.argv) > 1 and sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0
    found = []
    for folder, dirs, files in os.walk(root):
        dirs[:] = [d for d in dirs if d not in SKIP_DIRS and not d.startswith("build")]
        for name in files:
            if not (name.endswith(EXTENSIONS) or name == "CMakeLists.txt"):
                continue
            path = os.path.join(folder, name)
            with open(path, encoding="utf-8", errors="replace") as fh:
                for number, line in enumerate(fh, 1):
                    if PATTERN.search(line) and path != os.path.abspath(__file__):
                        found.append("%s:%d: %s" % (os.path.relpath(path, root), number, line.strip()))
    for line in found:
        print(line)
    print("check-issue-refs: %d issue references" % len(found))
    return 1 if found else 0


if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    print(__doc__.strip())  # --help: the usage above, and nothing else
    sys.exit(0)

if __name__ == "__main__":
    sys.exit(main(os.path.abspath(sys.argv[1] if len(sys.argv) > 1 and not sys.argv[1].startswith("-") else
                                  os.path.join(os.path.dirname(__file__), ".."))))
