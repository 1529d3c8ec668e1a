#!/usr/bin/env bash
# The README's picture: the built-in demo body exported by smpl-export in a
# walking pose (a one-frame motion), imported by Blender's own glTF importer
# and rendered there (Workbench, studio light), so the picture shows what a
# real client makes of the file, not our own drawing.
#   scripts/render-picture.sh [SMPL_EXPORT [OUT.png]]
# SMPL_EXPORT: default build/cli/smpl-export; OUT.png: default docs/images/body.png.
# Needs Blender 3.x (`blender` on PATH; scripts/setup-deps.sh installs it) and
# /usr/bin/python3 with numpy.
case "${1:-}" in -h | --help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;; esac
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
exe=${1:-$root/build/cli/smpl-export}
out=${2:-$root/docs/images/body.png}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# One frame of an SMPL pose: a step with arms lowered (axis-angle per joint, radians).
/usr/bin/python3 - "$work/pose.npz" <<'PY'
import sys
import numpy as np
pose = np.zeros(72)
def put(joint, xyz):
    pose[3 * joint:3 * joint + 3] = xyz
put(0, (1.5708, 0, 0))     # pelvis: AMASS motions are Z up; this stands the body up
put(1, (-0.35, 0, 0.08))    # left_hip forward
put(2, (0.30, 0, -0.08))    # right_hip back
put(4, (0.45, 0, 0))        # left_knee
put(5, (0.15, 0, 0))        # right_knee
put(16, (0, 0, -1.1))       # left_shoulder down
put(17, (0, 0, 1.1))        # right_shoulder down
put(18, (0, -0.3, 0))       # left_elbow
put(19, (0, 0.3, 0))        # right_elbow
np.savez(sys.argv[1], poses=pose[None], trans=np.zeros((1, 3)), mocap_framerate=np.array(30.0))
PY
"$exe" --model builtin --motion "$work/pose.npz" --out "$work/body.glb" -q
mkdir -p "$(dirname "$out")"
blender -b --factory-startup --python-exit-code 1 --python "$root/tools/render/picture_blender.py" -- \
  "$work/body.glb" "$work/body.png" >"$work/blender.log" 2>&1 || { tail -20 "$work/blender.log"; exit 1; }
mv "$work/body.png" "$out"
echo "render-picture: $out"
