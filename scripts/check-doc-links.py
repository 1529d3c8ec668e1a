#!/usr/bin/python3
"""Checks the links between the project's Markdown pages: README.md and docs/*.md.

Every relative link [text](path#anchor) must name a file that exists and, with
an anchor, a heading of that file. Anchors are the slugs the page is read
with: GitHub's for README.md (it is read on the repository's front page),
MkDocs' (Python-Markdown toc) for docs/*.md (the site). Section citations in
prose, `name.md "Heading"` (the form the code and pages use to point at a
section), must name an existing heading of that page (case-insensitive).

    scripts/check-doc-links.py [ROOT]
Exit 0 when every link resolves, 1 with one line per dead link (file:line: problem).
"""
import glob
import os
import re
import sys
import unicodedata

LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")
CITE = re.compile(r"([\w./-]+\.md),? \\?\"([^\"\\]+)\\?\"")
FENCE = re.compile(r"^\s*(```|~~~)")


def usage():
    print(__doc__.strip())


def mkdocs_slug(text):
    """Python-Markdown's toc.slugify (MkDocs 1.4 default)."""
    text = unicodedata.normalize("NFKD", text).encode("ascii", "ignore").decode("ascii")
    text = re.sub(r"[^\w\s-]", "", text).strip().lower()
    return re.sub(r"[-\s]+", "-", text)


def github_slug(text):
    """GitHub's heading anchor: lower case, punctuation dropped, each space a hyphen."""
    return re.sub(r"[^\w\- ]", "", text.lower()).replace(" ", "-")


def strip_code(line):
    return re.sub(r"`[^`]*`", lambda m: m.group(0).strip("`"), line)


def headings(path):
    """Heading texts of a Markdown file (outside fenced blocks), inline code marks removed."""
    found, fenced = [], False
    with open(path, encoding="utf-8") as f:
        for line in f:
            if FENCE.match(line):
                fenced = not fenced
            elif not fenced and re.match(r"#{1,6} ", line):
                found.append(strip_code(line.lstrip("#").strip()))
    return found


def anchors(path, root):
    in_docs = os.path.dirname(os.path.abspath(path)) == os.path.join(root, "docs")
    slug = mkdocs_slug if in_docs else github_slug
    seen, out = {}, set()
    for h in headings(path):
        s = slug(h)
        n = seen.get(s, 0)
        seen[s] = n + 1
        out.add(s if n == 0 else "%s-%d" % (s, n) if slug is mkdocs_slug else "%s-%d" % (s, n))
    # explicit anchors: <a id="x"> / <a name="x">
    with open(path, encoding="utf-8") as f:
        out.update(re.findall(r"<a (?:id|name)=\"([^\"]+)\"", f.read()))
    return out


def lines_outside_code(path):
    fenced = False
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            if FENCE.match(line):
                fenced = not fenced
                continue
            if not fenced and not line.startswith("    "):
                yield number, line


def check_file(path, root):
    problems = []
    here = os.path.dirname(path)
    for number, line in lines_outside_code(path):
        where = "%s:%d" % (os.path.relpath(path, root), number)
        for target in LINK.findall(line):
            if re.match(r"[a-z][a-z0-9+.-]*:", target):
                continue  # http:, https:, mailto:
            file_part, _, anchor = target.partition("#")
            dest = os.path.normpath(os.path.join(here, file_part)) if file_part else path
            if not os.path.exists(dest):
                problems.append("%s: link to %s: no such file" % (where, file_part))
            elif anchor and dest.endswith(".md") and anchor not in anchors(dest, root):
                problems.append("%s: link to %s#%s: no such heading in %s" % (
                    where, file_part, anchor, os.path.relpath(dest, root)))
        for page, title in CITE.findall(line):
            dest = resolve_page(page, here, root)
            if dest is None:
                continue  # a file name of another project (e.g. a package's README.md)
            names = [h.lower() for h in headings(dest)]
            if not any(h == title.lower() or h.startswith(title.lower()) for h in names):
                problems.append('%s: cites %s "%s": no such heading' % (where, page, title))
    return problems


def resolve_page(page, here, root):
    for base in (here, root, os.path.join(root, "docs")):
        p = os.path.normpath(os.path.join(base, page))
        if os.path.isfile(p) and os.path.commonpath([p, root]) == root:
            return p
    return None


def main(argv):
    if any(a in ("-h", "--help") for a in argv[1:]):
        usage()
        return 0
    root = os.path.abspath(argv[1] if len(argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    pages = [os.path.join(root, "README.md")] + sorted(glob.glob(os.path.join(root, "docs", "*.md")))
    problems = [p for page in pages for p in check_file(page, root)]
    for p in problems:
        print(p)
    print("%d pages, %d dead links" % (len(pages), len(problems)), file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
