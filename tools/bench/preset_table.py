#!/usr/bin/python3
"""The --preset table (README "Size", smpl-export --help) in one run: for each
preset (and the default export as the baseline) the GLB's size, the
whole-process export time and the vertex error of the file against the
model's math over a baked motion.

    /usr/bin/python3 tools/bench/preset_table.py --exe build/cli/smpl-export \
        [--model M.npz ...] [--motion walk.npz] [--work DIR] [--repeats 3]

Models: by default the fixture SMPL layout (tests/fixtures: 288 vertices),
the built-in body (`builtin`: smooth correctives, arrays from smpl-reference
--dump-model) and a full-size SMPL stand-in (tools/bench/make_standin.py: 6890 vertices,
207 correctives; random values, so its compressed sizes are pessimistic).
Motion: by default a synthetic AMASS-layout walk-like clip (120 frames at
30 fps, smooth sinusoids within +-0.6 rad, made here), baked with each
preset's options.

The error: the file is decoded here (numpy; EXT_meshopt_compression with
meshoptimizer's own decoder, libmeshoptimizer through ctypes), played at
every 6th key (base + sum w_t d_t with the file's baked weights, node
transforms from the animation's keys, linear blend skinning with every
JOINTS_n/WEIGHTS_n set) and compared with the model's math with all its
weights (tests/roundtrip/model_math.py, written from the equations), in the
exported axes. "added" is the preset's max error minus the default
export's (the pruning error both share at 4 influences).
"""
import argparse
import ctypes
import json
import os
import struct
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path.insert(0, os.path.join(ROOT, "tests", "roundtrip"))
import model_math  # noqa: E402

PRESETS = [("default", []), ("web", ["--preset", "web"]), ("engine", ["--preset", "engine"]),
           ("archive", ["--preset", "archive"])]
Z_UP_TO_Y_UP = np.array([[1.0, 0, 0], [0, 0, 1], [0, -1, 0]])  # AMASS worlds are Z up
COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}
DTYPES = {5120: np.int8, 5121: np.uint8, 5122: np.int16, 5123: np.uint16, 5125: np.uint32, 5126: np.float32}


def meshopt_library():
    for name in ("libmeshoptimizer.so", "libmeshoptimizer.so.2d"):
        try:
            return ctypes.CDLL(name)
        except OSError:
            pass
    raise SystemExit("preset_table.py: libmeshoptimizer not found (apt-get install libmeshoptimizer-dev)")


class Glb:
    """A GLB's JSON and buffer 0, with bufferViews decoded (EXT_meshopt_compression too)."""

    def __init__(self, path):
        data = open(path, "rb").read()
        magic, _, _ = struct.unpack_from("<III", data, 0)
        assert magic == 0x46546C67, path + ": not a GLB"
        json_length = struct.unpack_from("<I", data, 12)[0]
        self.doc = json.loads(data[20:20 + json_length])
        at = 20 + json_length
        self.bin = data[at + 8:at + 8 + struct.unpack_from("<I", data, at)[0]] if at < len(data) else b""
        self.views = {}

    def view(self, v):
        if v in self.views:
            return self.views[v]
        view = self.doc["bufferViews"][v]
        ext = view.get("extensions", {}).get("EXT_meshopt_compression")
        if ext is None:
            out = self.bin[view.get("byteOffset", 0):view.get("byteOffset", 0) + view["byteLength"]]
        else:
            lib = meshopt_library()
            count, stride = ext["count"], ext["byteStride"]
            src = self.bin[ext.get("byteOffset", 0):ext.get("byteOffset", 0) + ext["byteLength"]]
            dst = ctypes.create_string_buffer(count * stride)
            decode = lib.meshopt_decodeIndexBuffer if ext["mode"] == "TRIANGLES" else lib.meshopt_decodeVertexBuffer
            if ext["mode"] not in ("TRIANGLES", "ATTRIBUTES"):
                decode = lib.meshopt_decodeIndexSequence
            rc = decode(dst, ctypes.c_size_t(count), ctypes.c_size_t(stride), src, ctypes.c_size_t(len(src)))
            assert rc == 0, "meshopt could not decode view %d" % v
            filters = {"OCTAHEDRAL": lib.meshopt_decodeFilterOct, "QUATERNION": lib.meshopt_decodeFilterQuat,
                       "EXPONENTIAL": lib.meshopt_decodeFilterExp}
            if ext.get("filter", "NONE") != "NONE":
                filters[ext["filter"]](dst, ctypes.c_size_t(count), ctypes.c_size_t(stride))
            out = dst.raw
        self.views[v] = out
        return out

    def accessor(self, i):
        """Accessor i as float64 (count, components): strides, sparse and normalisation applied."""
        a = self.doc["accessors"][i]
        n, dtype = COMPONENTS[a["type"]], np.dtype(DTYPES[a["componentType"]])
        out = np.zeros((a["count"], n))
        if "bufferView" in a:
            view = self.doc["bufferViews"][a["bufferView"]]
            stride = view.get("byteStride", n * dtype.itemsize)
            raw = np.frombuffer(self.view(a["bufferView"]), dtype=np.uint8)
            start, size = a.get("byteOffset", 0), n * dtype.itemsize
            raw = np.concatenate([raw[start:], np.zeros(stride, np.uint8)])[:a["count"] * stride]
            rows = np.ascontiguousarray(raw.reshape(a["count"], stride)[:, :size])
            out = rows.view(dtype).reshape(-1, n).astype(np.float64)
        if "sparse" in a:
            s = a["sparse"]
            idx = np.frombuffer(self.view(s["indices"]["bufferView"]), dtype=DTYPES[s["indices"]["componentType"]],
                                count=s["count"], offset=s["indices"].get("byteOffset", 0))
            vals = np.frombuffer(self.view(s["values"]["bufferView"]), dtype=dtype, count=s["count"] * n,
                                 offset=s["values"].get("byteOffset", 0)).reshape(-1, n)
            out[idx.astype(np.int64)] = vals
        if a.get("normalized"):
            out = np.maximum(out / float(np.iinfo(dtype).max), -1.0) if dtype.kind == "i" else out / float(
                np.iinfo(dtype).max)
        return out


