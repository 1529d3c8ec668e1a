#!/usr/bin/env bash
# Every release artifact, built in one command into dist/ (Debian 12 x86_64;
# scripts/setup-deps.sh --build installs what it needs):
#   smpl-export-<version>-linux-x86_64.tar.gz   static binary at
#                                   smpl-export-<version>-linux-x86_64/bin/smpl-export,
#                                   with share/ (man page, completions, add-ons, LICENSE)
#   smpl-export_<version>_amd64.deb the same files under /usr (no dependencies)
#   smpl_correctives-<version>-blender.zip   the Blender add-on (Install from Disk)
#   smpl_maya-<version>.zip                  the Maya module (folder maya/)
#   com.smpl-export.correctives-<version>.tgz the Unity package (UPM: add package from tarball)
#   smpl-export-<version>-windows-x86_64.zip  bin/smpl-export.exe (scripts/build-windows.sh:
#                                   mingw-w64, static, Windows' own DLLs only), LICENSE, README.md,
#                                   share/doc/smpl-export/*.md
#   smpl-export-<version>-docs.tar.gz  the docs site (mkdocs.yml), also in the .tar.gz and .deb
#   SHA256SUMS
# The binary is a SMPL_STATIC=ON build in build-release/ (only smpl-export and
# the installed files are built; ccache makes a rebuild nearly free).
#   smpl-export-wasm-<version>.tgz           the WebAssembly npm package (scripts/build-wasm.sh;
#                                   node CLI `smpl-export`, one thread, no Draco)
#   smpl_export-<version>-cp3XX-cp3XX-linux_x86_64.whl  the Python module (docs/python.md):
#                                   `pip wheel` with Debian's setuptools and wheel, offline (no
#                                   build isolation, no index: python3-build would do the same
#                                   with --no-isolation, one package more); setup.py builds the
#                                   extension with CMake in build-wheel/ (Release, ccache)
# --windows, --npm and --all are accepted (every artifact is always built).
#   scripts/release.sh [--windows] [--npm] [--all]
# --help: the comment block above, then exit without doing anything.
case "${1:-}" in -h | --help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;; esac
set -euo pipefail
cd "$(dirname "$0")/.."
for arg in "$@"; do
  case $arg in
    --windows | --npm | --all) ;;  # every artifact is always built
    *) echo "release.sh: unknown option '$arg' (expected --windows, --npm or --all)" >&2; exit 1 ;;
  esac
done
version=$(head -n1 VERSION)
name=smpl-export-$version-linux-x86_64
dist=$PWD/dist
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

cmake -S . -B build-release -DCMAKE_BUILD_TYPE=Release -DSMPL_STATIC=ON -DSMPL_BUILD_TESTS=OFF \
  "${launcher[@]}" >/dev/null
cmake --build build-release -j"$(nproc)"
if readelf -lW build-release/cli/smpl-export | grep -q "program interpreter"; then
  echo "release.sh: build-release/cli/smpl-export is not static" >&2
  exit 1
fi
rm -rf "$dist" && mkdir -p "$dist"
# The docs site (mkdocs.yml), built before cpack so that the .tar.gz and the .deb carry it
# in share/doc/smpl-export/site/ (packaging/CMakeLists.txt installs build-release/site if present).
mkdocs build --strict -q -d "$PWD/build-release/site" || {
  echo "release.sh: mkdocs build --strict failed (scripts/setup-deps.sh --build installs mkdocs)" >&2
  exit 1
}
tar --sort=name --mtime=2026-01-01 --owner=0 --group=0 --numeric-owner \
  -C build-release --transform "s,^site,smpl-export-$version-docs," -czf "$dist/smpl-export-$version-docs.tar.gz" site
(cd build-release && cpack -G "TGZ;DEB" -B "$PWD/cpack" >cpack.log) || {
  echo "release.sh: cpack failed (build-release/cpack.log)" >&2
  exit 1
}
cp "build-release/cpack/$name.tar.gz" "build-release/cpack/smpl-export_${version}_amd64.deb" "$dist/"
cp build-release/smpl_correctives.zip "$dist/smpl_correctives-$version-blender.zip"
cp build-release/smpl_maya.zip "$dist/smpl_maya-$version.zip"
# The Windows zip: smpl-export-<version>-windows-x86_64/bin/smpl-export.exe, LICENSE, README.md,
# share/doc/smpl-export/*.md
# (stored with fixed times and order, so the same build zips to the same bytes).
mkdir -p build-windows-deps
scripts/build-windows.sh >build-windows-deps/build.log 2>&1 || {
  tail -20 build-windows-deps/build.log >&2
  echo "release.sh: the Windows build failed (build-windows-deps/build.log)" >&2
  exit 1
}
/usr/bin/python3 - "$dist/smpl-export-$version-windows-x86_64.zip" "smpl-export-$version-windows-x86_64" <<'PY'
import glob, os, sys, zipfile
out, top = sys.argv[1], sys.argv[2]
files = [("build-windows/cli/smpl-export.exe", "bin/smpl-export.exe"), ("LICENSE", "LICENSE"),
         ("README.md", "README.md")]
files += [(p, "share/doc/smpl-export/" + os.path.basename(p)) for p in sorted(glob.glob("docs/*.md"))]
with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as z:
    for src, name in files:
        info = zipfile.ZipInfo(f"{top}/{name}", date_time=(2026, 1, 1, 0, 0, 0))
        info.compress_type = zipfile.ZIP_DEFLATED
        info.external_attr = (0o755 if name.endswith(".exe") else 0o644) << 16
        z.writestr(info, open(src, "rb").read())
PY
# The WebAssembly npm package (build-wasm/npm: web/smpl-export-wasm/ and the built files).
scripts/build-wasm.sh >build-windows-deps/wasm-build.log 2>&1 || {
  tail -20 build-windows-deps/wasm-build.log >&2
  echo "release.sh: the WebAssembly build failed (build-windows-deps/wasm-build.log)" >&2
  exit 1
}
(cd build-wasm/npm && npm pack --silent --pack-destination "$dist" >/dev/null)
# npm pack writes the UPM tarball layout (package/...); the Unity package has no scripts to run.
(cd unity && npm pack --silent --pack-destination "$dist" >/dev/null)

# The Python wheel: the extension from build-wheel/ (a dynamic Release build: a Python
# extension is a shared object, unlike the static CLI), the shim and its stubs.
SMPL_BUILD_DIR=$PWD/build-wheel /usr/bin/python3 -m pip wheel --no-build-isolation --no-index \
  --no-deps -w "$dist" . >build-windows-deps/wheel.log 2>&1 || {
  tail -20 build-windows-deps/wheel.log >&2
  echo "release.sh: the Python wheel failed (build-windows-deps/wheel.log)" >&2
  exit 1
}
(cd "$dist" && sha256sum -- * >SHA256SUMS)
echo "dist/:"
(cd "$dist" && ls -l | tail -n +2)
