#!/usr/bin/python3
"""An independent numpy UsdSkel evaluation of what tinyusdz read from a USD
export (tests/usd/usd_read.mjs writes the JSON), and its checks against the
GLB exported with the same options and against the model's own math.

    usdskel_eval.py --usd USD.json [--glb SAME.glb] [--usdz FILE.usdz]
                    [--reference REF.json --frames 0,120,239] [--tol 1e-5]

--usdz: the container: stored entries, 64-byte aligned data, the layer first.
Without time samples: the evaluation at the default time equals the points
(the animation's defaults and restTransforms compose to the bindTransforms).
--glb: the USD's points, joints, skin weights, blend shape offsets, animated
blend shape weights and joint rotations equal the GLB's (float32 values exact;
quaternions up to sign), and inverse(bindTransforms) equal the skin's
inverseBindMatrices (1e-6).
--reference: tests/web/anim_reference.py's posed vertices (numpy's forward pass
of the model and the motion, tests/roundtrip/model_math.py) at source frames
`--frames`; the USD evaluated at those time codes (time code = frame) must lie
within --tol metres. Two plausible wrong readings of the same file must miss the
reference by more than 100 x tol (else the check could not tell them apart):
quaternions read as (x, y, z, w), and matrices read as column-vector
(translation in the last column).
Prints every measured number; exit 1 when a check fails.

USD conventions used:
- Matrices are row-major and act on row vectors, translation in the last row:
  v' = v M (OpenUSD, https://openusd.org/dev/api/usd_geom_page_front.html
  #UsdGeom_LinAlgBasics; the AOUSD forum thread "USD XForms: Row vs Column
  Major", https://forum.aousd.org/t/usd-xforms-row-vs-column-major/644, where
  ( (1,0,0,0), (0,1,0,0), (0,0,1,0), (5,0,0,1) ) translates by 5 in x).
- quatf text is (real, i, j, k): GfQuatf is "a real coefficient and three
  imaginary coefficients" and prints the real part first; the identity is
  (1, 0, 0, 0).
- UsdSkel (OpenUSD "UsdSkel Schemas In-Depth", UsdSkelSkinTransformLBS; the
  same equations summarised in lighttransport/LightUSD's wiki page "usdSkel":
  K_i = inv(B_i) * J_i, p = sum_i w_i K_i G p_local): local joint
  transforms from the SkelAnimation's translations/rotations/scales (else the
  Skeleton's restTransforms) composed down the `joints` paths (a joint's parent
  is its path without the last element: UsdSkelTopology), skel-space
  = local * parent skel-space; skinning transform = inverse(bindTransform) *
  skel-space (row vectors); blend shapes (weight * offsets at pointIndices,
  mapped by name from the animation's blendShapes to the mesh's
  skel:blendShapes) are added to the points before skinning; points go through
  primvars:skel:geomBindTransform, then linear blend skinning with
  primvars:skel:jointIndices / jointWeights (elementSize influences a point).
  A local transform from components is scale, then rotate, then translate
  (UsdSkelMakeTransform: S * R * T in row-vector form).
"""
import argparse
import json
import struct
import sys
import zipfile

import numpy as np

FAILED = []
WEIGHT_ULPS_TOL = 1e-7  # skin weights vs the GLB's: a few float32 ulps apart (see check_glb)


def check(ok, message):
    print(("ok:   " if ok else "FAIL: ") + message)
    if not ok:
        FAILED.append(message)


# ---------------------------------------------------------------------------
# UsdSkel evaluation


def quat_matrix_row(q, order="wxyz"):
    """(4,) quaternion -> (3,3) rotation for row vectors (v' = v R).

    order "wxyz" is USD's text order (real, i, j, k); "xyzw" is the wrong reading."""
    q = np.asarray(q, dtype=np.float64)
    w, x, y, z = q if order == "wxyz" else (q[3], q[0], q[1], q[2])
    n = np.sqrt(w * w + x * x + y * y + z * z)
    w, x, y, z = w / n, x / n, y / n, z / n
    column = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                       [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                       [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])
    return column.T


def sample_at(attr, t):
    """An attribute's value at time code t: its sample at t, else its default (no interpolation:
    the checks evaluate at authored time codes only)."""
    if attr is None:
        return None
    samples = attr.get("samples") or {}
    if samples:
        key = next((k for k in samples if float(k) == float(t)), None)
        if key is None:
            raise ValueError("no sample at time code %g (have %d samples)" % (t, len(samples)))
        return samples[key]
    return attr.get("default")


