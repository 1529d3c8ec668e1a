#!/usr/bin/env python3
"""The CLI's options are described once (cli/options.cpp); this checks the
two places that repeat them for readers:

- the README's option table (after "Options (`smpl-export --help`):") names
  exactly the options `smpl-export --help` lists;
- docs/cli.md holds the `--help` text verbatim between its
  `<!-- help:begin -->` and `<!-- help:end -->` markers.

    check-cli-docs.py SMPL_EXPORT REPO [--write]

--write regenerates the docs/cli.md block instead of checking it. Exit 1
with a line per difference.
"""
import re
import subprocess
import sys


def help_options(help_text):
    names = set()
    for line in help_text.splitlines():
        if line.startswith("  -"):
            left = line[2:].split("  ")[0]  # "--quiet, -q", "--max-influences N"
            names.update(re.findall(r"(?<![\w|-])(--[a-z][a-z0-9-]*|-[a-zA-Z])\b", left))
    return names


def option_column(line):
    cells = line.split("|")
    return cells[1] if len(cells) > 2 else ""


def readme_options(readme):
    start = readme.index("Options (`smpl-export --help`):")
    table = []
    for line in readme[start:].splitlines()[1:]:
        if not line.strip() and table:
            break
        if line.startswith("|"):
            table.append(line)
    names = set()
    for line in table[2:]:
        names.update(re.findall(r"`(--[a-z][a-z0-9-]*|-[a-zA-Z])\b", option_column(line.replace("\\|", "/"))))
        names.update(re.findall(r",\s*(-[a-zA-Z])\b", option_column(line)))
    return names


def main():
    exe, repo = sys.argv[1], sys.argv[2]
    write = "--write" in sys.argv[3:]
    help_text = subprocess.run([exe, "--help"], check=True, capture_output=True, text=True).stdout
    problems = []
    listed = help_options(help_text)
    with open(f"{repo}/README.md", encoding="utf-8") as f:
        documented = readme_options(f.read())
    for name in sorted(listed - documented):
        problems.append(f"README.md: option table lacks {name} (listed by --help)")
    for name in sorted(documented - listed):
        problems.append(f"README.md: option table names {name}, which --help does not list")
    path = f"{repo}/docs/cli.md"
    with open(path, encoding="utf-8") as f:
        doc = f.read()
    m = re.search(r"(<!-- help:begin -->\n```text\n)(.*?)(```\n<!-- help:end -->)", doc, re.S)
    if not m:
        problems.append(f"{path}: no <!-- help:begin --> ```text ... ``` <!-- help:end --> block")
    elif write:
        with open(path, "w", encoding="utf-8") as f:
            f.write(doc[: m.start(2)] + help_text + doc[m.end(2):])
    elif m.group(2) != help_text:
        problems.append(f"{path}: the --help block differs from `smpl-export --help` "
                        f"(regenerate: scripts/check-cli-docs.py build/cli/smpl-export . --write)")
    for p in problems:
        print(p)
    print(f"{len(listed)} options in --help; {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
