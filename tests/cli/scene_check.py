#!/usr/bin/python3
"""--scene (docs/file-contract.md "Scene files"): a multi-person motion file exported as one GLB,
read back by this file's own numpy glTF reader (GLB chunks, accessors, LINEAR/STEP samplers with
slerp, node hierarchy, morph targets, skinning as the glTF 2.0 spec defines them) and compared with
the numpy forward pass of the writing tool's conventions (tests/cli/layouts/video_cases.py, the same
reference the layout cases use), never with our C++.

    scene_check.py --exe build/cli/smpl-export --fixtures build/fixtures --layout wham [--work DIR]

Per body (one per track, named body_<track id>): at frames where the track has a detection, the
posed vertices within 1e-5 m of the reference at that track frame; at every other scene frame
(before, after, and in a gap of the track: PHALP's track 2 misses frames 8-9), hidden (all vertices
on one point). Sensitivity (each must be >= 1 mm away from what the file plays):
the reference with the other track's betas, and the reference one frame later (a start shifted by
one frame). Also: the sidecar's scene entry, one skin and one mesh per body, the timeline's span.
Exit status 0 only when every check passes; prints the measured numbers.

With --skeleton-names mixamo|ue5 the bones carry that rig's names: every body's skin joints must
be the renamed bones of its metadata (bone_names, and a spot check of the rig's hips name spelled
out here) and every check above holds unchanged (the player follows the skin, not the names).

With --format fbx the scene is written as FBX instead and read by Blender's FBX importer only
(--blender, tests/roundtrip/blender_scene.py): the same expected vertices, hidden bodies and camera
(world matrix and vertical field of view), with the FBX sensitivity checks there.
"""
import argparse
import json
import os
import struct
import subprocess
import sys

import joblib
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "layouts"))
import video_cases  # noqa: E402
import model_math  # noqa: E402  (tests/roundtrip, on the path through video_cases)

TOLERANCE = 1e-5
SENSITIVITY = 1e-3
FIXTURES = {"wham": "layouts/video/wham/wham_output.pkl", "vibe": "layouts/video/vibe/vibe_output.pkl",
            "phalp": "layouts/video/phalp/demo_video.pkl", "prompthmr": "layouts/video/prompthmr/results.pkl",
            "mcs": "layouts/video/prompthmr/world4d.mcs"}
MODELS = {"prompthmr": "smplx_small", "mcs": "smplx_small"}  # the family the tool writes; smpl_small otherwise
# Godot 3.2's importer resamples transform tracks at float32 times accumulated in 1/fps steps
# (~1e-7 s off the file's keys): next to a body's hold key that moves vertices up to ~1.6e-5 m.
GODOT_TOLERANCE = 2e-5
CAMERA_TOLERANCE = 1e-5  # metres (position), and the largest entry of a rotation matrix's difference
FAILED = []


def check(ok, message):
    if not ok:
        FAILED.append(message)
        print("FAIL: " + message)


# ---------------------------------------------------------------------------------------------
# A small glTF 2.0 reader and player (written from the spec, not from our writer).

COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}
DTYPES = {5120: np.int8, 5121: np.uint8, 5122: np.int16, 5123: np.uint16, 5125: np.uint32, 5126: np.float32}


def read_glb(path):
    data = open(path, "rb").read()
    magic, version, length = struct.unpack_from("<4sII", data, 0)
    assert magic == b"glTF" and version == 2 and length == len(data), "not a GLB 2.0"
    doc, blob, at = None, b"", 12
    while at < len(data):
        size, kind = struct.unpack_from("<II", data, at)
        chunk = data[at + 8:at + 8 + size]
        if kind == 0x4E4F534A:
            doc = json.loads(chunk.decode("utf-8"))
        elif kind == 0x004E4942:
            blob = chunk
        at += 8 + size
    return doc, blob