def local_transforms(usd, t, quat_order):
    """(J,4,4) row-vector local joint transforms at time code t, in the Skeleton's joint order."""
    skel, anim = usd["skeleton"], usd["animation"]
    joints = skel["joints"]
    local = np.array(usd["_rest"], dtype=np.float64).copy()
    tr, ro, sc = (sample_at(anim.get(k), t) for k in ("translations", "rotations", "scales"))
    if tr is None or ro is None:
        return local
    where = {name: i for i, name in enumerate(anim["joints"])}
    for j, name in enumerate(joints):
        if name not in where:
            continue  # joints the animation does not name keep their rest transform
        a = where[name]
        m = np.eye(4)
        s = np.asarray(sc[a], dtype=np.float64) if sc is not None else np.ones(3)
        m[:3, :3] = np.diag(s) @ quat_matrix_row(ro[a], quat_order)
        m[3, :3] = tr[a]
        local[j] = m
    return local


def skel_space(joints, local):
    """Compose local transforms down the joint paths (row vectors: child local * parent)."""
    index = {name: i for i, name in enumerate(joints)}
    out = np.zeros_like(local)
    for j, name in enumerate(joints):  # UsdSkel orders parents before children
        parent = name.rsplit("/", 1)[0] if "/" in name else None
        out[j] = local[j] @ out[index[parent]] if parent is not None else local[j]
    return out


def blend_shape_weights(usd, t):
    """(B,) weights in the mesh's skel:blendShapes order at time code t (0 where unanimated)."""
    mesh_names = usd["mesh"]["blendShapes"]
    w = np.zeros(len(mesh_names))
    values = sample_at(usd["animation"].get("blendShapeWeights"), t)
    if values is None:
        return w
    where = {name: i for i, name in enumerate(mesh_names)}
    for name, value in zip(usd["animation"]["blendShapes"], values):
        if name in where:
            w[where[name]] = value
    return w


def evaluate(usd, t, quat_order="wxyz", matrix_rows=True):
    """(N,3) posed points in metres at time code t.

    matrix_rows=False is the wrong reading: every matrix's text rows taken as its columns."""
    fix = (lambda m: np.asarray(m, dtype=np.float64)) if matrix_rows else \
        (lambda m: np.swapaxes(np.asarray(m, dtype=np.float64), -1, -2))
    usd["_rest"] = fix(usd["skeleton"]["restTransforms"])
    mesh = usd["mesh"]
    points = np.array(mesh["points"], dtype=np.float64)
    weights = blend_shape_weights(usd, t)
    for name, w in zip(mesh["blendShapes"], weights):
        shape = usd["blendShapes"][name]
        offsets = np.asarray(shape["offsets"], dtype=np.float64)
        idx = shape["pointIndices"] if shape["pointIndices"] is not None else np.arange(len(points))
        np.add.at(points, np.asarray(idx, dtype=np.int64), w * offsets)
    geom = fix(mesh["geomBindTransform"]) if mesh["geomBindTransform"] is not None else np.eye(4)
    homog = np.hstack([points, np.ones((len(points), 1))]) @ geom
    skel = skel_space(usd["skeleton"]["joints"], local_transforms(usd, t, quat_order))
    skinning = np.linalg.inv(fix(usd["skeleton"]["bindTransforms"])) @ skel
    m = mesh["elementSize"]
    idx = np.asarray(mesh["jointIndices"], dtype=np.int64).reshape(-1, m)
    wts = np.asarray(mesh["jointWeights"], dtype=np.float64).reshape(-1, m)
    blended = np.einsum("nk,nkij->nij", wts, skinning[idx])
    posed = np.einsum("ni,nij->nj", homog, blended)[:, :3]
    return posed * float(usd["stage"].get("metersPerUnit", 0.01))


# ---------------------------------------------------------------------------
# A small GLB reader (glTF 2.0 spec: chunks, accessors; no sparse, no strides but the packed one)

GLTF_TYPES = {5121: np.uint8, 5123: np.uint16, 5125: np.uint32, 5126: np.float32}
GLTF_WIDTH = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}


def read_glb(path):
    data = open(path, "rb").read()
    magic, version, _ = struct.unpack_from("<4sII", data, 0)
    if magic != b"glTF" or version != 2:
        raise ValueError("%s: not a GLB 2.0" % path)
    doc, blob, at = None, b"", 12
    while at < len(data):
        size, kind = struct.unpack_from("<II", data, at)
        if kind == 0x4E4F534A:
            doc = json.loads(data[at + 8:at + 8 + size])
        elif kind == 0x004E4942:
            blob = data[at + 8:at + 8 + size]
        at += 8 + size
    return doc, blob