def quat_matrix(q):
    x, y, z, w = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


class Player:
    """Plays a GLB's first animation at key f: base + sum w d, node transforms, LBS over every set."""

    def __init__(self, glb):
        self.g, doc = glb, glb.doc
        prim = doc["meshes"][0]["primitives"][0]
        attr = prim["attributes"]
        self.base = glb.accessor(attr["POSITION"])
        sets = sorted(int(k.split("_")[1]) for k in attr if k.startswith("JOINTS_"))
        self.joints = np.concatenate([glb.accessor(attr["JOINTS_%d" % s]) for s in sets], 1).astype(int)
        self.weights = np.concatenate([glb.accessor(attr["WEIGHTS_%d" % s]) for s in sets], 1)
        self.targets = [glb.accessor(t["POSITION"]) for t in prim.get("targets", [])]
        skin = doc["skins"][0]
        self.skin_nodes = skin["joints"]
        self.ibm = glb.accessor(skin["inverseBindMatrices"]).reshape(-1, 4, 4).transpose(0, 2, 1)
        self.parent = {c: p for p, node in enumerate(doc["nodes"]) for c in node.get("children", [])}
        self.keys = {}
        anim = doc["animations"][0]
        for ch in anim["channels"]:
            sampler = anim["samplers"][ch["sampler"]]
            self.keys[(ch["target"]["node"], ch["target"]["path"])] = glb.accessor(sampler["output"])
        self.mesh_node = next(i for i, n in enumerate(doc["nodes"]) if "mesh" in n)

    def local(self, node, f):
        n = self.g.doc["nodes"][node]
        t = self.keys.get((node, "translation"))
        r = self.keys.get((node, "rotation"))
        m = np.eye(4)
        m[:3, :3] = quat_matrix(r[f] if r is not None else np.array(n.get("rotation", [0, 0, 0, 1.0])))
        m[:3, 3] = t[f] if t is not None else n.get("translation", [0, 0, 0])
        return m

    def world(self, node, f, cache):
        if node not in cache:
            p = self.parent.get(node)
            cache[node] = (self.world(p, f, cache) if p is not None else np.eye(4)) @ self.local(node, f)
        return cache[node]

    def vertices(self, f):
        w = self.keys.get((self.mesh_node, "weights"))
        v = self.base.copy()
        if w is not None and self.targets:
            row = w.reshape(-1, len(self.targets))[f]
            for t, d in zip(row, self.targets):
                v += t * d
        cache = {}
        skin = np.stack([self.world(j, f, cache) @ self.ibm[k] for k, j in enumerate(self.skin_nodes)])
        blended = np.einsum("ns,nsij->nij", self.weights, skin[self.joints])
        return np.einsum("nij,nj->ni", blended[:, :3, :3], v) + blended[:, :3, 3]


def walk_motion(path, frames=120, fps=30.0):
    """A smooth AMASS-layout (SMPL-H, 52 joints) clip: per-joint sinusoids within +-0.6 rad."""
    rng = np.random.default_rng(25)
    t = np.arange(frames) / fps
    amp, freq, phase = rng.uniform(0.1, 0.6, (52, 3)), rng.uniform(0.3, 1.5, (52, 3)), rng.uniform(0, 6.3, (52, 3))
    poses = amp[None] * np.sin(2 * np.pi * freq[None] * t[:, None, None] + phase[None])
    trans = np.stack([0.8 * t, 0.02 * np.sin(4 * t), 0.9 + 0.01 * np.cos(4 * t)], 1)
    np.savez(path, poses=poses.reshape(frames, -1), trans=trans, mocap_framerate=np.array(fps),
             betas=np.zeros(16), gender=np.array("neutral"))