def accessor(doc, blob, index):
    a = doc["accessors"][index]
    n = COMPONENTS[a["type"]]
    view = doc["bufferViews"][a["bufferView"]]
    start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
    dtype = np.dtype(DTYPES[a["componentType"]])
    assert "byteStride" not in view or view["byteStride"] == n * dtype.itemsize, "strided view"
    out = np.frombuffer(blob, dtype, a["count"] * n, start).reshape(a["count"], n).astype(np.float64)
    if a.get("normalized"):
        out = {np.uint8: out / 255, np.uint16: out / 65535}.get(DTYPES[a["componentType"]], out)
    return out


def quat_matrix(q):
    x, y, z, w = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def slerp(a, b, u):
    d = float(np.dot(a, b))
    if d < 0:
        b, d = -b, -d
    if d > 0.9995:
        q = a + u * (b - a)
        return q / np.linalg.norm(q)
    th = np.arccos(d)
    return (np.sin((1 - u) * th) * a + np.sin(u * th) * b) / np.sin(th)


def sample(times, values, interpolation, path, t):
    """A sampler's value at time t (glTF 2.0 "Animations": clamped outside the keys)."""
    values = values.reshape(len(times), -1)
    if t <= times[0]:
        return values[0]
    if t >= times[-1]:
        return values[-1]
    i = int(np.searchsorted(times, t, side="right")) - 1
    if interpolation == "STEP":
        return values[i]
    u = (t - times[i]) / (times[i + 1] - times[i])
    if path == "rotation":
        return slerp(values[i], values[i + 1], u)
    return (1 - u) * values[i] + u * values[i + 1]


class Player:
    def __init__(self, path):
        self.doc, self.blob = read_glb(path)
        self.channels = []
        for anim in self.doc.get("animations", []):
            for ch in anim["channels"]:
                s = anim["samplers"][ch["sampler"]]
                self.channels.append((ch["target"]["node"], ch["target"]["path"], s.get("interpolation", "LINEAR"),
                                      accessor(self.doc, self.blob, s["input"])[:, 0],
                                      accessor(self.doc, self.blob, s["output"])))

    def world_matrices(self, t):
        nodes = self.doc["nodes"]
        trs = [{"translation": np.array(n.get("translation", [0, 0, 0]), float),
                "rotation": np.array(n.get("rotation", [0, 0, 0, 1]), float),
                "scale": np.array(n.get("scale", [1, 1, 1]), float),
                "weights": None} for n in nodes]
        for node, path, interp, times, values in self.channels:
            trs[node][path] = sample(times, values, interp, path, t)
        local = []
        for p in trs:
            m = np.eye(4)
            m[:3, :3] = quat_matrix(p["rotation"]) * p["scale"]
            m[:3, 3] = p["translation"]
            local.append(m)
        world = [None] * len(nodes)

        def visit(i, parent):
            world[i] = parent @ local[i]
            for c in nodes[i].get("children", []):
                visit(c, world[i])

        for root in self.doc["scenes"][self.doc.get("scene", 0)]["nodes"]:
            visit(root, np.eye(4))
        return world, trs

    def skinned(self, mesh_node, t):
        """Posed vertices of the skinned mesh on `mesh_node` at time t (the node's own transform
        is ignored, as the spec says for skinned meshes)."""
        world, trs = self.world_matrices(t)
        node = self.doc["nodes"][mesh_node]
        mesh = self.doc["meshes"][node["mesh"]]
        prim = mesh["primitives"][0]
        pos = accessor(self.doc, self.blob, prim["attributes"]["POSITION"])
        weights = trs[mesh_node]["weights"]
        if weights is None:
            weights = np.array(mesh.get("weights", [0.0] * len(prim.get("targets", []))))
        for w, target in zip(weights, prim.get("targets", [])):
            pos = pos + w * accessor(self.doc, self.blob, target["POSITION"])
        skin = self.doc["skins"][node["skin"]]
        ibm = accessor(self.doc, self.blob, skin["inverseBindMatrices"]).reshape(-1, 4, 4).transpose(0, 2, 1)
        joint_mats = np.stack([world[j] @ ibm[k] for k, j in enumerate(skin["joints"])])
        out = np.zeros_like(pos)
        homog = np.concatenate([pos, np.ones((len(pos), 1))], 1)
        s = 0
        while "JOINTS_%d" % s in prim["attributes"]:
            js = accessor(self.doc, self.blob, prim["attributes"]["JOINTS_%d" % s]).astype(int)
            ws = accessor(self.doc, self.blob, prim["attributes"]["WEIGHTS_%d" % s])
            for i in range(4):
                out += ws[:, i:i + 1] * np.einsum("vab,vb->va", joint_mats[js[:, i]], homog)[:, :3]
            s += 1
        return out