def accessor(doc, blob, index):
    a = doc["accessors"][index]
    if "sparse" in a or "bufferView" not in a:
        raise ValueError("accessor %d: sparse accessors are not read here" % index)
    view = doc["bufferViews"][a["bufferView"]]
    dtype = np.dtype(GLTF_TYPES[a["componentType"]])
    n = GLTF_WIDTH[a["type"]]
    if view.get("byteStride", n * dtype.itemsize) != n * dtype.itemsize:
        raise ValueError("accessor %d: interleaved views are not read here" % index)
    start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
    out = np.frombuffer(blob, dtype, a["count"] * n, start).reshape(a["count"], n)
    if a.get("normalized"):
        raise ValueError("accessor %d: normalized integers are not read here" % index)
    return out


# ---------------------------------------------------------------------------
# Checks


def max_abs(a, b):
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    if a.shape != b.shape:
        return float("inf")
    return float(np.max(np.abs(a - b))) if a.size else 0.0


def f32_equal(name, usd_values, glb_values, tol=0.0):
    """Equal as float32 values (tol 0: bit for bit), same shapes."""
    u = np.asarray(usd_values, dtype=np.float64)
    g = np.asarray(glb_values, dtype=np.float64)
    same_shape = u.shape == g.shape
    err = max_abs(u.astype(np.float32), g.astype(np.float32)) if same_shape else float("inf")
    check(err <= tol, "%s equal the GLB's (float32, %s; shapes %s / %s, max |diff| %.3g)"
          % (name, "exact" if tol == 0 else "within %g" % tol, u.shape, g.shape, err))


def dense_skin(indices, weights, m, joints):
    idx = np.asarray(indices, dtype=np.int64).reshape(-1, m)
    w = np.asarray(weights, dtype=np.float64).reshape(-1, m)
    dense = np.zeros((len(idx), joints))
    np.add.at(dense, (np.repeat(np.arange(len(idx)), m), idx.reshape(-1)), w.reshape(-1))
    return dense


def check_structure(usd):
    st, mesh, skel, anim = usd["stage"], usd["mesh"], usd["skeleton"], usd["animation"]
    check(st.get("metersPerUnit") == 1 and st.get("upAxis") == "Y",
          "stage metersPerUnit %s, upAxis %s (expected 1, Y)" % (st.get("metersPerUnit"), st.get("upAxis")))
    check(mesh["skeleton"] == skel["path"] and skel["animationSource"] == anim["path"],
          "bindings: mesh skel:skeleton %s, skeleton %s, animationSource %s"
          % (mesh["skeleton"], skel["path"], skel["animationSource"]))
    n, j, m = len(mesh["points"]), len(skel["joints"]), mesh["elementSize"]
    check(m == mesh["jointWeightsElementSize"] and len(mesh["jointIndices"]) == n * m
          and len(mesh["jointWeights"]) == n * m
          and mesh["jointIndicesInterpolation"] == "vertex" == mesh["jointWeightsInterpolation"],
          "skin primvars: %d points x elementSize %s, vertex interpolation" % (n, m))
    check(len(skel["bindTransforms"]) == j == len(skel["restTransforms"]),
          "skeleton: %d joints, bind/rest transforms" % j)
    check(anim["joints"] == skel["joints"] and anim["blendShapes"] == mesh["blendShapes"],
          "animation names the skeleton's joints and the mesh's blend shapes in order")
    check(mesh["normals"] is not None and len(mesh["normals"]) == n and mesh["normalsInterpolation"] == "vertex"
          and set(mesh["faceVertexCounts"]) == {3} and len(mesh["faceVertexIndices"]) == 3 * len(mesh["faceVertexCounts"]),
          "mesh: vertex normals, %d triangles" % len(mesh["faceVertexCounts"]))
    times = anim["timeCodes"]
    if times:
        start, end = st.get("startTimeCode"), st.get("endTimeCode")
        check(times == list(range(len(times))) and start == 0 and end == len(times) - 1,
              "time codes 0..%d, startTimeCode %s, endTimeCode %s" % (len(times) - 1, start, end))
    w = np.asarray(mesh["jointWeights"], dtype=np.float64).reshape(-1, m)
    check(np.max(np.abs(w.sum(1) - 1)) < 1e-6, "skin weights sum to 1 (max |sum-1| %.2g)"
          % np.max(np.abs(w.sum(1) - 1)))