def builtin_model(exe, work):
    """The built-in body's arrays (betas 0) from smpl-reference --dump-model, beside --exe's tools."""
    tool = os.path.join(os.path.dirname(exe), "..", "tools", "smpl-reference")
    prefix = os.path.join(work, "builtin_model")
    subprocess.run([tool, "--model", "builtin", "--poses", "1", "--dump-model", "--out", prefix], check=True,
                   stdout=subprocess.DEVNULL)
    header, arrays = model_math.read_reference(prefix)
    return {"parents": np.array(header["parents"]), "posedirs": arrays["posedirs"], "weights": arrays["weights"],
            "v_shaped": arrays["v_shaped"], "joints": arrays["rest_joints"], "v_template": arrays["v_shaped"]}


def reference(model, motion, frames):
    """Model math with every weight, in the exported axes (as tests/web/anim_reference.py)."""
    sys.path.insert(0, os.path.join(ROOT, "tests", "web"))
    import anim_reference  # noqa: E402
    m = anim_reference.read_amass(motion)
    names = model_math.joint_names(len(model["parents"]))
    if "v_shaped" in model:  # the built-in body: its rest shape (the motion's betas are 0)
        v_shaped, joints = model["v_shaped"], model["joints"]
    else:
        b = min(model["shapedirs"].shape[2], 300)
        v_shaped, joints = model_math.shape(model, m["betas"][:min(16, b)])
    out = []
    for frame in frames:
        pose = np.array([m["rot"][n][frame] if n in m["rot"] else np.zeros(3) for n in names])
        verts, _, _ = model_math.forward(model, v_shaped, joints, pose, model["weights"])
        out.append((verts + m["trans"][frame]) @ Z_UP_TO_Y_UP.T)
    return out


def measure(exe, model_path, motion, work, tag, args, repeats, expected):
    out = os.path.join(work, "%s_%s.glb" % (tag, args[1] if args else "default"))
    cmd = [exe, "--model", model_path, "--motion", motion, "--out", out, "--quiet"] + args
    seconds = []
    for _ in range(repeats):
        start = time.perf_counter()
        subprocess.run(cmd, check=True)
        seconds.append(time.perf_counter() - start)
    player = Player(Glb(out))
    errors = [np.linalg.norm(player.vertices(f) - e, axis=1) for f, e in expected]
    return os.path.getsize(out), float(np.median(seconds)), max(e.max() for e in errors), float(
        np.mean([e.mean() for e in errors]))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--model", action="append", help="model .npz (repeatable; default: fixture + stand-in)")
    ap.add_argument("--motion")
    ap.add_argument("--work")
    ap.add_argument("--repeats", type=int, default=3)
    a = ap.parse_args()
    work = a.work or tempfile.mkdtemp(prefix="preset-table-")
    os.makedirs(work, exist_ok=True)
    motion = a.motion or os.path.join(work, "walk_smplh.npz")
    if not a.motion:
        walk_motion(motion)
    models = a.model
    if not models:
        subprocess.run([sys.executable, os.path.join(ROOT, "tests", "fixtures", "make_models.py"), work],
                       check=True, stdout=subprocess.DEVNULL)
        subprocess.run([sys.executable, os.path.join(HERE, "make_standin.py"), work], check=True,
                       stdout=subprocess.DEVNULL)
        models = [os.path.join(work, "models", "smpl_small.npz"), "builtin",
                  os.path.join(work, "standin_smpl_stored.npz")]
    print("| model | preset | size | vs default | export time | max error | mean error | added (max) |")
    print("|---|---|---|---|---|---|---|---|")
    for model_path in models:
        model = builtin_model(a.exe, work) if model_path == "builtin" else model_math.load_model_npz(model_path)
        frames = list(range(0, 120, 6))
        expected = list(zip(frames, reference(model, motion, frames)))
        tag = os.path.splitext(os.path.basename(model_path))[0]
        base = None
        for name, args in PRESETS:
            size, sec, worst, mean = measure(a.exe, model_path, motion, work, tag, args, a.repeats, expected)
            base = base or (size, worst)
            print("| %s (%d vertices) | %s | %.2f MB | %.0f%% | %.2f s | %.3f mm | %.4f mm | %+.3f mm |" % (
                tag, len(model["v_template"]), name, size / 1e6, 100.0 * size / base[0], sec, worst * 1e3,
                mean * 1e3, (worst - base[1]) * 1e3))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
