#!/usr/bin/env bash
# `cmake --install` of a build puts every piece a user needs under the prefix
# (packaging/CMakeLists.txt): the binary, the man page and bash/zsh/fish
# completions, LICENSE, the Blender add-on zip, the Maya module, the Unity
# package, the Unreal plug-in and the three.js driver; each is checked for
# what makes it usable (the zip holds the add-on, the module file points at
# its scripts, the package manifests carry the build's version), and the
# installed binary runs.
#   install_test.sh BUILD_DIR VERSION WORK
set -euo pipefail
build=$1 version=$2 work=$3
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work"
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" >"$work/install.log" 2>&1 || fail "cmake --install: $(tail -5 "$work/install.log")"

expected=(
  bin/smpl-export
  share/man/man1/smpl-export.1
  share/bash-completion/completions/smpl-export
  share/zsh/vendor-completions/_smpl-export
  share/fish/vendor_completions.d/smpl-export.fish
  share/doc/smpl-export/LICENSE
  share/doc/smpl-export/README.md
  share/doc/smpl-export/CHANGELOG.md
  share/doc/smpl-export/cli.md
  share/doc/smpl-export/motions.md
  share/doc/smpl-export/getting-started.md
  share/doc/smpl-export/sidecar.schema.json
  share/smpl-export/blender/smpl_correctives.zip
  share/smpl-export/maya/smpl_maya.mod
  share/smpl-export/maya/scripts/smpl_maya/core.py
  share/smpl-export/unity/com.smpl-export.correctives/package.json
  share/smpl-export/unity/com.smpl-export.correctives/Runtime.meta
  share/smpl-export/unreal/SmplCorrectives/SmplCorrectives.uplugin
  share/smpl-export/web/smpl-correctives/package.json
  share/smpl-export/web/smpl-correctives/index.js
  share/smpl-export/web/smpl-correctives/index.d.ts
  share/smpl-export/web/smpl-correctives/LICENSE
)
for f in "${expected[@]}"; do
  [[ -f $prefix/$f ]] || fail "cmake --install did not install $f"
done
[[ -x $prefix/bin/smpl-export ]] || fail "bin/smpl-export is not executable"
[[ $("$prefix/bin/smpl-export" --version) == "smpl-export $version" ]] ||
  fail "installed smpl-export --version says '$("$prefix/bin/smpl-export" --version)', expected 'smpl-export $version'"
cmp "$prefix/share/doc/smpl-export/LICENSE" "$(dirname "$0")/../../LICENSE" || fail "installed LICENSE differs"

/usr/bin/python3 - "$prefix" "$version" <<'EOF' || fail "installed packages (see above)"
import json, pathlib, sys, zipfile
prefix, version = pathlib.Path(sys.argv[1]), sys.argv[2]
share = prefix / "share/smpl-export"
problems = []
names = zipfile.ZipFile(share / "blender/smpl_correctives.zip").namelist()
for member in ("smpl_correctives/__init__.py", "smpl_correctives/blender_manifest.toml"):
    if member not in names:
        problems.append(f"blender zip lacks {member}")
mod = (share / "maya/smpl_maya.mod").read_text()
if "smpl_maya" not in mod or not (share / "maya/plug-ins").is_dir():
    problems.append("maya module: smpl_maya.mod or plug-ins/ missing")
for manifest in ("unity/com.smpl-export.correctives/package.json", "web/smpl-correctives/package.json"):
    v = json.loads((share / manifest).read_text()).get("version")
    if v != version:
        problems.append(f"{manifest}: version {v}, expected {version}")
for p in problems:
    print(p)
sys.exit(1 if problems else 0)
EOF

# Every page --help and the unknown-motion refusal name is installed where they
# say: the installed binary finds <prefix>/share/doc/smpl-export beside it
# (cli/docs_folder.h) and names that folder as a path that exists.
docs=share/doc/smpl-export
where=$(cd "$prefix/$docs" && pwd -P)
help=$("$prefix/bin/smpl-export" --help)
grep -qF "$where" <<<"$(tr '\n' ' ' <<<"$help" | tr -s ' ')" || fail "--help does not name the installed pages' folder $where"
for page in $(grep -o '[a-z-]*\.md' <<<"$help" | sort -u); do
  [[ -f $prefix/$docs/$page ]] || fail "--help names $page, which is not installed in $docs"
done
/usr/bin/python3 -c 'import numpy as np, sys; np.savez(sys.argv[1], fps=np.array(30.0),
    root_positions=np.zeros((4, 3)), rotations=np.zeros((4, 24, 4)))' "$work/unknown.npz"
set +e
refusal=$("$prefix/bin/smpl-export" --model builtin --motion "$work/unknown.npz" --out "$work/u.glb" 2>&1)
set -e
page=$(grep -oF "supported layouts: motions.md in $where" <<<"$refusal" | grep -o '[a-z-]*\.md') ||
  fail "an unknown motion layout does not name a page in $where: $refusal"
[[ -f $where/$page ]] || fail "the unknown-layout refusal names $page, which is not installed in $docs"
# A binary on its own (copied out of the tree) has no pages beside it: it names
# none by path, only the documentation in general.
mkdir -p "$work/alone/bin" && cp "$prefix/bin/smpl-export" "$work/alone/bin/"
set +e
alone=$("$work/alone/bin/smpl-export" --model builtin --motion "$work/unknown.npz" --out "$work/u.glb" 2>&1)
set -e
grep -qF "supported layouts: motions.md in the smpl-export documentation" <<<"$alone" ||
  fail "a binary without pages beside it should name the documentation in general: $alone"
grep -q "share/doc" <<<"$("$work/alone/bin/smpl-export" --help)" &&
  fail "a binary without pages beside it names a share/doc folder in --help"
echo "cmake --install: ${#expected[@]} files checked under the prefix; the installed smpl-export runs"