def glb_morph_weights(doc, blob, times):
    """(T, B) animated morph weights of the GLB's one weights channel, at its keys."""
    for anim in doc.get("animations", []):
        for ch in anim["channels"]:
            if ch["target"]["path"] == "weights":
                s = anim["samplers"][ch["sampler"]]
                keys = accessor(doc, blob, s["input"]).reshape(-1)
                values = accessor(doc, blob, s["output"]).reshape(len(keys), -1)
                return keys, values
    return None, None


def check_glb(usd, glb_path):
    doc, blob = read_glb(glb_path)
    mesh, skel, anim = usd["mesh"], usd["skeleton"], usd["animation"]
    prim = doc["meshes"][0]["primitives"][0]
    f32_equal("points", mesh["points"], accessor(doc, blob, prim["attributes"]["POSITION"]))
    skin = doc["skins"][0]
    names = [doc["nodes"][n]["name"] for n in skin["joints"]]
    leaves = [p.rsplit("/", 1)[-1] for p in skel["joints"]]
    check(leaves == names, "joints: the USD joint paths' names equal the GLB skin's %d joints" % len(names))
    j = len(names)
    sets = sorted(int(k.split("_")[1]) for k in prim["attributes"] if k.startswith("WEIGHTS_"))
    glb_dense = sum(dense_skin(accessor(doc, blob, prim["attributes"]["JOINTS_%d" % s]),
                               accessor(doc, blob, prim["attributes"]["WEIGHTS_%d" % s]), 4, j) for s in sets)
    # The GLB writer nudges a vertex's float32 weights by an ulp or two until they sum to 1 the
    # way the glTF validator adds them (writers/gltf/gltf_streams.cpp); USD keeps the asset's.
    f32_equal("skin weights (dense, per joint)",
              dense_skin(mesh["jointIndices"], mesh["jointWeights"], mesh["elementSize"], j), glb_dense,
              tol=WEIGHT_ULPS_TOL)
    ibm = accessor(doc, blob, skin["inverseBindMatrices"]).reshape(-1, 4, 4)  # column-major = row-vector rows
    err = max_abs(np.linalg.inv(np.asarray(skel["bindTransforms"], dtype=np.float64)), ibm)
    check(err <= 1e-6, "inverse(bindTransforms) equal the GLB's inverseBindMatrices (max |diff| %.3g)" % err)
    target_names = doc["meshes"][0].get("extras", {}).get("targetNames", [])
    check(target_names == mesh["blendShapes"],
          "blend shape names equal the GLB's %d morph target names in order" % len(target_names))
    n = len(mesh["points"])
    usd_dense, glb_dense = [], []
    for name, target in zip(mesh["blendShapes"], prim.get("targets", [])):
        shape = usd["blendShapes"][name]
        d = np.zeros((n, 3))
        idx = shape["pointIndices"] if shape["pointIndices"] is not None else np.arange(n)
        d[np.asarray(idx, dtype=np.int64)] = shape["offsets"]
        usd_dense.append(d)
        glb_dense.append(accessor(doc, blob, target["POSITION"]))
    f32_equal("blend shape offsets (dense)", usd_dense, glb_dense)
    keys, values = glb_morph_weights(doc, blob, None)
    usd_times = anim["timeCodes"]
    if keys is None:
        check(not usd_times, "no animation in the GLB, no time samples in the USD")
        return
    fps = float(usd["stage"].get("timeCodesPerSecond", 24))
    check(max_abs(np.asarray(usd_times) / fps, keys) < 1e-6,
          "time codes / timeCodesPerSecond (%g) equal the GLB's %d keys" % (fps, len(keys)))
    f32_equal("animated blend shape weights", [sample_at(anim["blendShapeWeights"], t) for t in usd_times], values)
    check_glb_rotations(doc, blob, usd, usd_times)