# ---------------------------------------------------------------------------------------------


def detections(layout, path):
    """The source frames of each track id's detections, as the tools store them: WHAM and VIBE
    frame_ids; PHALP per frame `tid` with tracked_time 0 (a detection) at frame `time`."""
    if layout == "mcs":  # MC_scene_description smpl_bodies[i].frame_presence = [first, end)
        with open(path, encoding="utf-8") as fh:
            gltf = json.load(fh)
        bodies = gltf["scenes"][gltf.get("scene", 0)]["extensions"]["MC_scene_description"]["smpl_bodies"]
        return {str(i): set(range(*b["frame_presence"])) for i, b in enumerate(bodies)}
    data = joblib.load(path)
    if layout == "prompthmr":  # yufu-wang/PromptHMR pipeline/world.py: people[id]['frames']
        return {str(int(k)): set(int(f) for f in np.asarray(p["frames"])) for k, p in data["people"].items()}
    if layout == "phalp":
        out = {}
        for frame in data.values():
            for i, tid in enumerate(frame["tid"]):
                if frame["tracked_time"][i] == 0:
                    out.setdefault(str(tid), set()).add(int(frame["time"]))
        return out
    return {str(int(k)): set(int(f) for f in np.asarray(v["frame_ids"])) for k, v in data.items()}


# glTF cameras look down their local -z with +y up (glTF 2.0 spec, "Cameras"); OpenCV's (PromptHMR's)
# look down +z with +y down: the same axes turned by diag(1, -1, -1).
OPENCV_TO_GLTF = np.diag([1.0, -1.0, -1.0])


def expected_camera(layout, path):
    """{frame: (3x3 camera-to-world rotation in glTF camera axes, centre)} and (yfov, aspect) of the
    file's camera, from the tool's own fields: PromptHMR pipeline/world.py camera_world Rwc (the camera's
    axes in the world), Twc (its centre), img_focal and img_center in pixels. None for a file without one.
    Also the plausible wrong readings (Rcw / Tcw taken as camera-to-world; the OpenCV axes kept)."""
    if layout not in ("prompthmr", "mcs"):
        return None
    # PromptHMR writes world4d.mcs from the same camera_world (pipeline/mcs_export_cam.py): the
    # fixture's .mcs sits beside the results.pkl it was made from.
    cam = joblib.load(os.path.join(os.path.dirname(path), "results.pkl"))["camera_world"]
    rwc, twc = np.asarray(cam["Rwc"], float), np.asarray(cam["Twc"], float)
    rcw, tcw = np.asarray(cam["Rcw"], float), np.asarray(cam["Tcw"], float)
    right = {f: (rwc[f] @ OPENCV_TO_GLTF, twc[f]) for f in range(len(rwc))}
    wrong = {"Rcw/Tcw as camera-to-world": {f: (rcw[f] @ OPENCV_TO_GLTF, tcw[f]) for f in range(len(rwc))},
             "OpenCV axes kept": {f: (rwc[f], twc[f]) for f in range(len(rwc))}}
    focal, centre = float(cam["img_focal"]), np.asarray(cam["img_center"], float)
    return {"frames": right, "wrong": wrong, "yfov": 2 * np.arctan(centre[1] / focal),
            "aspect": centre[0] / centre[1]}


