#!/usr/bin/env python3
"""Checks the files the engine packages must carry, which no build reads:

- unity/ (installed by git URL `...?path=/unity`, so it must carry its own
  licence): LICENSE.md equal to the repository's LICENSE, CHANGELOG.md with an
  entry for package.json's version, Documentation~/index.md, a `license` and
  `licensesUrl` in package.json (and, when given, documentationUrl and
  changelogUrl as https URLs), each with the .meta file Unity needs (folders
  ending in '~' need none; scripts/unity-meta.py --check checks the rest);
- unreal/SmplCorrectives/SmplCorrectives.uplugin: marked beta (it is never
  compiled against the engine here) and no EngineVersion pin below what
  unreal/README.md promises ("UE 5.3 or newer": a pin would make newer engines
  call it incompatible).

    check-packages.py [ROOT]

Exit 1 with one line per problem.
"""
import json
import pathlib
import re
import sys


def unity_problems(root):
    pkg = root / "unity"
    problems = []
    manifest = json.loads((pkg / "package.json").read_text(encoding="utf-8"))
    version = manifest.get("version", "")
    lic = pkg / "LICENSE.md"
    if not lic.is_file():
        problems.append("unity/LICENSE.md: missing (a ?path=/unity install carries no licence)")
    elif lic.read_bytes() != (root / "LICENSE").read_bytes():
        problems.append("unity/LICENSE.md: differs from LICENSE (copy it: cp LICENSE unity/LICENSE.md)")
    log = pkg / "CHANGELOG.md"
    if not log.is_file():
        problems.append("unity/CHANGELOG.md: missing")
    elif not re.search(r"^## \[%s\]" % re.escape(version), log.read_text(encoding="utf-8"), re.M):
        problems.append(f"unity/CHANGELOG.md: no '## [{version}]' entry (package.json version)")
    doc = pkg / "Documentation~" / "index.md"
    if not doc.is_file() or not doc.read_text(encoding="utf-8").strip():
        problems.append("unity/Documentation~/index.md: missing or empty")
    if manifest.get("license") != "Apache-2.0":
        problems.append(f"unity/package.json: license {manifest.get('license')!r}, expected 'Apache-2.0'")
    for key in ("licensesUrl", "documentationUrl", "changelogUrl"):
        url = manifest.get(key)
        if url is None and key != "licensesUrl":
            continue  # optional until the repository has a public home
        if not isinstance(url, str) or not re.match(r"https://[^\s<>]+$", url):
            problems.append(f"unity/package.json: {key} {url!r} is not an https URL")
    for name in ("LICENSE.md", "CHANGELOG.md"):
        if not (pkg / (name + ".meta")).is_file():
            problems.append(f"unity/{name}.meta: missing (run scripts/unity-meta.py)")
    return problems


def unreal_problems(root):
    path = root / "unreal/SmplCorrectives/SmplCorrectives.uplugin"
    plugin = json.loads(path.read_text(encoding="utf-8"))
    problems = []
    if plugin.get("IsBetaVersion") is not True:
        problems.append(f"{path.relative_to(root)}: IsBetaVersion is not true (never compiled against the engine)")
    readme = (root / "unreal/README.md").read_text(encoding="utf-8")
    m = re.search(r"UE (\d+\.\d+) or newer", readme)
    if not m:
        problems.append("unreal/README.md: no 'UE <major.minor> or newer' statement")
    elif "EngineVersion" in plugin:
        problems.append(f"{path.relative_to(root)}: EngineVersion {plugin['EngineVersion']!r} pins one engine, "
                        f"but unreal/README.md says UE {m.group(1)} or newer")
    return problems


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    problems = unity_problems(root) + unreal_problems(root)
    for p in problems:
        print(p)
    print(f"check-packages: {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    print(__doc__.strip())  # --help: the usage above, and nothing else
    sys.exit(0)

if __name__ == "__main__":
    sys.exit(main())
