#!/usr/bin/python3
"""The build commands of the README and the docs pages work after the README's quick start.

The quick start configures `build` with its own flags (read from the README's
quick-start line, e.g. -DSMPL_BUILD_TESTS=OFF). This configures a fresh
directory the same way (configure only: seconds) and checks that

- every target of a README `cmake --build build --target T ...` line exists
  there (a tool left out of the configuration fails with "No rule to make
  target");
- every program the README runs as `build/<dir>/<name>` is built by the quick
  start itself (smpl-export) or by one of those --target lines.

    readme_build_commands.py SOURCE_DIR WORK_DIR [CMAKE]
Exit 1 with one line per problem.
"""
import glob
import os
import re
import shlex
import shutil
import subprocess
import sys


def quick_start_flags(readme):
    line = next(l for l in readme.splitlines() if "cmake -S . -B build" in l)
    args = shlex.split(line.split("cmake -S . -B build", 1)[1].split("&&")[0])
    return [a for a in args if a.startswith("-D")]


def target_lines(readme):
    targets = []
    for m in re.finditer(r"cmake --build build --target ([A-Za-z0-9_ -]+?)(?:`|$| #|\n)", readme, re.M):
        targets += [t for t in m.group(1).split() if not t.startswith("-")]
    return targets


def main():
    src, work = sys.argv[1], sys.argv[2]
    cmake = sys.argv[3] if len(sys.argv) > 3 else "cmake"
    with open(os.path.join(src, "README.md"), encoding="utf-8") as f:
        readme = f.read()
    flags = quick_start_flags(readme)
    # The --target lines and build/... programs of the README and of the docs pages it links to.
    for page in sorted(glob.glob(os.path.join(src, "docs", "*.md"))):
        with open(page, encoding="utf-8") as f:
            readme += "\n" + f.read()
    build = os.path.join(work, "quickstart-build")
    shutil.rmtree(build, ignore_errors=True)
    r = subprocess.run([cmake, "-S", src, "-B", build, "-DCMAKE_BUILD_TYPE=Release"] + flags,
                       capture_output=True, text=True)
    if r.returncode != 0:
        print("configure failed:", r.stdout[-2000:], r.stderr[-2000:])
        return 1
    listing = subprocess.run([cmake, "--build", build, "--target", "help"], capture_output=True,
                             text=True).stdout
    known = set(re.findall(r"^\.\.\. ([A-Za-z0-9_.-]+)", listing, re.M))
    problems = []
    targets = target_lines(readme)
    for t in targets:
        if t not in known:
            problems.append(f"README: `cmake --build build --target {t}` fails after the quick start "
                            f"({' '.join(flags)}): no such target")
    for prog in sorted(set(re.findall(r"\bbuild/(?:tools|cli)/([A-Za-z0-9_-]+)", readme))):
        if prog != "smpl-export" and prog not in targets:
            problems.append(f"README: runs build/.../{prog}, which no README `--target` line builds")
    for p in problems:
        print(p)
    print(f"quick-start flags {flags}; {len(targets)} README targets; {len(problems)} problems")
    shutil.rmtree(build, ignore_errors=True)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
