#!/usr/bin/env python3
"""Checks that every place that must state the version agrees with VERSION.

VERSION is the one source: CMake reads it (project version, the exporter's
`exporter_version`); the Blender add-on (bl_info, which Blender parses as a
literal, and blender_manifest.toml), the Unity and web package.json cannot read a
file, nor can the Maya module file, the Maya plug-in's registration and the
Unreal .uplugin: this check keeps them equal. Exits 1 and names each mismatch.
    scripts/check-version.py [ROOT]
"""
import ast
import json
import pathlib
import re
import sys


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    version = (root / "VERSION").read_text().strip()
    found = {}
    init = (root / "blender/smpl_correctives/__init__.py").read_text()
    tree = ast.parse(init)
    for node in tree.body:
        if isinstance(node, ast.Assign) and getattr(node.targets[0], "id", "") == "bl_info":
            info = ast.literal_eval(node.value)
            found["blender/smpl_correctives/__init__.py bl_info"] = ".".join(map(str, info["version"]))
    manifest = (root / "blender/smpl_correctives/blender_manifest.toml").read_text()
    m = re.search(r'^version\s*=\s*"([^"]+)"', manifest, re.M)
    found["blender/smpl_correctives/blender_manifest.toml"] = m.group(1) if m else None
    found["unity/package.json"] = json.loads((root / "unity/package.json").read_text()).get("version")
    mod = re.search(r"^\+ smpl_maya (\S+) ", (root / "maya/smpl_maya.mod").read_text(), re.M)
    found["maya/smpl_maya.mod"] = mod.group(1) if mod else None
    node = re.search(r'MFnPlugin\(obj, "smpl-export", "([^"]+)"', (root / "maya/scripts/smpl_maya/node.py").read_text())
    found["maya/scripts/smpl_maya/node.py MFnPlugin"] = node.group(1) if node else None
    plugin = json.loads((root / "unreal/SmplCorrectives/SmplCorrectives.uplugin").read_text())
    found["unreal/SmplCorrectives/SmplCorrectives.uplugin VersionName"] = plugin.get("VersionName")
    found["web/smpl-correctives/package.json"] = json.loads(
        (root / "web/smpl-correctives/package.json").read_text()).get("version")
    changelog = (root / "CHANGELOG.md").read_text()
    m = re.search(r"^## \[?(\d+\.\d+\.\d+)", changelog, re.M)
    found["CHANGELOG.md (latest entry)"] = m.group(1) if m else None
    bad = {k: v for k, v in found.items() if v != version}
    for k, v in bad.items():
        print(f"{k}: version {v!r}, expected {version!r} (VERSION)")
    print(f"check-version: {version}, {len(found)} places, {len(bad)} mismatches")
    return 1 if bad else 0


if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    print(__doc__.strip())  # --help: the usage above, and nothing else
    sys.exit(0)

if __name__ == "__main__":
    sys.exit(main())
