#!/usr/bin/python3
"""Godot 3.2 check of a --scene GLB (docs/file-contract.md "Scene files"): Godot's own glTF importer
(the editor's, run headless: `godot3-server --path P -e --quit`) imports the file into a throw-away
project, tests/cli/godot_scene.gd seeks the imported AnimationPlayer to each checked scene frame and
reports what Godot holds; this script compares it with numpy's forward pass (the .expected.json that
tests/cli/scene_check.py writes: per body the checked frames, its vertices or "hidden"; the camera).

    godot_scene.py --godot godot3-server --asset scene.glb --expected scene.glb.expected.json [--tol 1e-5]

Godot 3.2 blends shapes and skins on the GPU, so the skinned vertices are computed here from Godot's
numbers, as its renderer combines them (scene/3d/skeleton.cpp: each skin bind's matrix is the
bone's global pose (skeleton space) times the bind pose; the MeshInstance's global transform then
places the skinned mesh): v = M_mesh * sum_k w_k * (P[bone(j_k)] * B[j_k]) * v_morphed, with
v_morphed = base + sum_i s_i * (shape_i - base) (Mesh.BLEND_SHAPE_MODE_NORMALIZED, which the
importer sets: it stores each morph target as base + delta). Import options: animation/fps = the
scene's fps and the animation optimizer off, as docs/file-contract.md tells Godot users (the
importer resamples transform tracks at animation/fps, 15 by default).

Present: max vertex error <= tol; hidden: all vertices on one point (the body node's scale 0);
sensitivity: another checked frame's vertices and the other body's are >= 1 mm away; the camera's
position, view direction (-z), up (+y) within 1e-5 and its vertical fov (Camera.fov, degrees,
keep_aspect KEEP_HEIGHT) within 1e-4 degrees. Exit status 0 only if every check passes.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SENSITIVITY = 1e-3
FAILED = []


def check(ok, message):
    if not ok:
        FAILED.append(message)
        print("FAIL: " + message)
    return ok


BLOB = None  # report.bin: the float32 numbers godot_scene.gd wrote


def values(ref):
    """The numbers of one {"at", "n"} reference into report.bin, as float64."""
    return BLOB[ref["at"]:ref["at"] + ref["n"]].astype(np.float64)


def matrix(ref):
    """Godot's Transform as written by godot_scene.gd (3 rows of basis | origin) as a 4x4 matrix."""
    m = np.eye(4)
    m[:3, :] = values(ref).reshape(3, 4)
    return m


def run_godot(godot, asset, times, fps, work):
    """Import `asset` into a fresh project under `work` and run godot_scene.gd at `times` (seconds)."""
    project = os.path.join(work, "godot_project")
    shutil.rmtree(project, ignore_errors=True)
    os.makedirs(project)
    shutil.copyfile(asset, os.path.join(project, "scene.glb"))
    with open(os.path.join(project, "project.godot"), "w", encoding="utf-8") as fh:
        fh.write('config_version=4\n\n[application]\n\nconfig/name="scene_check"\n')
    with open(os.path.join(project, "scene.glb.import"), "w", encoding="utf-8") as fh:
        fh.write('[remap]\n\nimporter="scene"\ntype="PackedScene"\n\n[params]\n\n'
                 "animation/fps=%d\nanimation/optimizer/enabled=false\nmeshes/compress=false\n" % int(round(fps)))
    with open(os.path.join(project, "request.json"), "w", encoding="utf-8") as fh:
        json.dump({"times": times}, fh)
    for what, args in (("import", ["-e", "--quit"]), ("script", ["--script", os.path.join(HERE, "godot_scene.gd")])):
        began = time.time()
        run = subprocess.run([godot, "--path", project] + args, capture_output=True, text=True, timeout=600)
        errors = [line for line in (run.stdout + run.stderr).splitlines() if "SCRIPT ERROR" in line]
        print("godot %s: exit %d, %.1f s" % (what, run.returncode, time.time() - began))
        if run.returncode != 0 or errors:
            sys.exit("FAIL: godot %s: exit %d: %s" % (what, run.returncode, " | ".join(errors or
                                                                                        run.stderr.splitlines()[-5:])))
    report = os.path.join(project, "report.json")
    if not os.path.exists(report):
        sys.exit("FAIL: godot wrote no report (%s)" % report)
    global BLOB
    BLOB = np.fromfile(os.path.join(project, "report.bin"), dtype="<f4")
    with open(report, encoding="utf-8") as fh:
        return json.load(fh)


