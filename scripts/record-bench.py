#!/usr/bin/python3
"""Run a benchmark and record its table for the docs.

    scripts/record-bench.py NAME -- COMMAND [ARG ...]

Runs COMMAND (a benchmark that prints a Markdown table: tools/bench/preset_table.py,
smpl-bench --compare, bench/*.py), echoes its output, and writes the table lines it
printed (lines starting with "|") to bench/results/NAME.md under one provenance line:
the command, the date, the commit, the cores and the load average before the run.
The docs show these files' tables between `<!-- bench:NAME -->` and
`<!-- bench:end -->` markers; scripts/check-doc-numbers.py checks (test
docs.numbers) and with --write refreshes those blocks, so a number in a docs
table is the benchmark's own output, never typed by hand.
Exit: the command's exit code (nothing recorded when it fails or prints no table).
"""
import datetime
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def provenance(command):
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip() or "unknown"
    dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--untracked-files=no"],
                           capture_output=True, text=True).stdout.strip()
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    shown = " ".join(os.path.relpath(a, ROOT) if os.path.isabs(a) and a.startswith(ROOT) else a
                     for a in command)
    return (f"Recorded {datetime.date.today().isoformat()} by `scripts/record-bench.py` from "
            f"`{shown}` at commit {commit}{' (with local changes)' if dirty else ''}, "
            f"{os.cpu_count()} cores, load average {load:.1f} before the run.")


def main(argv):
    if len(argv) < 2 or argv[0] in ("-h", "--help") or "--" not in argv:
        print(__doc__.strip())
        return 0 if argv[:1] in (["-h"], ["--help"]) else 1
    name, command = argv[0], argv[argv.index("--") + 1:]
    if not name.replace("_", "").replace("-", "").isalnum() or not command:
        print("record-bench: NAME is letters, digits, '-' and '_'; a command follows --", file=sys.stderr)
        return 1
    header = provenance(command)
    run = subprocess.run(command, stdout=subprocess.PIPE, text=True)
    sys.stdout.write(run.stdout)
    table = [line.rstrip() for line in run.stdout.splitlines() if line.startswith("|")]
    if run.returncode != 0 or not table:
        print(f"record-bench: {command[0]} exited {run.returncode} with {len(table)} table lines; "
              "nothing recorded", file=sys.stderr)
        return run.returncode or 1
    path = os.path.join(ROOT, "bench", "results", name + ".md")
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(header + "\n\n" + "\n".join(table) + "\n")
    os.replace(tmp, path)
    print(f"record-bench: {len(table)} table lines -> {os.path.relpath(path, ROOT)}; "
          "refresh the docs: scripts/check-doc-numbers.py --write")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