def check_camera(player, want, first, end, fps):
    """The file's camera node played at every scene frame against `want` (expected_camera)."""
    doc = player.doc
    nodes = [i for i, n in enumerate(doc["nodes"]) if "camera" in n]
    if want is None:
        check(not nodes, "a camera node in a file without a camera")
        return
    if not nodes:
        check(False, "no camera node")
        return
    node = nodes[0]
    persp = doc["cameras"][doc["nodes"][node]["camera"]].get("perspective", {})
    check(abs(persp.get("yfov", 0) - want["yfov"]) <= 1e-6 and abs(persp.get("aspectRatio", 0) - want["aspect"]) <= 1e-6,
          "camera yfov/aspect %s, expected %.6f / %.6f" % (persp, want["yfov"], want["aspect"]))
    worst, gaps = 0.0, {k: 0.0 for k in want["wrong"]}
    for f in range(first, end):
        if f not in want["frames"]:
            continue
        world, _ = player.world_matrices((f - first) / fps)
        got_r, got_c = world[node][:3, :3], world[node][:3, 3]
        r, c = want["frames"][f]
        worst = max(worst, float(np.abs(got_r - r).max()), float(np.abs(got_c - c).max()))
        for k, frames in want["wrong"].items():
            wr, wc = frames[f]
            gaps[k] = max(gaps[k], float(np.abs(got_r - wr).max()), float(np.abs(got_c - wc).max()))
    print("camera: %d frames, max_err %.3e (rotation entries, metres); yfov %.6f aspect %.6f"
          % (len(want["frames"]), worst, persp.get("yfov", 0), persp.get("aspectRatio", 0)))
    check(worst <= CAMERA_TOLERANCE, "camera off by %.3g" % worst)
    for k, gap in gaps.items():
        print("camera: wrong reading %-28s %.3e away" % (k + ":", gap))
        check(gap >= SENSITIVITY, "camera: the wrong reading %r is only %.3g away" % (k, gap))


