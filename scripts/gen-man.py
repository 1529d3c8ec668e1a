#!/usr/bin/env python3
"""The smpl-export(1) man page, generated from the binary's `--help` and
`--version`, so it lists exactly the options cli/options.cpp has:

    gen-man.py SMPL_EXPORT OUT.1

Sections: NAME and SYNOPSIS (the usage lines), OPTIONS (one entry per option,
grouped under the usage text's headings), EXIT STATUS, SEE ALSO. No date is
written: the page depends only on the binary (deterministic builds). The
build runs it (packaging/CMakeLists.txt); tests/package/completions_test.py
checks that the page names every option and that groff reads it cleanly.
"""
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cli_help  # noqa: E402


def roff(text):
    """Plain text as roff: backslashes and hyphens escaped, no line starting
    with a control character."""
    text = text.replace("\\", "\\e").replace("-", "\\-")
    return "\\&" + text if text.startswith((".", "'")) else text


def option_head(o):
    head = "\\fB%s\\fR" % roff(o.name)
    if o.alias:
        head += ", \\fB%s\\fR" % roff(o.alias)
    if o.value:
        head += " \\fI%s\\fR" % roff(o.value)
    return head


def page(help_, version):
    title = help_.title.split(": ", 1)
    summary = title[1] if len(title) == 2 else help_.title
    out = [".\\\" generated from `smpl-export --help` by scripts/gen-man.py; do not edit",
           '.TH SMPL\\-EXPORT 1 "" "%s" "User Commands"' % roff(version),
           ".SH NAME", "smpl\\-export \\- " + roff(summary),
           ".SH SYNOPSIS"]
    for i, line in enumerate(help_.usage):
        line = line.split(": ", 1)[1] if line.startswith("Usage: ") else line
        if i:
            out.append(".br")
        out.append(roff(line))
    out += [".SH DESCRIPTION",
            "Turns SMPL\\-family body models (SMPL, SMPL\\-H, SMPL\\-X, MANO) and a shape vector "
            "into rigged glTF 2.0 / GLB and FBX assets with the model's pose\\-corrective blend "
            "shapes as morph targets, optionally with animations baked from motion files. "
            "Without a model file (\\fB\\-\\-model builtin\\fR) it exports a built\\-in "
            "synthetic demo body.",
            ".SH OPTIONS"]
    for section in help_.sections:
        if section.heading:
            out += [".SS " + roff(section.heading.rstrip(":"))]
        for o in section.options:
            out += [".TP", option_head(o), roff(o.help)]
    out.append(".SH EXIT STATUS")
    for line in help_.epilog:
        if line.startswith("Exit codes"):
            out.append(roff(line.split(": ", 1)[1]))
    out += [".SH SEE ALSO",
            "README.md (installed in share/doc/smpl\\-export/) and, in the sources, docs/cli.md "
            "(the rules of each option), docs/motions.md (the motion layouts read) and "
            "docs/file\\-contract.md (the metadata written)."]
    return "\n".join(out) + "\n"


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: gen-man.py SMPL_EXPORT OUT.1")
    exe, out_path = sys.argv[1], sys.argv[2]
    version = subprocess.run([exe, "--version"], check=True, capture_output=True,
                             text=True).stdout.strip()
    text = page(cli_help.parse(cli_help.run_help(exe)), version)
    tmp = os.path.join(os.path.dirname(os.path.abspath(out_path)), "." + os.path.basename(out_path) + ".tmp")
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, out_path)


if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    print(__doc__.strip())  # --help: the usage above, and nothing else
    sys.exit(0)

if __name__ == "__main__":
    main()
