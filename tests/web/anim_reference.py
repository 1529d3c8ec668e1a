"""Expected vertices of an AMASS motion baked on a fixture model, for the
three.js tests (tests/web/three_node_test.mjs): numpy's forward pass
(tests/roundtrip/model_math.py, written from the equations) at chosen
source frames, in the exported axes (Y up, metres), with the weights pruned
to M influences as the exporter does.

    /usr/bin/python3 anim_reference.py --model M.npz --motion walk.npz \
        --max-influences 4 --frames 0,120,239 --out PREFIX

Writes PREFIX.json: {"fps", "frames", "num_vertices", "vertices": [[x,y,z]...]
per frame} (vertices as float64 decimal text: exact round trip).
Only AMASS .npz motions (poses or split keys), at their own frame rate.
--offset-from SIDECAR: add the sidecar's `origin` offset (an --origin floor or
--root-bone export: every position moved by (0, dy, 0)).
"""
import argparse
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "roundtrip"))
import model_math  # noqa: E402

Z_UP_TO_Y_UP = np.array([[1.0, 0, 0], [0, 0, 1], [0, -1, 0]])  # AMASS worlds are Z up


def read_amass(path):
    data = np.load(path, allow_pickle=False)
    if "root_orient" in data.files:  # AMASS SMPL-X release: split keys
        poses = np.concatenate([data[k] for k in ("root_orient", "pose_body", "pose_jaw", "pose_eye",
                                                  "pose_hand")], axis=1)
    else:
        poses = np.asarray(data["poses"], dtype=np.float64)
    frames = poses.shape[0]
    poses = poses.reshape(frames, -1, 3)
    names = model_math.joint_names(poses.shape[1])
    fps = next(float(data[k]) for k in ("mocap_framerate", "mocap_frame_rate", "fps") if k in data.files)
    trans = np.asarray(data["trans"], dtype=np.float64) if "trans" in data.files else np.zeros((frames, 3))
    betas = np.asarray(data["betas"], dtype=np.float64) if "betas" in data.files else np.zeros(0)
    return {"rot": {n: poses[:, j] for j, n in enumerate(names)}, "trans": trans, "betas": betas,
            "fps": fps, "frames": frames}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--model", required=True)
    ap.add_argument("--motion", required=True)
    ap.add_argument("--max-influences", type=int, default=4)
    ap.add_argument("--frames", required=True, help="comma-separated source frames")
    ap.add_argument("--out", required=True)
    ap.add_argument("--offset-from", default="", help="an export's .smpl.json: add its origin offset")
    a = ap.parse_args()
    model = model_math.load_model_npz(a.model)
    motion = read_amass(a.motion)
    names = model_math.joint_names(len(model["parents"]))
    b = min(model["shapedirs"].shape[2], 300)  # SMPL-X: 300 shape + 100 expression columns
    v_shaped, joints = model_math.shape(model, motion["betas"][:min(16, b)])
    weights = model_math.prune(model["weights"], a.max_influences)
    frames = [int(x) for x in a.frames.split(",")]
    shift = np.zeros(3)
    if a.offset_from:
        with open(a.offset_from, encoding="utf-8") as fh:
            shift = np.array(json.load(fh)["origin"]["offset"], dtype=np.float64)
    out = []
    for frame in frames:
        pose = np.zeros((len(names), 3))
        for k, name in enumerate(names):
            if name in motion["rot"]:  # joints the motion lacks stay at rest
                pose[k] = motion["rot"][name][frame]
        verts, _, _ = model_math.forward(model, v_shaped, joints, pose, weights)
        out.append(((verts + motion["trans"][frame]) @ Z_UP_TO_Y_UP.T + shift).tolist())
    with open(a.out + ".json", "w", encoding="utf-8") as f:
        json.dump({"fps": motion["fps"], "frames": frames, "num_vertices": len(v_shaped), "vertices": out}, f)


if __name__ == "__main__":
    main()
