#!/usr/bin/env python3
"""Fails when smpl-export's code does what only works (or only gives the same bytes) on one OS.

1. Outputs must be byte-identical on every platform and CPU, so the code that
   computes them (cli/, request/, core/, exporter/, writers/) calls core/math/libm.h
   (smpl::libm::sin ...: musl's libm everywhere) and core/math/rotation.h, never
   std::sin & co nor Eigen's AngleAxis, slerp or eulerAngles (which call the C
   library's).
2. Paths are UTF-8 strings: a std::filesystem::path is made with os::fsPath()
   and turned back with os::utf8() / os::genericUtf8() (core/os/path.h), never
   fs::path(std::string) or .string(), which are Latin-1 on Windows.
Prints one line per finding ("file:line: ...") and exits 1 if there is any.
    scripts/check-portable.py [ROOT]
"""
import pathlib
import re
import sys

FOLDERS = ("cli", "request", "core", "exporter", "writers")
ALLOWED = {"core/math/libm.h", "core/math/rotation.h", "core/math/rotation.cpp", "core/os/path.h"}
FUNCS = "sin|cos|tan|asin|acos|atan|atan2|exp|exp2|expm1|log|log2|log10|log1p|pow|hypot|cbrt|" \
        "sinh|cosh|tanh|asinh|acosh|atanh|erf|erfc|tgamma|lgamma|sincos"
CALL = re.compile(r"(?<![\w:.])(?:std::|::)?(" + FUNCS + r")f?\s*\(")
PATH = re.compile(r"\b(?:fs|filesystem)::path\s*\(|\.(?:generic_)?string\(\)")
EIGEN = re.compile(r"\b(AngleAxis[fd]?|eulerAngles)\b|\.(slerp)\s*\(")


def code_of(line):
    """The line without its // comment and string literals (roughly)."""
    line = re.sub(r'"(\\.|[^"\\])*"', '""', line)
    return line.split("//", 1)[0]


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    problems = files = 0
    for folder in FOLDERS:
        for path in sorted((root / folder).rglob("*")):
            rel = path.relative_to(root).as_posix()
            if path.suffix not in (".h", ".cpp") or rel in ALLOWED:
                continue
            files += 1
            for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
                code = code_of(line)
                for m in CALL.finditer(code):
                    if re.search(r"\b(double|float|int|auto|bool|void)\s+$", code[: m.start()]):
                        continue  # a declaration of our own function with that name
                    print(f"{rel}:{number}: use smpl::libm::{m.group(1)} (core/math/libm.h), "
                          f"not the C library's")
                    problems += 1
                for m in PATH.finditer(code):
                    print(f"{rel}:{number}: use os::fsPath() / os::utf8() (core/os/path.h), not "
                          f"'{m.group(0)}' (Latin-1 on Windows)")
                    problems += 1
                for m in EIGEN.finditer(code):
                    print(f"{rel}:{number}: use core/math/rotation.h, not Eigen's {m.group(1) or m.group(2)} "
                          f"(it calls the C library's sin/cos/acos)")
                    problems += 1
    print(f"check-portable: {files} files, {problems} findings")
    return 1 if problems else 0


if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    print(__doc__.strip())  # --help: the usage above, and nothing else
    sys.exit(0)

if __name__ == "__main__":
    sys.exit(main())