def check_glb_rotations(doc, blob, usd, times):
    """USD rotations (real, i, j, k) vs the GLB's rotation keys (x, y, z, w), up to sign."""
    node_joint = {n: i for i, n in enumerate(doc["skins"][0]["joints"])}
    anim = doc["animations"][0]
    worst, count = 0.0, 0
    for ch in anim["channels"]:
        if ch["target"]["path"] != "rotation" or ch["target"]["node"] not in node_joint:
            continue
        j = node_joint[ch["target"]["node"]]
        s = anim["samplers"][ch["sampler"]]
        glb = accessor(doc, blob, s["output"]).astype(np.float64)
        usd_q = np.array([sample_at(usd["animation"]["rotations"], t)[j] for t in times], dtype=np.float64)
        as_xyzw = usd_q[:, [1, 2, 3, 0]]
        sign = np.where(np.sum(as_xyzw * glb, axis=1, keepdims=True) < 0, -1.0, 1.0)
        worst = max(worst, max_abs(as_xyzw * sign, glb))
        count += 1
    check(count > 0 and worst < 1e-7,
          "joint rotations of %d channels equal the GLB's keys (max |diff| %.3g)" % (count, worst))


def check_reference(usd, ref_path, frames, tol):
    ref = json.load(open(ref_path, encoding="utf-8"))
    if [int(f) for f in ref["frames"]] != frames:
        raise ValueError("%s: frames %s, asked %s" % (ref_path, ref["frames"], frames))
    errs = {"right": [], "quat xyzw": [], "column-vector matrices": []}
    for frame, verts in zip(frames, ref["vertices"]):
        verts = np.asarray(verts, dtype=np.float64)
        for name, kw in (("right", {}), ("quat xyzw", {"quat_order": "xyzw"}),
                         ("column-vector matrices", {"matrix_rows": False})):
            posed = evaluate(usd, frame, **kw)
            e = float(np.max(np.linalg.norm(posed - verts, axis=1))) if posed.shape == verts.shape else float("inf")
            errs[name].append(e)
            print("  frame %d, %s reading: max vertex error %.3g m" % (frame, name, e))
    check(max(errs["right"]) <= tol,
          "UsdSkel evaluation within %g m of the model at frames %s (max %.3g m)" % (tol, frames, max(errs["right"])))
    for name in ("quat xyzw", "column-vector matrices"):
        check(min(errs[name]) > 100 * tol,
              "wrong reading (%s) misses the model by > %g m at every frame (min %.3g m)"
              % (name, 100 * tol, min(errs[name])))


def check_rest(usd, tol):
    """Without time samples the animation's defaults are the rest pose: UsdSkel must give the points."""
    err = float(np.max(np.abs(evaluate(usd, 0) - np.asarray(usd["mesh"]["points"], dtype=np.float64))))
    check(err <= tol, "static file: the evaluation at the default time gives the points (max |diff| %.3g m)" % err)


def check_usdz(path):
    """The USDZ container (OpenUSD docs "Usdz File Format Specification"): a zip archive, entries
    stored without compression, each file's data 64-byte aligned, the first file the root layer."""
    with zipfile.ZipFile(path) as z:
        infos = z.infolist()
        raw = open(path, "rb").read()
        offsets = []
        for info in infos:  # data start = local header (30 bytes + name + extra) after its offset
            name_len, extra_len = struct.unpack_from("<HH", raw, info.header_offset + 26)
            offsets.append(info.header_offset + 30 + name_len + extra_len)
    check(bool(infos) and infos[0].filename.endswith((".usda", ".usdc", ".usd")),
          "usdz: first entry %s is the layer" % (infos[0].filename if infos else None))
    check(all(i.compress_type == zipfile.ZIP_STORED for i in infos), "usdz: entries stored uncompressed")
    check(all(o % 64 == 0 for o in offsets), "usdz: data offsets %s are 64-byte aligned" % offsets)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--usd", required=True, help="usd_read.mjs output")
    ap.add_argument("--glb", help="the GLB exported with the same options")
    ap.add_argument("--reference", help="anim_reference.py PREFIX.json")
    ap.add_argument("--frames", default="", help="the reference's source frames, comma-separated")
    ap.add_argument("--tol", type=float, default=1e-5)
    ap.add_argument("--usdz", help="the .usdz file the JSON was read from: its container layout")
    a = ap.parse_args()
    usd = json.load(open(a.usd, encoding="utf-8"))
    check_structure(usd)
    if a.usdz:
        check_usdz(a.usdz)
    if a.glb:
        check_glb(usd, a.glb)
    if a.reference:
        check_reference(usd, a.reference, [int(f) for f in a.frames.split(",")], a.tol)
    if not usd["animation"]["timeCodes"]:
        check_rest(usd, a.tol)
    print("%d check(s) failed" % len(FAILED) if FAILED else "all checks passed")
    return 1 if FAILED else 0


if __name__ == "__main__":
    sys.exit(main())
