#!/usr/bin/env python3
"""Shell completions for smpl-export, generated from the binary's `--help`
(the option table of cli/options.cpp), so they list exactly its options:

    gen-completions.py SMPL_EXPORT OUT_DIR

writes OUT_DIR/smpl-export (bash), OUT_DIR/_smpl-export (zsh) and
OUT_DIR/smpl-export.fish (fish). An option's value completes from its syntax:
fixed words ("all|none") are offered, FILE/PATH/OBJ/NPY complete file names,
DIR folder names, anything else (numbers, lists) nothing. The build runs it
(packaging/CMakeLists.txt); tests/package/completions_test.py checks every
`--help` option is in each file and asks bash and fish for completions.
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cli_help  # noqa: E402

HEADER = "generated from `smpl-export --help` by scripts/gen-completions.py; do not edit"


def short_help(text, limit=70):
    """The help's first clause, shortened, with the characters the shells'
    quoting would need removed (brackets, quotes, backslashes, backticks)."""
    first = re.split(r"[;.](?:\s|$)", text, maxsplit=1)[0]
    first = re.sub(r"[\[\]'\"`\\$]", "", first).strip()
    return first if len(first) <= limit else first[: limit - 3].rstrip() + "..."


def names(o):
    return [o.name] + ([o.alias] if o.alias else [])


def bash(options):
    cases = {"words": [], "dir": [], "file": [], "free": []}
    lines = [f"# bash completion for smpl-export: {HEADER}", "_smpl_export() {",
             "  local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]}",
             "  case $prev in"]
    for o in options:
        if not o.value:
            continue
        words = " ".join(cli_help.choices(o.value))
        pattern = "|".join(names(o))
        if cli_help.takes_dir_only(o.value):
            lines.append(f"    {pattern}) COMPREPLY=($(compgen -d -- \"$cur\")); return ;;")
        elif cli_help.takes_path(o.value):
            extra = f"$(compgen -W '{words}' -- \"$cur\") " if words else ""
            lines.append(f"    {pattern}) COMPREPLY=({extra}$(compgen -f -- \"$cur\")); return ;;")
        elif words:
            lines.append(f"    {pattern}) COMPREPLY=($(compgen -W '{words}' -- \"$cur\")); return ;;")
        else:
            lines.append(f"    {pattern}) COMPREPLY=(); return ;;  # a value: {o.value}")
    every = " ".join(n for o in options for n in names(o))
    lines += ["  esac",
              "  if [[ $cur == -* ]]; then",
              f"    COMPREPLY=($(compgen -W '{every}' -- \"$cur\"))",
              "  else",
              "    COMPREPLY=($(compgen -f -- \"$cur\"))",
              "  fi",
              "}",
              "complete -o filenames -F _smpl_export smpl-export", ""]
    return "\n".join(lines)


def zsh_action(o):
    if not o.value:
        return ""
    label = re.sub(r"[^A-Za-z0-9|,._-]", "", o.value).replace("|", " or ") or "value"
    words = cli_help.choices(o.value)
    if cli_help.takes_dir_only(o.value):
        action = "_files -/"
    elif cli_help.takes_path(o.value):
        action = ("{_alternative \"words:word:(%s)\" \"files:file:_files\"}" % " ".join(words)
                  if words else "_files")
    elif words:
        action = "(%s)" % " ".join(words)
    else:
        action = " "
    return f":{label}:{action}"


def zsh(options):
    lines = ["#compdef smpl-export", f"# zsh completion for smpl-export: {HEADER}",
             "_arguments -s \\"]
    for o in options:
        repeat = "*" if "repeatable" in o.help else ""
        for n in names(o):
            lines.append(f"  '{repeat}{n}[{short_help(o.help)}]{zsh_action(o)}' \\")
    lines.append("  '*:file:_files'")
    return "\n".join(lines) + "\n"


def fish(options):
    lines = [f"# fish completion for smpl-export: {HEADER}"]
    for o in options:
        spec = ["complete -c smpl-export"]
        spec.append(f"-l {o.name[2:]}" if o.name.startswith("--") else f"-s {o.name[1:]}")
        if o.alias:
            spec.append(f"-s {o.alias[1:]}")
        words = cli_help.choices(o.value)
        if cli_help.takes_dir_only(o.value):
            spec.append("-x -a '(__fish_complete_directories)'")
        elif o.value:
            spec.append("-r -F" if cli_help.takes_path(o.value) else "-x")
            if words:
                spec.append("-a '%s'" % " ".join(words))
        spec.append("-d '%s'" % short_help(o.help))
        lines.append(" ".join(spec))
    return "\n".join(lines) + "\n"


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: gen-completions.py SMPL_EXPORT OUT_DIR")
    exe, out_dir = sys.argv[1], sys.argv[2]
    options = cli_help.all_options(cli_help.parse(cli_help.run_help(exe)))
    os.makedirs(out_dir, exist_ok=True)
    for name, text in (("smpl-export", bash(options)), ("_smpl-export", zsh(options)),
                       ("smpl-export.fish", fish(options))):
        tmp = os.path.join(out_dir, f".{name}.tmp")
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(tmp, os.path.join(out_dir, name))


if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    print(__doc__.strip())  # --help: the usage above, and nothing else
    sys.exit(0)

if __name__ == "__main__":
    main()
