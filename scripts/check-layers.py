#!/usr/bin/env python3
"""Fails when a C++ file includes a header of a layer above its own.

The folder tree is the architecture (docs/architecture.md). Each layer may
include itself and the layers listed for it; tests/ may include anything.
Prints one line per violation ("file:line: <layer> must not include <header>")
and exits 1 if there is any.
    scripts/check-layers.py [ROOT]
"""
import pathlib
import re
import sys

# layer -> the layers it may include besides itself (lowest layer first).
ALLOWED = {
    "core": [],
    "core/math": ["core"],
    "core/io": ["core"],
    "core/io/pickle": ["core", "core/io"],
    "core/io/tree": ["core", "core/io", "core/io/pickle"],
    "core/models": ["core", "core/io", "core/io/pickle", "core/io/tree", "core/math"],
    "core/motions": ["core", "core/io", "core/io/pickle", "core/io/tree", "core/math",
                     "core/models"],
    "core/demo": ["core", "core/math"],
    "exporter": ["core", "core/math", "core/io", "core/models", "core/motions"],
    "writers": ["core", "core/math", "exporter", "writers/gltf", "writers/fbx", "writers/bvh",
                "writers/mjcf"],
    "writers/gltf": ["core", "core/math", "exporter", "writers"],
    "writers/fbx": ["core", "core/math", "exporter", "writers"],
    "writers/bvh": ["core", "core/math", "exporter", "writers"],
    "writers/mjcf": ["core", "core/math", "exporter", "writers"],
    # The export request, a top-level layer: above exporter/ and the writers (it
    # picks one), below the front ends (cli/, tools/) that fill it.
    "request": ["core", "core/math", "core/io", "core/io/pickle", "core/models", "core/motions", "core/demo",
                "exporter", "writers"],
    "cli": ["core", "core/math", "core/io", "core/models", "core/motions", "core/demo", "exporter", "writers",
            "request"],
    # The Python module: a front end beside cli/, whose option parser it reuses.
    "python": ["core", "core/math", "core/io", "core/models", "core/motions", "core/demo", "exporter",
               "writers", "request", "cli"],
    "tools": ["core", "core/math", "core/io", "core/models", "core/motions", "core/demo", "exporter",
              "writers", "writers/gltf", "writers/fbx", "request", "tools/bench"],
    "tools/bench": ["core", "core/math", "core/io", "core/models", "core/motions", "core/demo", "exporter",
                    "writers", "request", "tools"],
    "tools/reference": ["core", "core/math", "core/io", "core/models", "core/motions", "core/demo", "exporter",
                        "request", "cli"],
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def layer_of(path):
    """The deepest layer folder that holds `path` (a repository-relative str), or None."""
    folder = str(pathlib.PurePosixPath(path).parent)
    while folder not in ALLOWED:
        if "/" not in folder:
            return None
        folder = folder.rsplit("/", 1)[0]
    return folder


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    problems = 0
    files = 0
    for path in sorted(root.rglob("*")):
        rel = path.relative_to(root).as_posix()
        if path.suffix not in (".h", ".cpp") or rel.startswith(("build", "tests/", ".")):
            continue
        layer = layer_of(rel)
        if layer is None:
            continue
        files += 1
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            match = INCLUDE.match(line)
            if not match:
                continue
            target = layer_of(match.group(1))
            if target is None:
                print(f"{rel}:{number}: include \"{match.group(1)}\" is not in a known layer")
                problems += 1
            elif target != layer and target not in ALLOWED[layer]:
                print(f"{rel}:{number}: {layer} must not include {match.group(1)} ({target})")
                problems += 1
    print(f"check-layers: {files} files, {problems} violations")
    return 1 if problems else 0


if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    print(__doc__.strip())  # --help: the usage above, and nothing else
    sys.exit(0)

if __name__ == "__main__":
    sys.exit(main())
