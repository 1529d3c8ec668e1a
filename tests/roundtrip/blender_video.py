"""Headless-Blender round trip of a video-to-motion layout (docs/motions.md "Video-to-motion
layouts"): import the GLB that `smpl-export --motion <tool's file>` (or `--motion-sequence`)
wrote, play it with NO runtime script, and compare the evaluated mesh at the case's three clip
frames with the numpy reference of the tool's conventions (tests/roundtrip/video_reference.py,
from tests/cli/layouts/video_cases.py).

  blender -b --factory-startup --python-exit-code 1 --python blender_video.py -- \
      --asset wham_world.glb --reference wham_world.ref.json [--tol 1e-5]

Blender's vertices are matched to the model's by rest position (the reference's v_shaped).
Prints one line per frame: "video <case> frame <f> max_err_m <e>"; exit status 0 only if every
frame is within the tolerance.
"""
import argparse
import json
import os
import sys

import bpy  # noqa: F401  (Blender's module: the script runs inside Blender)
import numpy as np

sys.dont_write_bytecode = True  # run from the source tree: leave no __pycache__ there
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_harness as harness  # noqa: E402  (numpy patch, checks, exit status)
import blender_animation as anim  # noqa: E402  (import with the scene at the clip's rate)
import blender_roundtrip as rt  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--asset", required=True)
    ap.add_argument("--reference", required=True)
    ap.add_argument("--tol", type=float, default=1e-5)
    a = ap.parse_args(harness.script_args())
    with open(a.reference, encoding="utf-8") as fh:
        ref = json.load(fh)
    _, _, mesh = anim.import_asset(a.asset, ref["fps"])
    rest = np.asarray(ref["rest"])
    index, _ = rt.vertex_map(mesh, rest, rt.rest_positions(mesh, {}))  # split weights: 0 at rest
    worst = 0.0
    for frame, want in zip(ref["frames"], ref["vertices"]):
        anim.evaluate(bpy.context.scene, frame)
        got = rt.evaluated_vertices(mesh)
        err = float(np.linalg.norm(got - np.asarray(want)[index], axis=1).max())
        worst = max(worst, err)
        print("video %s frame %d max_err_m %.3e" % (ref["case"], frame, err))
        harness.check(err <= a.tol, "%s frame %d: max vertex error %.3g m > %g"
                      % (ref["case"], frame, err, a.tol))
    print("video %s worst_m %.3e over frames %s" % (ref["case"], worst, ref["frames"]))
    harness.finish()


if __name__ == "__main__":
    harness.run(main)
