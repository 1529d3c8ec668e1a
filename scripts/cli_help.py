"""smpl-export's option table, read back from its `--help` text.

The options are described once, in cli/options.cpp; `--help` prints them.
The man page (gen-man.py) and the shell completions (gen-completions.py) are
generated from that text at build time, so they cannot drift from the binary.

A usage line is "  --name[, -a] [VALUE]" then the help in a column (the
column of the continuation lines); a long left part puts the help on the next
line. Section headings are unindented lines after the first option.

    parse(help_text) -> Help(title, usage, sections, epilog)
"""
import collections
import os
import re
import shutil
import subprocess
import tempfile

Option = collections.namedtuple("Option", "name alias value help")
Section = collections.namedtuple("Section", "heading options")  # heading "" for the first
Help = collections.namedtuple("Help", "title usage sections epilog")

NAME = re.compile(r"^(--[a-z][a-z0-9-]*)(?:, (-[a-zA-Z]))?(?: (\S+))?$")


def run_help(exe):
    """The `--help` text of the binary `exe` (str), as a copy of it with no
    documentation pages beside it prints it: the help names the folder of the
    pages it finds next to its executable (cli/docs_folder.h), which differs
    between a build tree and each install; the generated pages show the
    generic wording instead of one machine's path."""
    with tempfile.TemporaryDirectory() as tmp:
        alone = os.path.join(tmp, "prefix", "bin", os.path.basename(exe))
        os.makedirs(os.path.dirname(alone))
        shutil.copy2(exe, alone)
        return subprocess.run([alone, "--help"], check=True, capture_output=True,
                              text=True).stdout


def help_column(lines):
    """The column where the option help starts: the most common indentation
    of the continuation lines (those starting with 4 or more blanks)."""
    counts = collections.Counter(len(l) - len(l.lstrip(" ")) for l in lines
                                 if l.startswith("    ") and l.strip())
    if not counts:
        raise ValueError("--help: no option help column found")
    return counts.most_common(1)[0][0]


def split_option_line(line, column):
    """("--name[, -a] [VALUE]", help on this line or "")."""
    if len(line) > column and line[column - 1] == " " and line[column] != " ":
        return line[:column].strip(), line[column:].strip()
    return line.strip(), ""


def parse(text):
    """The options of a `--help` text, in order, grouped by section.

    Raises ValueError on a usage line it cannot read (the generators then fail
    the build rather than drop an option)."""
    lines = text.splitlines()
    column = help_column(lines)
    first = next(i for i, l in enumerate(lines) if l.startswith("  -"))
    header = [l for l in lines[:first]]
    title = header[0] if header else ""
    usage = [l.strip() for l in header[1:] if l.strip()]
    sections, epilog, heading, current = [], [], "", None
    for line in lines[first:]:
        if line.startswith("  -"):
            left, help_text = split_option_line(line, column)
            m = NAME.match(left)
            if not m:
                raise ValueError(f"--help: cannot read the option line '{line}'")
            if current is None:
                current = Section(heading, [])
                sections.append(current)
            current.options.append(Option(m.group(1), m.group(2), m.group(3), [help_text] if help_text else []))
        elif line.startswith(" " * column) and current and current.options:
            current.options[-1].help.append(line.strip())
        elif not line.strip():
            continue
        elif current is not None and line.startswith(("Exit codes", "Reference")):
            epilog.append(line.strip())
        else:  # a heading (may wrap over several lines)
            if current is not None and current.options:
                heading, current = line.strip(), None
            else:
                heading = (heading + " " + line.strip()).strip()
    out = [Section(s.heading, [o._replace(help=" ".join(o.help)) for o in s.options]) for s in sections]
    return Help(title, usage, out, epilog)


def all_options(help_):
    """Every Option of a parsed Help, in usage order."""
    return [o for s in help_.sections for o in s.options]


def choices(value):
    """The fixed words of a value syntax ("all|none" -> ["all", "none"],
    "PATH|DIR|builtin" -> ["builtin"]); [] for a free value ("N", "FILE")."""
    if not value:
        return []
    return [w for w in value.split("|") if re.fullmatch(r"-?[a-z0-9][a-z0-9-]*", w)]


def takes_path(value):
    """Whether the value names a file or folder ("FILE", "PATH|DIR|builtin", "OBJ|NPY|none")."""
    return bool(value) and any(w in ("FILE", "PATH", "DIR", "OBJ", "NPY") for w in value.split("|"))


def takes_dir_only(value):
    return value == "DIR"
