#!/usr/bin/env bash
# Install the Debian packages the build, the docs site and the tests need.
# Idempotent: it only calls apt-get when something is missing. Run as root (or
# with sudo). apt-get waits up to 10 minutes for the package lock (a fresh
# machine's unattended upgrades hold it for a while after boot).
#   scripts/setup-deps.sh          everything: the build's packages, the Windows
#                                  and WebAssembly cross builds' (below), and the
#                                  tests' (Blender, Chromium, clang, mono, Slurm, ...;
#                                  Node.js and npm when no npm is on PATH)
#   scripts/setup-deps.sh --build  only what building smpl-export and its docs
#                                  site (mkdocs, mkdocs-material) needs
#   scripts/setup-deps.sh --windows  the build's packages and the Windows and
#                                  WebAssembly cross builds' (mingw-w64,
#                                  emscripten, dpkg-dev for Debian's source
#                                  packages, wine to run the .exe:
#                                  scripts/build-windows.sh, build-wasm.sh)
#   scripts/setup-deps.sh --wasm   the same as --windows
#   scripts/setup-deps.sh --help   this text; installs nothing
set -euo pipefail

case "${1:-}" in
  -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'; exit 0 ;;
  ""|--build|--windows|--wasm) ;;
  *) echo "setup-deps: unknown option '$1' (see scripts/setup-deps.sh --help)" >&2; exit 1 ;;
esac

build_pkgs=(cmake g++ make libeigen3-dev zlib1g-dev libtinygltf-dev nlohmann-json3-dev libdraco-dev libmeshoptimizer-dev
            libssl-dev libdeflate-dev pkg-config python3 musl-dev python3-dev pybind11-dev mkdocs mkdocs-material)
test_pkgs=(libgtest-dev clang libclang-rt-14-dev python3-numpy python3-scipy python3-torch python3-joblib blender
           libassimp-dev mono-mcs ccache chromium clang-format zsh fish groff-base python3-pybind11
           python3-pytest python3-venv python3-pip python3-setuptools python3-wheel godot3-server
           slurm-wlm munge libmujoco-dev)
windows_pkgs=(mingw-w64 libz-mingw-w64-dev dpkg-dev wine wine64 emscripten)

pkgs=("${build_pkgs[@]}")
[[ "${1:-}" == "--build" ]] || pkgs+=("${windows_pkgs[@]}")
if [[ "${1:-}" != "--build" && "${1:-}" != "--windows" && "${1:-}" != "--wasm" ]]; then
  pkgs+=("${test_pkgs[@]}")
  # The glTF validator runs on Node.js: use the machine's node/npm when present
  # (any install), else Debian's.
  command -v npm >/dev/null 2>&1 || pkgs+=(nodejs npm)
fi

missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  echo "setup-deps: all ${#pkgs[@]} packages present"
  exit 0
fi

SUDO=""
[[ $(id -u) -eq 0 ]] || SUDO="sudo"
echo "setup-deps: installing ${missing[*]}"
lock=(-o DPkg::Lock::Timeout=600)
$SUDO apt-get "${lock[@]}" update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get "${lock[@]}" install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup-deps: done"
