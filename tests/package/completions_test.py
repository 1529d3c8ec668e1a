#!/usr/bin/env python3
"""The generated man page and shell completions hold exactly the options of
`smpl-export --help`, and the shells read them:

- every option (and alias) that --help lists is in the bash, zsh and fish
  files and in the man page as groff renders it, and none that it lacks;
- bash -n, zsh -n and fish --no-execute accept the files; groff renders the
  page without warnings;
- bash and fish complete an option's fixed values (--correctives -> all
  none), an option prefix (--fbx-ver -> --fbx-version) and a folder option's
  value (fish: --motion-dir / -> the folders of /).

The option names are read from --help here with a plain pattern, not with
scripts/cli_help.py (which the generators use).

    completions_test.py SMPL_EXPORT COMPLETIONS_DIR MAN_PAGE
"""
import os
import re
import subprocess
import sys

OPTION_LINE = re.compile(r"^  (--[a-z][a-z0-9-]*)(?:, (-[a-zA-Z]))?\b")


def help_names(exe):
    text = subprocess.run([exe, "--help"], check=True, capture_output=True, text=True).stdout
    names = []
    for line in text.splitlines():
        m = OPTION_LINE.match(line)
        if m:
            names += [n for n in m.groups() if n]
    if len(names) < 20:
        raise SystemExit(f"--help lists only {len(names)} options: the pattern no longer reads it")
    return names


def run(cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, **kw)


def named_in(kind, text):
    """The option names a completion file or a rendered man page offers."""
    if kind == "bash":
        m = re.search(r"compgen -W '(-[^']*)' -- \"\$cur\"\)\)\n  else", text)
        return set(m.group(1).split()) if m else set()
    if kind == "zsh":
        return set(re.findall(r"^  '\*?(--?[a-zA-Z][a-z0-9-]*)\[", text, re.M))
    if kind == "fish":
        return ({"--" + n for n in re.findall(r" -l ([a-z0-9-]+)", text)} |
                {"-" + n for n in re.findall(r" -s ([a-zA-Z])\b", text)})
    # man: the entries' heads, "       --quiet, -q" (groff's option indent)
    return {n for m in re.finditer(r"^ {7}(--[a-z][a-z0-9-]*)(?:, (-[a-zA-Z]))?\b", text, re.M)
            for n in m.groups() if n}


def bash_complete(path, words):
    script = (f"source {path}; COMP_WORDS=({' '.join(repr(w) for w in words)}); "
              f"COMP_CWORD={len(words) - 1}; _smpl_export; printf '%s\\n' \"${{COMPREPLY[@]}}\"")
    return run(["bash", "-c", script]).stdout.split()


def fish_complete(path, line):
    out = run(["fish", "--no-config", "-c", f"source {path}; complete -C '{line}'"]).stdout
    return [l.split("\t")[0] for l in out.splitlines()]


def main():
    exe, comp_dir, man = sys.argv[1:4]
    expected = set(help_names(exe))
    problems = []
    files = {"bash": f"{comp_dir}/smpl-export", "zsh": f"{comp_dir}/_smpl-export",
             "fish": f"{comp_dir}/smpl-export.fish"}
    texts = {k: open(p, encoding="utf-8").read() for k, p in files.items()}
    rendered = run(["groff", "-man", "-Tutf8", "-ww", man], env={"LC_ALL": "C.UTF-8", "PATH": "/usr/bin:/bin"})
    if rendered.returncode or rendered.stderr.strip():
        problems.append(f"{man}: groff: {rendered.stderr.strip() or rendered.returncode}")
    texts["man"] = re.sub(r".\x08", "", rendered.stdout).replace("\u2010", "-").replace("\u2212", "-")
    for kind, text in texts.items():
        found = named_in(kind, text)
        for name in sorted(expected - found):
            problems.append(f"{kind}: lacks {name} (listed by --help)")
        for name in sorted(found - expected):
            problems.append(f"{kind}: offers {name}, which --help does not list")
    for kind, cmd in (("bash", ["bash", "-n"]), ("zsh", ["zsh", "-n"]), ("fish", ["fish", "--no-execute"])):
        r = run(cmd + [files[kind]])
        if r.returncode:
            problems.append(f"{files[kind]}: {kind} refuses it: {r.stderr.strip()}")
    checks = [
        ("bash --correctives", bash_complete(files["bash"], ["smpl-export", "--correctives", ""]), ["all", "none"]),
        ("bash --fbx-ver", bash_complete(files["bash"], ["smpl-export", "--fbx-ver"]), ["--fbx-version"]),
        ("bash --qui", bash_complete(files["bash"], ["smpl-export", "--qui"]), ["--quiet"]),
        ("fish --correctives", fish_complete(files["fish"], "smpl-export --correctives "), ["all", "none"]),
        ("fish --fbx-ver", fish_complete(files["fish"], "smpl-export --fbx-ver"), ["--fbx-version"]),
        ("fish --motion-dir", fish_complete(files["fish"], "smpl-export --motion-dir /"),
         sorted(f"/{d}/" for d in os.listdir("/") if os.path.isdir(f"/{d}") and not d.startswith("."))),
    ]
    for what, got, want in checks:
        if sorted(got) != sorted(want):
            problems.append(f"{what}: completed to {got}, expected {want}")
    for p in problems:
        print(p)
    if problems:
        return 1
    print(f"completions and man page: all {len(expected)} option names of --help; "
          f"bash, zsh, fish and groff read them; {len(checks)} completions as expected")
    return 0


if __name__ == "__main__":
    sys.exit(main())
