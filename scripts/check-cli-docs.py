#!/usr/bin/env python3
"""The CLI's options are described once (cli/options.cpp); this checks the
two places that repeat them for readers:

- docs/options.md's option table (after "Options (`smpl-export --help`):") names
  exactly the options `smpl-export --help` lists;
- docs/cli.md holds the `--help` text verbatim between its
  `<!-- help:begin -->` and `<!-- help:end -->` markers.

    check-cli-docs.py SMPL_EXPORT REPO [--write]

- every `--help` line fits a terminal's 80 columns;
- every option docs/cli.md names (`--name` in its prose and tables) is one
  `--help` lists;
- docs/cli.md's claims about what the program does (CLAIMS: each a sentence
  of the doc, whitespace-normalised, and a run of the built-in body that must
  bear it out), so a claim the binary contradicts fails here.

--write regenerates the docs/cli.md block instead of checking it. Exit 1
with a line per difference.
"""
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cli_help  # noqa: E402

HELP_WIDTH = 80


def run(exe, args, cwd, stdout=subprocess.PIPE):
    return subprocess.run([exe] + args, cwd=cwd, stdout=stdout, stderr=subprocess.PIPE, text=True)


def gltf_beside(exe, cwd):
    r = run(exe, ["--model", "builtin", "--out", "t.gltf", "-q"], cwd)
    return r.returncode == 0 and os.path.isfile(os.path.join(cwd, "t.bin")), "exit %d, t.bin %s" % (
        r.returncode, "written" if os.path.isfile(os.path.join(cwd, "t.bin")) else "missing")


def gltf_embed(exe, cwd):
    r = run(exe, ["--model", "builtin", "--out", "e.gltf", "--gltf-embed", "-q"], cwd)
    embedded = False
    if r.returncode == 0:
        with open(os.path.join(cwd, "e.gltf"), encoding="utf-8") as f:
            embedded = "data:application/octet-stream;base64," in f.read()
    bin_there = os.path.exists(os.path.join(cwd, "e.bin"))
    return r.returncode == 0 and embedded and not bin_there, "exit %d, data URI %s, e.bin %s" % (
        r.returncode, embedded, "written" if bin_there else "absent")


def exit_code(args, want, stderr_has=None, stdout=subprocess.PIPE):
    def check(exe, cwd):
        r = run(exe, args, cwd, stdout=stdout)
        ok = r.returncode == want and (stderr_has is None or stderr_has in r.stderr)
        return ok, "exit %d, stderr %r" % (r.returncode, r.stderr.strip()[:300])
    return check


def full_stdout(exe, cwd):
    with open("/dev/full", "w") as full:
        return exit_code(["--model", "builtin", "--out", "f.glb"], 4,
                         "Error writing standard output: No space left on device", stdout=full)(exe, cwd)


# (a sentence of docs/cli.md, whitespace-normalised; the run that must bear it out)
CLAIMS = [
    ("`FILE.gltf`: JSON glTF with its buffer in `FILE.bin` beside it", gltf_beside),
    ("with `--gltf-embed` the buffer is embedded as a base64 data URI instead", gltf_embed),
    ("`--max-influences 30` on a 24-joint model",
     exit_code(["--model", "builtin", "--out", "m.glb", "--max-influences", "30"], 1)),
    ("1..K (the model's joints) or all",
     exit_code(["--model", "builtin", "--out", "k.glb", "--max-influences", "24", "-q"], 0)),
    ("`--shape-keys 100` on a model with 10",
     exit_code(["--model", "builtin", "--out", "s.glb", "--shape-keys", "100"], 1)),
    ("`--threads: '0x10' is not an integer`",
     exit_code(["--model", "builtin", "--out", "x.glb", "--threads", "0x10"], 1,
               "--threads: '0x10' is not an integer")),
    ("`--threads` 1..1024", exit_code(["--model", "builtin", "--out", "x.glb", "--threads", "1025"], 1)),
    ("the output folder is missing", exit_code(["--model", "builtin", "--out", "no/such/dir/x.glb"], 4)),
    ("missing or unreadable model", exit_code(["--model", "no_such_model.npz", "--out", "x.glb"], 2)),
    ("`Error writing standard output: No space left on device`", full_stdout),
]


def doc_options(doc):
    """Options docs/cli.md names outside its --help block."""
    text = re.sub(r"<!-- help:begin -->.*?<!-- help:end -->", "", doc, flags=re.S)
    return set(re.findall(r"`(--[a-z][a-z0-9-]*)", text)) | set(
        re.findall(r"`[^`]*?(?<![\w-])(--[a-z][a-z0-9-]*)[^`]*`", text))


def claim_problems(exe, path, doc):
    flat = " ".join(doc.split())
    problems = []
    with tempfile.TemporaryDirectory(prefix="cli-docs-") as cwd:
        for sentence, check in CLAIMS:
            if sentence not in flat:
                problems.append(f"{path}: no longer says {sentence!r} (update CLAIMS in this script)")
                continue
            ok, seen = check(exe, cwd)
            if not ok:
                problems.append(f"{path}: says {sentence!r}, but the binary: {seen}")
    return problems


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
    exe, repo = os.path.abspath(sys.argv[1]), sys.argv[2]
    write = "--write" in sys.argv[3:]
    help_text = cli_help.run_help(exe)  # as a binary with no pages beside it prints it
    problems = []
    listed = help_options(help_text)
    with open(f"{repo}/docs/options.md", encoding="utf-8") as f:
        documented = readme_options(f.read())
    for name in sorted(listed - documented):
        problems.append(f"docs/options.md: option table lacks {name} (listed by --help)")
    for name in sorted(documented - listed):
        problems.append(f"docs/options.md: option table names {name}, which --help does not list")
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
    for i, line in enumerate(help_text.splitlines(), 1):
        if len(line) > HELP_WIDTH:
            problems.append(f"--help line {i} has {len(line)} columns (at most {HELP_WIDTH}): {line!r}")
    for name in sorted(doc_options(doc) - listed):
        problems.append(f"{path}: names {name}, which --help does not list")
    if not write:
        problems += claim_problems(exe, path, doc)
    for p in problems:
        print(p)
    print(f"{len(listed)} options in --help; {len(CLAIMS)} docs/cli.md claims run; {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    print(__doc__.strip())  # --help: the usage above, and nothing else
    sys.exit(0)

if __name__ == "__main__":
    sys.exit(main())
