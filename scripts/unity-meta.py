#!/usr/bin/env python3
"""Writes (or checks) the Unity .meta file of every asset in the Unity package.

Unity imports an asset of an immutable package (one added from a git URL or a
tarball) only if its .meta file is in the package: it cannot write one into
the read-only package cache. So every file and folder Unity sees in unity/
needs a committed .meta, with a GUID that never changes.

    scripts/unity-meta.py [--check] [PACKAGE_DIR]      (default: unity/)

Without --check, writes the missing or outdated .meta files and deletes
orphaned ones. With --check, changes nothing, prints one line per missing,
stale or orphaned .meta file, and exits 1 if there is any.

Deterministic GUIDs: guid = md5("Packages/<package name>/<relative path>")
as 32 lowercase hex digits (the whole digest), i.e. the md5 of the asset path
Unity itself shows for the asset, e.g.
"Packages/com.smpl-export.correctives/Runtime/SmplCorrectives.cs". The
package name keeps two packages that use this scheme from sharing a GUID for
"Runtime"; the path keeps GUIDs stable across checkouts. Renaming or moving an
asset changes its GUID (as deleting and re-adding it would in Unity).

What Unity ignores (and so gets no .meta): names starting with '.', ending
with '~' (e.g. Samples~, whose content Unity copies into Assets/ on import
and gives .meta files there), named 'cvs' or ending in '.tmp'. A .meta file
inside an ignored folder is reported as orphaned.

Importer per kind: folders DefaultImporter with folderAsset: yes; .cs
MonoImporter; .asmdef AssemblyDefinitionImporter; .json, .md, .txt
TextScriptImporter (TextAsset); everything else DefaultImporter. The text is
what Unity 2021.3 writes, without its trailing spaces after empty values
(YAML reads both the same).
"""
import hashlib
import json
import os
import pathlib
import sys

IMPORTERS = {
    ".cs": "MonoImporter",
    ".asmdef": "AssemblyDefinitionImporter",
    ".json": "TextScriptImporter",
    ".md": "TextScriptImporter",
    ".txt": "TextScriptImporter",
}

COMMON_TAIL = "  userData:\n  assetBundleName:\n  assetBundleVariant:\n"


def ignored(name):
    """True if Unity's asset database skips a file or folder of this name."""
    return (name.startswith(".") or name.endswith("~") or name.lower() == "cvs"
            or name.lower().endswith(".tmp"))


def guid(package_name, rel):
    return hashlib.md5(f"Packages/{package_name}/{rel}".encode("utf-8")).hexdigest()


def meta_text(package_name, rel, is_dir):
    """The .meta content for the asset at package-relative POSIX path rel."""
    head = f"fileFormatVersion: 2\nguid: {guid(package_name, rel)}\n"
    if is_dir:
        return head + "folderAsset: yes\nDefaultImporter:\n  externalObjects: {}\n" + COMMON_TAIL
    importer = IMPORTERS.get(pathlib.PurePosixPath(rel).suffix.lower(), "DefaultImporter")
    if importer == "MonoImporter":
        return (head + "MonoImporter:\n  externalObjects: {}\n  serializedVersion: 2\n"
                "  defaultReferences: []\n  executionOrder: 0\n  icon: {instanceID: 0}\n" + COMMON_TAIL)
    return head + f"{importer}:\n  externalObjects: {{}}\n" + COMMON_TAIL


def scan(root):
    """(expected {meta path: text}, existing .meta paths) under the package root."""
    package_name = json.loads((root / "package.json").read_text(encoding="utf-8"))["name"]
    expected, existing = {}, []
    stack = [(root, False)]
    while stack:
        folder, hidden = stack.pop()
        for entry in sorted(folder.iterdir()):
            is_hidden = hidden or ignored(entry.name)
            if entry.is_dir():
                stack.append((entry, is_hidden))
            elif entry.name.endswith(".meta"):
                existing.append(entry)
                continue
            if is_hidden:
                continue
            rel = entry.relative_to(root).as_posix()
            meta = entry.parent / (entry.name + ".meta")
            expected[meta] = meta_text(package_name, rel, entry.is_dir())
    return expected, existing


def write_atomic(path, text):
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(text, encoding="utf-8")
    os.replace(tmp, path)


def main(argv):
    check = "--check" in argv
    args = [a for a in argv if a != "--check"]
    if len(args) > 1 or any(a.startswith("-") for a in args):
        print("usage: unity-meta.py [--check] [PACKAGE_DIR]", file=sys.stderr)
        return 2
    root = pathlib.Path(args[0] if args else pathlib.Path(__file__).resolve().parent.parent / "unity")
    if not (root / "package.json").is_file():
        print(f"{root}: no package.json; expected the Unity package folder", file=sys.stderr)
        return 2
    expected, existing = scan(root)
    problems = []
    for meta, text in sorted(expected.items()):
        if not meta.is_file():
            problems.append(f"{meta}: missing .meta file")
        elif meta.read_text(encoding="utf-8") != text:
            problems.append(f"{meta}: stale .meta file (differs from what unity-meta.py generates)")
        else:
            continue
        if not check:
            write_atomic(meta, text)
    for meta in sorted(existing):
        if meta not in expected:
            problems.append(f"{meta}: orphaned .meta file (no asset, or the asset is ignored by Unity)")
            if not check:
                meta.unlink()
    for p in problems:
        print(p if check else "fixed: " + p)
    print(f"unity-meta: {len(expected)} assets, {len(problems)} "
          f"{'problems' if check else 'files written or removed'}")
    return 1 if check and problems else 0


if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    print(__doc__.strip())  # --help: the usage above, and nothing else
    sys.exit(0)

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