def skinned(body, frame, weights="shape_weights"):
    """Godot's vertices of one body at one frame, from the numbers Godot reported (see the docstring);
    `weights`: the blend shape weights the AnimationPlayer set ("shape_weights") or the imported
    Animation's value tracks at that time ("imported_weights")."""
    base = values(body["vertices"]).reshape(-1, 3)
    shapes = np.stack([values(v).reshape(-1, 3) for v in body["shapes"]])
    s = values(frame[weights])
    morphed = base + np.einsum("i,ivc->vc", s, shapes - base[None])
    poses = np.stack([matrix(p) for p in frame["bone_poses"]])
    binds = np.stack([matrix(b) for b in body["binds"]])
    joint = poses[np.array(body["bind_bones"])] @ binds
    bones = np.array(body["bones"], int).reshape(-1, 4)
    skin_weights = values(body["weights"]).reshape(-1, 4)
    homog = np.concatenate([morphed, np.ones((len(morphed), 1))], 1)
    out = np.zeros((len(morphed), 4))
    for k in range(4):
        out += skin_weights[:, k:k + 1] * np.einsum("vab,vb->va", joint[bones[:, k]], homog)
    return (matrix(frame["mesh_global"]) @ out.T).T[:, :3]


# Godot 3.2's AnimationPlayer applies at most this many value (property) tracks per step
# (scene/animation/animation_player.h NODE_CACHE_UPDATE_MAX; animation_player.cpp prints
# 'Condition "cache_update_prop_size >= NODE_CACHE_UPDATE_MAX"' and drops the rest): one morph
# weight is one value track, so a scene with more correctives than that plays some unposed.
GODOT_VALUE_TRACK_MAX = 1024


def check_bodies(report, ref, times, tol):
    """Each body at its checked frames: the imported file (Godot's mesh, shapes, skin, bone poses and
    the imported Animation's morph weights) within tol; what the AnimationPlayer played likewise
    while the animation has no more value tracks than Godot 3.2 plays (GODOT_VALUE_TRACK_MAX)."""
    got_names = sorted(report["bodies"])
    want_names = sorted(name + "_mesh" for name in ref["bodies"])
    check(got_names == want_names, "Godot's MeshInstances %s, expected %s" % (got_names, want_names))
    over_limit = report["value_tracks"] > GODOT_VALUE_TRACK_MAX
    print("godot value tracks %d (Godot 3.2 plays at most %d per step)" % (report["value_tracks"],
                                                                           GODOT_VALUE_TRACK_MAX))
    index = {t: i for i, t in enumerate(times)}
    worst = played_worst = 0.0
    for name, body in sorted(ref["bodies"].items()):
        gbody = report["bodies"].get(name + "_mesh")
        if gbody is None:
            continue
        mode = gbody["blend_shape_mode"]
        check(mode == 0, "%s: blend shape mode %s, not NORMALIZED" % (name, mode))
        present = {f: np.array(v) for f, v in zip(body["frames"], body["vertices"]) if v != "hidden"}
        others = [np.array(v) for n, b in ref["bodies"].items() if n != name for v in b["vertices"] if v != "hidden"]
        for frame, want in zip(body["frames"], body["vertices"]):
            gframe = report["frames"][index[(frame - ref["first_frame"]) / ref["fps"]]]["bodies"][name + "_mesh"]
            got = skinned(gbody, gframe, "imported_weights")
            played = skinned(gbody, gframe)
            if want == "hidden":
                spread = float(max(np.ptp(got, axis=0).max(), np.ptp(played, axis=0).max()))
                print("godot %s frame %d hidden spread_m %.3e" % (name, frame, spread))
                check(spread <= 1e-6, "%s frame %d: not hidden (spread %.3g m)" % (name, frame, spread))
                continue
            err = float(np.abs(got - present[frame]).max())
            played_err = float(np.abs(played - present[frame]).max())
            worst, played_worst = max(worst, err), max(played_worst, played_err)
            wrong_frame = min([float(np.abs(got - v).max()) for f, v in present.items() if f != frame] or [np.inf])
            wrong_body = min([float(np.abs(got - v).max()) for v in others] or [np.inf])
            print("godot %s frame %d max_err_m %.3e (imported), played by the AnimationPlayer %.3e; another frame "
                  ">= %.3e m; the other body >= %.3e m" % (name, frame, err, played_err, wrong_frame, wrong_body))
            check(err <= tol, "%s frame %d: max vertex error %.3g m > %g" % (name, frame, err, tol))
            check(over_limit or played_err <= tol,
                  "%s frame %d: played max vertex error %.3g m > %g" % (name, frame, played_err, tol))
            check(wrong_frame >= SENSITIVITY,
                  "%s frame %d: another frame only %.3g m away" % (name, frame, wrong_frame))
            check(wrong_body >= SENSITIVITY, "%s frame %d: the other body only %.3g m away" % (name, frame, wrong_body))
    print("godot scene worst max_err_m %.3e (imported); played %.3e%s" % (
        worst, played_worst, " (GODOT LIMIT: %d value tracks > %d, the AnimationPlayer drops the rest)"
        % (report["value_tracks"], GODOT_VALUE_TRACK_MAX) if over_limit else ""))


