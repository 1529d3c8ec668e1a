#!/usr/bin/python3
"""The independent side of the MJCF checks (tests/roundtrip/mjcf_check.cpp):
rest joints and the closed rest mesh's volume, in the model's Y-up axes, from
a source other than the MJCF writer.

    mjcf_reference.py --glb ASSET.glb OUT.txt
        joints: the GLB's skin joint nodes, world position = the sum of the
        node translations from the scene root (rest rotations are identity,
        docs/file-contract.md); volume: the GLB mesh's POSITION and indices.
    mjcf_reference.py --model MODEL.npz [--betas v,v,..] OUT.txt
        numpy from the model file alone (model_math.shape: v_shaped and
        J = J_regressor v_shaped; volume from v_shaped and the faces `f`).

Volume: sum over triangles of v0 . (v1 x v2) / 6 (signed tetrahedra from the
origin, divergence theorem), in float64.

    mjcf_reference.py --model MODEL.npz --motion MOTION.npz --qpos BODY.qpos.npz
                      [--first A] [--step S] OUT.txt
        the reference motion check (mjcf_check --motion): the posed joints of
        output frames 0, T/2 and T-1 (source frame A + S i: the export's
        --frames A: and an integer --fps ratio S, so no interpolation) computed here: betas = the motion's
        first min(16, B) (as smpl-export takes them), model_math.shape, one
        Rodrigues rotation per joint from the motion's axis-angle poses
        (joints matched by name; absent ones at rest), forward kinematics over
        the kintree (model_math.forward), plus trans, an AMASS motion's Z-up
        world turned Y up (-90 degrees about X, as the exporter does); and the
        .qpos.npz read with numpy (np.load, no pickle): its joint names, fps,
        the rows of those frames and the row of the last keyframe (min(T, 100)-1).

    mjcf_reference.py --reorder-hinges BODY.xml OUT.xml
        a copy of BODY.xml whose bodies list their hinges z, y, x (MuJoCo then
        applies Rz Ry Rx: the wrong reading mjcf_check --wrong-order must catch).

    mjcf_reference.py --glb ASSET.glb --hulls OUT.txt
        also "hull NAME X Y Z" lines (--mjcf-geoms mesh): per joint the GLB
        vertices whose largest skin weight (JOINTS_n/WEIGHTS_n, ties to the
        lower joint) is that joint's, for the joints whose points span a
        solid: at least 4, and the square root of the smallest eigenvalue of
        their covariance (divided by the count) at least 1 mm.

OUT.txt: "volume V" then one "joint NAME X Y Z" line per joint (metres);
--motion: "names N NAME..", "frames T", "fps F", "row I Q..", "pose I NAME X Y Z"
(model axes, Y up; mjcf_check turns them Z up).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import model_math  # noqa: E402
import skin_fit_check  # noqa: E402  (read_glb, accessor)


def signed_volume(vertices, faces):
    v = np.asarray(vertices, np.float64)[np.asarray(faces, np.int64)]
    return float(np.einsum("ij,ij->i", v[:, 0], np.cross(v[:, 1], v[:, 2])).sum() / 6.0)


def from_glb(path):
    doc, blob = skin_fit_check.read_glb(path)
    nodes = doc["nodes"]
    world = {}

    def walk(n, base):
        p = base + np.asarray(nodes[n].get("translation", [0, 0, 0]), np.float64)
        assert "rotation" not in nodes[n] or np.allclose(nodes[n]["rotation"], [0, 0, 0, 1])
        world[n] = p
        for c in nodes[n].get("children", []):
            walk(c, p)

    for root in doc["scenes"][doc.get("scene", 0)]["nodes"]:
        walk(root, np.zeros(3))
    joints = [(nodes[n]["name"], world[n]) for n in doc["skins"][0]["joints"]]
    prim = doc["meshes"][0]["primitives"][0]
    positions = skin_fit_check.accessor(doc, blob, prim["attributes"]["POSITION"])
    a = doc["accessors"][prim["indices"]]
    view = doc["bufferViews"][a["bufferView"]]
    dtype = {5121: np.uint8, 5123: np.uint16, 5125: np.uint32}[a["componentType"]]
    start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
    indices = np.frombuffer(blob, dtype, a["count"], start).reshape(-1, 3)
    return joints, signed_volume(positions, indices)


def hull_points(path):
    """NAME -> (n, 3) dominated GLB vertices of each joint whose points span a solid."""
    doc, blob = skin_fit_check.read_glb(path)
    names = [doc["nodes"][n]["name"] for n in doc["skins"][0]["joints"]]
    attributes = doc["meshes"][0]["primitives"][0]["attributes"]
    positions = np.asarray(skin_fit_check.accessor(doc, blob, attributes["POSITION"]), np.float64)
    dense = np.zeros((len(positions), len(names)))
    for i in range(4):
        if "JOINTS_%d" % i not in attributes:
            break
        joints = np.asarray(skin_fit_check.accessor(doc, blob, attributes["JOINTS_%d" % i]), np.int64)
        weights = np.asarray(skin_fit_check.accessor(doc, blob, attributes["WEIGHTS_%d" % i]), np.float64)
        for c in range(joints.shape[1]):
            np.add.at(dense, (np.arange(len(positions)), joints[:, c]), weights[:, c])
    owner = np.argmax(dense, axis=1)  # the first maximum: ties to the lower joint
    hulls = {}
    for k, name in enumerate(names):
        points = positions[owner == k]
        if len(points) < 4:
            continue
        centred = points - points.mean(0)
        smallest = np.linalg.eigvalsh(centred.T @ centred)[0]
        if np.sqrt(max(smallest, 0.0) / len(points)) >= 1e-3:
            hulls[name] = points
    return hulls


def from_model(path, betas):
    model = model_math.load_model_npz(path)
    v_shaped, joints = model_math.shape(model, betas)
    names = model_math.joint_names(len(model["parents"]))
    faces = np.load(path)["f"]
    return list(zip(names, joints)), signed_volume(v_shaped, faces)


# AMASS world (Z up) -> the exported model axes (Y up): -90 degrees about X.
Z_UP_TO_Y_UP = np.array([[1.0, 0, 0], [0, 0, 1], [0, -1, 0]])


def read_motion(path):
    """Axis-angle poses (T, J, 3) with their joint names, trans (T, 3), betas, AMASS or not."""
    data = np.load(path, allow_pickle=False)
    if "root_orient" in data.files:  # AMASS SMPL-X release: split keys
        keys = ("root_orient", "pose_body", "pose_jaw", "pose_eye", "pose_hand")
        poses = np.concatenate([data[k] for k in keys], axis=1)
    else:
        poses = np.asarray(data["poses"], np.float64)
    poses = poses.reshape(poses.shape[0], -1, 3)
    trans = np.asarray(data["trans"], np.float64) if "trans" in data.files else np.zeros((len(poses), 3))
    betas = np.asarray(data["betas"], np.float64) if "betas" in data.files else np.zeros(0)
    amass = "mocap_framerate" in data.files or "mocap_frame_rate" in data.files
    return poses, model_math.joint_names(poses.shape[1]), trans, betas, amass


def posed_joints(model_path, motion_path, frames):
    """Frame -> [(name, (3,) joint position, model axes)] for the source frames listed."""
    model = model_math.load_model_npz(model_path)
    poses, motion_names, trans, betas, amass = read_motion(motion_path)
    b = min(model["shapedirs"].shape[2], 300)  # SMPL-X stores 300 shape + 100 expression columns
    v_shaped, rest = model_math.shape(model, betas[:min(16, b)])
    names = model_math.joint_names(len(model["parents"]))
    column = {n: j for j, n in enumerate(motion_names)}
    up = Z_UP_TO_Y_UP if amass else np.eye(3)
    out = {}
    for f in frames:
        pose = np.array([poses[f, column[n]] if n in column else np.zeros(3) for n in names])
        _, joints, _ = model_math.forward(model, v_shaped, rest, pose, model["weights"])
        out[f] = list(zip(names, (joints + trans[f]) @ up.T))
    return out


def motion_reference(args):
    q = np.load(args.qpos, allow_pickle=False)
    assert sorted(q.files) == ["fps", "joint_names", "qpos"], q.files
    qpos, names, fps = q["qpos"], [str(n) for n in q["joint_names"]], float(q["fps"])
    assert qpos.dtype == np.float64 and qpos.ndim == 2, (qpos.dtype, qpos.shape)
    count = len(qpos)
    checked = sorted({0, count // 2, count - 1})
    source = {i: args.first + args.step * i for i in checked}
    joints = posed_joints(args.model, args.motion, sorted(source.values()))
    with open(args.out, "w") as f:
        f.write("names %d %s\n" % (len(names), " ".join(names)))
        f.write("frames %d\nfps %.17g\n" % (count, fps))
        for i in sorted(set(checked) | {min(count, 100) - 1}):
            f.write("row %d %s\n" % (i, " ".join("%.17g" % v for v in qpos[i])))
        for i in checked:
            for name, p in joints[source[i]]:
                f.write("pose %d %s %.17g %.17g %.17g\n" % (i, name, p[0], p[1], p[2]))
    print("qpos (%d, %d) at %g fps, %d joint names; posed joints of frames %s (source %s)"
          % (count, qpos.shape[1], fps, len(names), checked, [source[i] for i in checked]))


def reorder_hinges(src, out):
    lines = open(src).read().split("\n")
    swapped = 0
    for i in range(len(lines) - 2):
        if ('_x" type="hinge"' in lines[i] and '_y" type="hinge"' in lines[i + 1]
                and '_z" type="hinge"' in lines[i + 2]):
            lines[i], lines[i + 2] = lines[i + 2], lines[i]
            swapped += 1
    assert swapped > 0, "no hinge triple in " + src
    open(out, "w").write("\n".join(lines))
    print("%d bodies' hinges listed z, y, x" % swapped)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--glb")
    ap.add_argument("--model")
    ap.add_argument("--betas", default="")
    ap.add_argument("--motion")
    ap.add_argument("--qpos")
    ap.add_argument("--first", type=int, default=0)
    ap.add_argument("--step", type=int, default=1)
    ap.add_argument("--reorder-hinges")
    ap.add_argument("--hulls", action="store_true")
    ap.add_argument("out")
    args = ap.parse_args()
    if args.motion:
        return motion_reference(args)
    if args.reorder_hinges:
        return reorder_hinges(args.reorder_hinges, args.out)
    if args.glb:
        joints, volume = from_glb(args.glb)
    else:
        betas = [float(b) for b in args.betas.split(",")] if args.betas else []
        joints, volume = from_model(args.model, betas)
    with open(args.out, "w") as f:
        f.write("volume %.17g\n" % volume)
        for name, p in joints:
            f.write("joint %s %.17g %.17g %.17g\n" % (name, p[0], p[1], p[2]))
        hulls = hull_points(args.glb) if args.hulls else {}
        for name, points in hulls.items():
            for p in points:
                f.write("hull %s %.17g %.17g %.17g\n" % (name, p[0], p[1], p[2]))
    print("%d joints, volume %.9g m^3" % (len(joints), volume) +
          ("; %d parts with hull points" % len(hulls) if args.hulls else ""))


if __name__ == "__main__":
    main()