def camera_for_clients(want, first, end):
    """The camera per checked scene frame as the clients see it: its centre, view direction (local -z)
    and up (local +y) in the file's axes."""
    if want is None:
        return False
    frames = [f for f in sorted({first, (first + end) // 2, end - 1}) if f in want["frames"]]
    return {"frames": frames, "yfov": want["yfov"],
            "position": [want["frames"][f][1].tolist() for f in frames],
            "direction": [(-want["frames"][f][0][:, 2]).tolist() for f in frames],
            "up": [want["frames"][f][0][:, 1].tolist() for f in frames]}


def expected_clients(refs, detected, first, end, fps, m, weights, camera=False):
    """What the three.js, Babylon.js and Blender checks compare with: per body (named body_<id>) its rest mesh,
    a few scene frames (its first, middle and last detection, the scene's first and last frame, the
    frames just before and after its track and the first frame of a gap where it is absent) with numpy's vertices or "hidden"."""
    bodies = {}
    for tid, c in refs.items():
        frames_of = sorted(detected[tid])
        start = frames_of[0]
        present = sorted({start, frames_of[len(frames_of) // 2], frames_of[-1]})
        gaps = [f for f in range(start, frames_of[-1]) if f not in detected[tid]][:1]
        edges = [start - 1, frames_of[-1] + 1]  # either side of its track: the visibility changes
        absent = sorted({f for f in [first, end - 1] + gaps + edges if first <= f < end and f not in detected[tid]})
        frames = sorted(present + absent)
        bodies["body_" + tid] = {
            "rest": video_cases.shaped(m, c["betas"])[0].tolist(),
            "frames": frames,
            "vertices": [video_cases.vertices(c, m, f - start, weights).tolist() if f in present else "hidden"
                         for f in frames]}
    return {"fps": fps, "first_frame": first, "end_frame": end, "camera": camera, "bodies": bodies}


def client(cmd, what):
    run = subprocess.run(cmd, capture_output=True, text=True)
    keys = ("max_err", "spread", "FAIL", "away", "yfov")
    lines = [line for line in run.stdout.splitlines() if any(k in line for k in keys)]
    print("\n".join("%s: %s" % (what, line.strip()) for line in lines))
    check(run.returncode == 0, "%s check failed (exit %d): %s" % (
        what, run.returncode, " | ".join((run.stdout + run.stderr).strip().splitlines()[-15:])))


def refusals(a, model_path, fixture):
    """--scene with what it cannot do: one line on stderr naming the problem, exit 1, nothing
    written. A file with one motion is allowed: one body, named after --name."""
    base = [a.exe, "--model", model_path, "--motion", fixture, "--scene"]
    cases = [
        ("track_id", ["--track", "1"], ".glb", "--scene exports every track; --track 1 picks one"),
        ("track_all", ["--track", "all"], ".glb", "--track all writes one file per track"),
        ("bvh", [], ".bvh", "--scene: bvh output cannot hold several bodies on one timeline"),
        ("frames", ["--frames", "2:9"], ".glb", "--frames is not supported with it"),
        ("floor", ["--origin", "floor"], ".glb", "--origin floor and --root-bone"),
        ("in_place", ["--root-motion", "in-place"], ".glb", "--root-motion in-place is not supported"),
    ]
    for name, extra, ext, message in cases:
        out = os.path.join(a.work, "refused_" + name + ext)
        run = subprocess.run(base + ["--out", out] + extra, capture_output=True, text=True)
        lines = run.stderr.strip().splitlines()
        left = [f for f in os.listdir(a.work) if f.lstrip(".").startswith("refused_" + name)]
        print("refused %-9s exit %d: %s" % (name, run.returncode, lines[0] if lines else ""))
        check(run.returncode == 1 and len(lines) == 1 and message in lines[0] and not left,
              "%s: exit %d, stderr %r, left %s (expected exit 1 and %r)" % (name, run.returncode, run.stderr, left,
                                                                            message))
    single = os.path.join(a.fixtures, "motions", "smpl_72.npz")
    out = os.path.join(a.work, "single_scene.glb")
    run = subprocess.run([a.exe, "--model", model_path, "--motion", single, "--scene", "--out", out, "--quiet"],
                         capture_output=True, text=True)
    check(run.returncode == 0, "one-motion file: exit %d: %s" % (run.returncode, run.stderr.strip()))
    if run.returncode == 0:
        doc, _ = read_glb(out)
        names = [n["name"] for n in doc["nodes"] if "mesh" in n]
        print("one-motion file: mesh nodes %s, skins %d" % (names, len(doc["skins"])))
        check(names == ["body_mesh"] and len(doc["skins"]) == 1, "one-motion file: mesh nodes %s" % names)


def check_glb(out, refs, detected, starts, first, end, fps, m, weights, camera):
    """The GLB played by this file's numpy glTF player: every body where present, hidden where
    absent, the sensitivity checks, and the camera."""
    player = Player(out)
    doc = player.doc
    check(len(doc["skins"]) == len(refs) and len(doc["meshes"]) == len(refs),
          "%d skins, %d meshes for %d tracks" % (len(doc["skins"]), len(doc["meshes"]), len(refs)))
    # Body <name>: node <name> (parent of its skeleton), skinned mesh node <name>_mesh.
    mesh_nodes = {n["name"][:-len("_mesh")]: i for i, n in enumerate(doc["nodes"]) if "mesh" in n}
    body_nodes = {n["name"]: i for i, n in enumerate(doc["nodes"]) if "mesh" not in n}
    ids = sorted(refs, key=int)
    worst = 0.0
    for tid in ids:
        name = "body_" + tid
        check(name in mesh_nodes, "no mesh node %s (mesh nodes: %s)" % (name, sorted(mesh_nodes)))
        if name not in mesh_nodes:
            continue
        skin = doc["skins"][doc["nodes"][mesh_nodes[name]]["skin"]]
        check(doc["nodes"][body_nodes.get(name, 0)].get("children") == [skin["joints"][0]],
              "%s: no body node holding its skeleton" % name)
        c = refs[tid]
        length = len(c["pose"])
        other = refs[ids[(ids.index(tid) + 1) % len(ids)]]
        wrong_betas = dict(c, betas=other["betas"])
        body_worst = hidden_worst = 0.0
        swapped = shifted = np.inf
        for f in range(first, end):
            got = player.skinned(mesh_nodes[name], (f - first) / fps)
            k = f - starts[tid]
            if f in detected[tid]:
                want = video_cases.vertices(c, m, k, weights)
                body_worst = max(body_worst, float(np.abs(got - want).max()))
                swapped = min(swapped, float(np.abs(got - video_cases.vertices(wrong_betas, m, k, weights)).max()))
                if f + 1 in detected[tid]:  # a held next frame repeats this one: no shift to see
                    shifted = min(shifted, float(np.abs(got - video_cases.vertices(c, m, k + 1, weights)).max()))
            else:
                hidden_worst = max(hidden_worst, float(np.ptp(got, axis=0).max()))
        gaps = length - len(detected[tid])
        print("%s (track %s, frames %d-%d of %d-%d, %d without a detection): present max_err_m %.3e; "
              "hidden spread %.3e m; other track's betas >= %.3e m; one frame later >= %.3e m"
              % (name, tid, starts[tid], starts[tid] + length - 1, first, end - 1, gaps, body_worst, hidden_worst,
                 swapped, shifted))
        worst = max(worst, body_worst)
        check(body_worst <= TOLERANCE, "%s: max vertex error %.3g m > %g" % (name, body_worst, TOLERANCE))
        check(hidden_worst <= 1e-6, "%s: not hidden where absent (spread %.3g m)" % (name, hidden_worst))
        check(swapped >= SENSITIVITY, "%s: the other track's betas only %.3g m away" % (name, swapped))
        check(shifted >= SENSITIVITY, "%s: a one-frame shift only %.3g m away" % (name, shifted))
    print("worst max_err_m %.3e over %d bodies" % (worst, len(ids)))
    check_camera(player, camera, first, end, fps)


HIPS = {"mixamo": "mixamorig:Hips", "ue5": "pelvis"}  # the rigs' own names (docs/retargeting.md)
THIGH = {"mixamo": "mixamorig:LeftUpLeg", "ue5": "thigh_l"}


def check_bone_names(path, sidecar, names):
    """Every body's metadata (the sidecar's bodies) records the renamed bones, and every skin's
    joints are those bone_names, none the model's name of a renamed joint; the hips and left
    thigh carry the rig's names."""
    doc, _ = read_glb(path)
    bodies = sidecar.get("bodies", [])
    check(len(bodies) == len(doc["skins"]) and all(b.get("skeleton_names") == names for b in bodies),
          "sidecar bodies' skeleton_names %s for %d skins"
          % ([b.get("skeleton_names") for b in bodies], len(doc["skins"])))
    bones = bodies[0].get("bone_names") if bodies else None
    if bones is None:
        check(False, "no bone_names in the sidecar's bodies")
        return
    for skin in doc["skins"]:
        got = [doc["nodes"][j]["name"] for j in skin["joints"]]
        check(got[-len(bones):] == bones, "skin %s joints %s..., expected bone_names %s..."
              % (skin.get("name"), got[:3], bones[:3]))
        check(HIPS[names] in got and THIGH[names] in got and "left_hip" not in got,
              "skin %s lacks %s/%s or keeps left_hip" % (skin.get("name"), HIPS[names], THIGH[names]))
    print("bone names (%s): %d skins carry bone_names (%s for left_hip, ...)"
          % (names, len(doc["skins"]), bones[bodies[0]["joint_names"].index("left_hip")]))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--fixtures", required=True)
    ap.add_argument("--layout", default="wham", choices=sorted(FIXTURES))
    ap.add_argument("--work", default="/tmp/scene_check")
    ap.add_argument("--format", default="glb", choices=["glb", "fbx"],
                    help="fbx: write the scene as FBX, checked in Blender only (needs --blender)")
    ap.add_argument("--skeleton-names", choices=["mixamo", "ue5"],
                    help="export with these bone names and check every skin carries them")
    ap.add_argument("--web-src", help="tests/web: also play the scene in three.js (three_scene_test.mjs)")
    ap.add_argument("--babylon-src", help="tests/web: also play the scene in Babylon.js (babylon_scene_test.mjs)")
    ap.add_argument("--blender", help="a Blender binary: also play it in Blender (tests/roundtrip/blender_scene.py)")
    ap.add_argument("--godot", help="a Godot 3.2 binary with the editor (godot3-server): also import and play it "
                    "in Godot (tests/cli/godot_scene.py)")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    fixture = os.path.join(a.fixtures, FIXTURES[a.layout])
    model_name = MODELS.get(a.layout, "smpl_small")
    model_path = os.path.join(a.fixtures, "models", model_name + ".npz")
    out = os.path.join(a.work, a.layout + "_scene." + a.format)
    if a.format == "fbx" and not a.blender:
        sys.exit("FAIL: --format fbx is checked in Blender: give --blender")
    for p in (out, out + ".smpl.json"):
        if os.path.exists(p):
            os.remove(p)
    cmd = [a.exe, "--model", model_path, "--motion", fixture, "--out", out, "--scene",
           "--skin-weights", "truncated", "--max-influences", "4", "--corrective-refit", "off"]
    if a.skeleton_names:
        cmd += ["--skeleton-names", a.skeleton_names]
    refusals(a, model_path, fixture)
    run = subprocess.run(cmd, capture_output=True, text=True)
    print(" ".join(cmd))
    if run.returncode != 0:
        sys.exit("FAIL: exit %d: %s" % (run.returncode, run.stderr.strip()))
    check("scene: " in run.stderr, "no scene note on stderr: %r" % run.stderr[-400:])

    m = video_cases.load_model(a.fixtures, model_name)
    weights = model_math.prune(m["weights"], 4)
    case = {"name": a.layout + "_scene", "fixture": FIXTURES[a.layout], "model": model_name,
            "args": ["--track", "all"], "outputs": None, "frames": [], "expression": None}
    refs = {sfx[len(".track"):-len(".glb")]: c for sfx, c in video_cases.clips(case, a.fixtures, m)}
    detected = detections(a.layout, fixture)
    starts = {t: min(frames) for t, frames in detected.items()}
    check(sorted(refs) == sorted(starts), "reference tracks %s, fixture %s" % (sorted(refs), sorted(starts)))
    first = min(starts.values())
    end = max(starts[t] + len(refs[t]["pose"]) for t in refs)

    with open(out + ".smpl.json", encoding="utf-8") as fh:
        sidecar = json.load(fh)
    scene = sidecar["scene"]
    check([scene["first_frame"], scene["end_frame"]] == [first, end],
          "scene frames %s, expected %s" % ([scene["first_frame"], scene["end_frame"]], [first, end]))
    fps = float(scene["fps"])
    ids = sorted(refs, key=int)
    for tid in ids:
        entry = [b for b in scene["bodies"] if b["name"] == "body_" + tid]
        check(len(entry) == 1 and entry[0]["track"] == tid and entry[0]["first_frame"] == starts[tid],
              "sidecar scene entry of body_%s: %s" % (tid, entry))
    if a.skeleton_names and a.format == "glb":
        check_bone_names(out, sidecar, a.skeleton_names)
    camera = expected_camera(a.layout, fixture)
    if a.format == "glb":
        check_glb(out, refs, detected, starts, first, end, fps, m, weights, camera)
    expected = expected_clients(refs, detected, first, end, fps, m, weights, camera_for_clients(camera, first, end))
    with open(out + ".expected.json", "w", encoding="utf-8") as fh:
        json.dump(expected, fh)
    if a.web_src:
        client(["node", os.path.join(a.web_src, "three_scene_test.mjs"), "--asset", out,
                "--expected", out + ".expected.json", "--tol", str(TOLERANCE)], "three.js")
    if a.babylon_src:
        client(["node", os.path.join(a.babylon_src, "babylon_scene_test.mjs"), "--asset", out,
                "--expected", out + ".expected.json", "--tol", str(TOLERANCE)], "Babylon.js")
    if a.blender:
        client([a.blender, "-b", "--factory-startup", "--python-exit-code", "1", "--python",
                os.path.join(HERE, "..", "roundtrip", "blender_scene.py"), "--", "--asset", out,
                "--expected", out + ".expected.json", "--tol", str(TOLERANCE)], "Blender")
    if a.godot:
        client([sys.executable, os.path.join(HERE, "godot_scene.py"), "--godot", a.godot, "--asset", out,
                "--expected", out + ".expected.json", "--tol", str(GODOT_TOLERANCE)], "Godot")
    if FAILED:
        sys.exit("%d check(s) failed" % len(FAILED))


if __name__ == "__main__":
    main()
