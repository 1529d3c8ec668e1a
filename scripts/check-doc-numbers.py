#!/usr/bin/python3
"""Docs tables that are a benchmark's output equal that output.

    scripts/check-doc-numbers.py [ROOT] [--write]      (ROOT: the sources, default this clone)

A docs page (README.md, docs/*.md) shows a recorded benchmark table between
`<!-- bench:NAME -->` and `<!-- bench:end -->`; bench/results/NAME.md holds what
scripts/record-bench.py wrote from the benchmark's own stdout (a provenance line,
then the table). Between the markers the page must hold exactly that file's
content: an edited number, a table with no recording or a recording no page shows
is a problem. --write copies each recording into its blocks instead of checking.
Exit 1 on a problem (one line each), 0 otherwise.
"""
import glob
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # replaced by a ROOT argument
BLOCK = re.compile(r"(<!-- bench:([A-Za-z0-9_-]+) -->\n)(.*?)(<!-- bench:end -->)", re.S)


def pages():
    return [os.path.join(ROOT, "README.md")] + sorted(glob.glob(os.path.join(ROOT, "docs", "*.md")))


def main(argv):
    if {"-h", "--help"} & set(argv):
        print(__doc__.strip())
        return 0
    global ROOT
    write = "--write" in argv
    roots = [a for a in argv if not a.startswith("-")]
    if roots:
        ROOT = os.path.abspath(roots[0])
    problems, shown = [], set()
    for page in pages():
        with open(page, encoding="utf-8") as f:
            text = f.read()
        rel = os.path.relpath(page, ROOT)

        def fill(m):
            name = m.group(2)
            shown.add(name)
            path = os.path.join(ROOT, "bench", "results", name + ".md")
            if not os.path.exists(path):
                problems.append(f"{rel}: table '{name}' has no recording bench/results/{name}.md "
                                "(record it: scripts/record-bench.py)")
                return m.group(0)
            with open(path, encoding="utf-8") as f:
                recorded = f.read()
            if m.group(3) != recorded and not write:
                problems.append(f"{rel}: table '{name}' differs from bench/results/{name}.md "
                                "(a number typed by hand? refresh: scripts/check-doc-numbers.py --write)")
            return m.group(1) + recorded + m.group(4)

        new = BLOCK.sub(fill, text)
        if write and new != text:
            with open(page, "w", encoding="utf-8") as f:
                f.write(new)
    for path in sorted(glob.glob(os.path.join(ROOT, "bench", "results", "*.md"))):
        name = os.path.basename(path)[:-3]
        if name not in shown:
            problems.append(f"bench/results/{name}.md: no page shows it (<!-- bench:{name} -->)")
    for p in problems:
        print(p)
    print(f"{len(shown)} recorded benchmark tables in the docs; {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