def check_camera(report, ref, times):
    want = ref.get("camera")
    has = [f for f in report["frames"] if "camera" in f]
    if not want:
        check(not has, "a camera in Godot for a file without one")
        return
    index = {t: i for i, t in enumerate(times)}
    for i, frame in enumerate(want["frames"]):
        cam = report["frames"][index[(frame - ref["first_frame"]) / ref["fps"]]].get("camera")
        if not check(cam is not None, "no Camera node in Godot's scene"):
            return
        m = matrix(cam["global"])
        got = [m[:3, 3], -m[:3, 2] / np.linalg.norm(m[:3, 2]), m[:3, 1] / np.linalg.norm(m[:3, 1])]
        err = max(float(np.abs(g - np.array(w[i])).max())
                  for g, w in zip(got, [want["position"], want["direction"], want["up"]]))
        fov_err = abs(cam["fov"] - np.degrees(want["yfov"]))
        print("godot camera frame %d max_err %.3e; fov %.6f deg (err %.2e deg, keep_aspect %d)"
              % (frame, err, cam["fov"], fov_err, cam["keep_aspect"]))
        check(err <= 1e-5, "camera frame %d: position/direction/up off by %.3g" % (frame, err))
        # Camera.fov is vertical only with keep_aspect KEEP_HEIGHT (1), Godot's default.
        check(fov_err <= 1e-4 and cam["keep_aspect"] == 1, "camera frame %d: fov %.6f deg (keep_aspect %d), "
              "expected vertical %.6f deg" % (frame, cam["fov"], cam["keep_aspect"], np.degrees(want["yfov"])))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--godot", required=True, help="a Godot 3.2 binary with the editor (godot3-server)")
    ap.add_argument("--asset", required=True)
    ap.add_argument("--expected", required=True)
    ap.add_argument("--tol", type=float, default=1e-5)
    a = ap.parse_args()
    with open(a.expected, encoding="utf-8") as fh:
        ref = json.load(fh)
    frames = set(f for b in ref["bodies"].values() for f in b["frames"])
    frames |= set((ref.get("camera") or {}).get("frames", []))
    times = [(f - ref["first_frame"]) / ref["fps"] for f in sorted(frames)]
    report = run_godot(a.godot, a.asset, times, ref["fps"], os.path.dirname(os.path.abspath(a.asset)))
    check(not report["errors"], "godot: %s" % report["errors"])
    check(len(report.get("animations", [])) == 1, "animations %s" % report.get("animations"))
    if len(report["frames"]) == len(times):
        check_bodies(report, ref, times, a.tol)
        check_camera(report, ref, times)
    if FAILED:
        sys.exit("%d check(s) failed" % len(FAILED))


if __name__ == "__main__":
    main()
