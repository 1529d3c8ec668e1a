#!/usr/bin/env bash
# Install every Debian package the build and the tests need. Idempotent: it
# only calls apt-get when something is missing. Run as root (or with sudo).
#   scripts/setup-deps.sh          build + test dependencies (Blender included)
#   scripts/setup-deps.sh --build  only what building smpl-export needs
#   scripts/setup-deps.sh --windows  that, and the Windows and WebAssembly
#                                  cross builds' (mingw-w64, emscripten, dpkg-dev
#                                  for Debian's source packages, wine to run
#                                  the .exe: scripts/build-windows.sh, build-wasm.sh)
#   scripts/setup-deps.sh --wasm   the same as --windows
set -euo pipefail

build_pkgs=(cmake g++ make libeigen3-dev zlib1g-dev libtinygltf-dev nlohmann-json3-dev libdraco-dev libmeshoptimizer-dev
            libssl-dev libdeflate-dev pkg-config python3 musl-dev python3-dev pybind11-dev)
test_pkgs=(libgtest-dev clang libclang-rt-14-dev python3-numpy python3-scipy python3-torch python3-joblib blender
           libassimp-dev mono-mcs ccache chromium clang-format zsh fish groff-base python3-pybind11
           python3-pytest python3-venv python3-pip python3-setuptools python3-wheel godot3-server)
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
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup-deps: done"
