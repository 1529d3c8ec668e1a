"""Reliability cases for inputs: hostile sizes,
endless files, bad numbers and raw bytes in names. Every case checks, through
harness.expect_failure: the exit code, one printable error line naming the
right file, no output or temporary file, inputs unchanged and bounded peak
memory. The hostile inputs are generated here with numpy (small on disk: the
large members are runs of zeros, deflated).
Run: /usr/bin/python3 tests/reliability/input_cases.py SMPL_EXPORT FIXTURE_DIR WORK_DIR
"""
import json
import os
import pathlib
import sys
import zipfile

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import harness  # noqa: E402

exe, fixtures, work = harness.args()
MODEL = fixtures / "models" / "smpl_small.npz"
MOTIONS = fixtures / "motions"
out_dir = work / "out"
out_dir.mkdir()
OUT = out_dir / "o.glb"


def npy_header(dtype, shape):
    """The .npy v1 preamble numpy writes for a C-order array."""
    d = "{'descr': '%s', 'fortran_order': False, 'shape': %s, }" % (dtype, repr(tuple(shape)))
    pad = 64 - (10 + len(d) + 1) % 64
    d = d + " " * (pad % 64) + "\n"
    return b"\x93NUMPY\x01\x00" + len(d).to_bytes(2, "little") + d.encode("latin-1")


def zero_npz(path, members):
    """An .npz whose members are {name: (dtype, shape)} of zeros, streamed through
    deflate (a 512 MiB member is about 0.5 MB on disk), or {name: ndarray}."""
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as z:
        for name, spec in members.items():
            if isinstance(spec, np.ndarray):
                import io
                b = io.BytesIO()
                np.save(b, spec)
                z.writestr(name + ".npy", b.getvalue())
                continue
            dtype, shape = spec
            n = int(np.prod(shape)) * np.dtype(dtype).itemsize
            with z.open(name + ".npy", "w", force_zip64=True) as f:
                f.write(npy_header(dtype, shape))
                chunk = bytes(1 << 22)
                while n > 0:
                    f.write(chunk[:min(n, len(chunk))])
                    n -= len(chunk)
    return path


def motion_npz(name, frames=4, **extra):
    arrays = {"poses": np.zeros((frames, 72)), "mocap_framerate": np.array(30.0)}
    arrays.update(extra)
    path = work / name
    np.savez(path, **arrays)
    return path


def model_with(name, **changes):
    arrays = dict(np.load(MODEL))
    for key, fn in changes.items():
        arrays[key] = fn(arrays[key].copy())
    path = work / name
    np.savez(path, **arrays)
    return path


ONLY = os.environ.get("SMPL_RELIABILITY_ONLY", "")  # run only cases whose name contains this


def fail(name, argv, code, names, inputs, max_rss_mb=400):
    if ONLY and ONLY not in name:
        return
    harness.expect_failure(name, [exe] + [str(a) for a in argv], exit_code=code, names=names,
                           inputs=[str(p) for p in inputs], out_dirs=[out_dir],
                           forbidden=[str(OUT), str(OUT) + ".smpl.json"], max_rss_mb=max_rss_mb)


def base(*more):
    return ["--model", MODEL, "--out", OUT, "--quiet"] + list(more)


# ---- kind 1: memory ------------------------------------------------------------
bomb = zero_npz(work / "bomb.npz", {"shapedirs": ("|u1", (512, 1 << 20))})          # 512 MiB inflated
fail("npz member inflating past the limit", ["--model", bomb, "--out", OUT, "--memory-limit", "256M"],
     2, ["bomb.npz/shapedirs.npy", "inflating", "set --memory-limit"], [bomb])
widen = zero_npz(work / "widen.npz", {"shapedirs": ("|u1", (200, 1 << 20))})        # 1.6 GiB as doubles
fail("npz member widened to doubles past the limit", ["--model", widen, "--out", OUT, "--memory-limit", "1G"],
     2, ["widen.npz/shapedirs.npy", "as doubles would need", "the limit is 1.0 GiB"], [widen])
long2m = zero_npz(work / "long2m.npz", {"poses": ("|u1", (2000000, 72)), "mocap_framerate": np.array(30.0)})
fail("motion declaring 2,000,000 frames", base("--motion", long2m, "--memory-limit", "512M"),
     2, ["long2m.npz", "decoding 'poses' and its frames would need"], [long2m], max_rss_mb=300)
long500k = zero_npz(work / "long500k.npz", {"poses": ("|u1", (500000, 72)), "mocap_framerate": np.array(30.0)})
fail("motion whose 500,000 frames exceed the limit", base("--motion", long500k, "--memory-limit", "1G"),
     2, ["long500k.npz", "decoding 'poses' and its frames would need"], [long500k], max_rss_mb=800)
slow = zero_npz(work / "slow.npz", {"poses": ("<f8", (30000, 72)), "mocap_framerate": np.array(1.0)})
fail("resampling a 1 fps motion to --fps 1000", base("--motion", slow, "--fps", "1000"),
     3, ["slow.npz", "resampling 30000 frames", "would need"], [slow])
big_json = work / "big.json"
big_json.write_text(json.dumps({"poses": [[0] * 72] * 70000, "fps": 30}))  # 10 MB of text
fail("JSON motion whose parse exceeds the limit", base("--motion", big_json, "--memory-limit", "64M"),
     2, ["big.json", "parsing the JSON would need"], [big_json])
# Last resort: the system refuses memory below --memory-limit (here an address-space
# limit of 700 MB, set by the shell that execs smpl-export): one error line, the
# stage's exit code, never an abort (134).
if not ONLY or "last resort" in ONLY:
    def limited(*argv):
        return ["/bin/sh", "-c", 'ulimit -v 700000; exec "$0" "$@"', exe] + [str(a) for a in argv]
    harness.expect_failure("last resort: out of memory while loading the model",
                           limited("--model", widen, "--out", OUT, "--memory-limit", "16G"), exit_code=2,
                           names=["widen.npz", "out of memory"], inputs=[str(widen)], out_dirs=[out_dir],
                           forbidden=[str(OUT)], max_rss_mb=800)
    harness.expect_failure("last resort: out of memory in an export job",
                           limited(*base("--motion", long2m, "--memory-limit", "16G")), exit_code=3,
                           names=["o.glb", "out of memory"], inputs=[str(long2m)], out_dirs=[out_dir],
                           forbidden=[str(OUT)], max_rss_mb=800)
    batch_in, batch_out = work / "batch_in", work / "batch_out"
    batch_in.mkdir()
    os.link(long2m, batch_in / "long2m.npz")
    harness.expect_failure("last resort: out of memory in a batch job (worker thread)",
                           limited("--model", MODEL, "--motion-dir", batch_in, "--out-dir", batch_out,
                                   "--memory-limit", "16G", "--threads", "2"), exit_code=3,
                           names=["long2m.glb", "out of memory"], inputs=[str(batch_in)], out_dirs=[batch_out],
                           forbidden=[str(batch_out / "long2m.glb")], max_rss_mb=800)
tiny = motion_npz("tiny_fps.npz", frames=10, mocap_framerate=np.array(1e-3))
fail("tiny source frame rate", base("--motion", tiny, "--fps", "30"), 2,
     ["tiny_fps.npz", "'mocap_framerate' is 0.001 frames per second"], [tiny])
fail("--model /dev/zero", ["--model", "/dev/zero", "--out", OUT], 2, ["/dev/zero", "not a regular file"], [])
fail("--motion /dev/zero", base("--motion", "/dev/zero"), 2, ["/dev/zero", "not a regular file"], [])
# A directory is a model folder: without released model names it is one error line.
fail("--model a directory", ["--model", work, "--out", OUT], 2, [str(work), "no model files with the released names"], [])

fail("--uv /dev/zero", base("--uv", "/dev/zero"), 2, ["/dev/zero", "not a regular file"], [])

# ---- kind 5: numbers validated where they enter ----------------------------------
n_vertices = np.load(MODEL)["v_template"].shape[0]
wrap_obj = work / "wrap.obj"  # 2^32 + 1 used to wrap to vertex 1 when cast to int
wrap_obj.write_text("".join(f"v 0 0 0\n" for _ in range(n_vertices)) + "vt 0 0\nf 4294967297/1 2/1 3/1\n")
fail("UV face index beyond the int range", base("--uv", wrap_obj), 2, ["wrap.obj:", "4294967297/1"], [wrap_obj])
for label, value in (("NaN", np.nan), ("Inf", np.inf), ("1e300", 1e300)):
    betas = work / f"betas_{label}.npy"
    np.save(betas, np.array([0.5, value, 0.0]))
    fail(f"betas .npy with {label}", base("--betas-file", betas), 2, [f"betas_{label}.npy", "'betas'[1]"], [betas])
betas_json = work / "betas_big.json"
betas_json.write_text(json.dumps({"betas": [1, 2, 5000]}))
fail("betas .json beyond 1000", base("--betas-file", betas_json), 2, ["betas_big.json", "'betas'[2] is 5000"], [betas_json])
betas_npz = work / "betas_inf.npz"
np.savez(betas_npz, betas=np.array([np.inf]))
fail("betas .npz with Inf", base("--betas-file", betas_npz), 2, ["betas_inf.npz", "'betas'[0] is inf"], [betas_npz])
fail("--betas 1e300", base("--betas", "0,1e300"), 1, ["--betas", "1e+300"], [])
fail("--expression -2e3", ["--model", MODEL, "--out", OUT, "--expression", "-2e3"], 1, ["--expression"], [])
for label, value in (("NaN", np.nan), ("1e300", 1e300)):
    m = motion_npz(f"motion_betas_{label}.npz", betas=np.array([0.1, value]))
    fail(f"motion betas with {label}", base("--motion", m), 2, [f"motion_betas_{label}.npz", "'betas'[1]"], [m])


def set_flat(index, value):
    """A change for model_with(): element `index` (C order) set to `value`, as float64."""
    def change(a):
        a = a.astype(np.float64)
        a.ravel()[index] = value
        return a
    return change


huge_model = model_with("model_huge.npz", shapedirs=set_flat(5, 1e39))
fail("model value beyond float32 range", ["--model", huge_model, "--out", OUT], 2,
     ["model_huge.npz", "'shapedirs' element 5 is 1e+39"], [huge_model])
face_model = model_with("model_face.npz", f=set_flat(7, 1.5))
fail("float face index 1.5", ["--model", face_model, "--out", OUT], 2, ["model_face.npz", "'f' element 7 is 1.5"],
     [face_model])
far = motion_npz("far.npz", trans=np.array([[0, 0, 0], [0, 0, 0], [1e6, 0, 0], [0, 0, 0]]))
fail("root translation of 1e6 m", base("--motion", far), 2, ["far.npz", "'trans' frame 2 is 1e+06 m"], [far])
for label, mat in (("zero", np.zeros((3, 3))), ("scaled identity", 2 * np.eye(3)), ("reflection", np.diag([1, 1, -1.0]))):
    poses = np.tile(np.eye(3), (3, 24, 1, 1))
    poses[1, 4] = mat
    m = work / f"rot_{label.replace(' ', '_')}.npz"
    np.savez(m, poses=poses, fps=np.array(30))
    fail(f"rotation matrix: {label}", base("--motion", m), 2,
         [m.name, "frame 1 joint 4 (left_knee) is not a rotation matrix"], [m])

# ---- kind 8: untrusted bytes escaped -------------------------------------------------
evil_npy = work / "evil_key.npy"
evil_npy.write_bytes(npy_header("<f8", (1,)).replace(b"'shape'", b"'\x1b[2J\rshape'") + bytes(8))
fail("escape sequence and \\r in an npy header key", base("--betas-file", evil_npy), 2,
     ["evil_key.npy", "\\x1b[2J\\x0dshape"], [evil_npy])
evil_pkl = work / "evil_global.pkl"
evil_pkl.write_bytes(b"\x80\x02cos\x1b]0;owned\x07\nsys\rtem\n.")
fail("escape sequence and \\r in a pickle global name", ["--model", evil_pkl, "--out", OUT], 2,
     ["evil_global.pkl", "os\\x1b]0;owned\\x07.sys\\x0dtem"], [evil_pkl])
evil_member = work / "evil_member.npz"
with zipfile.ZipFile(evil_member, "w") as z:
    z.writestr("po\x1b[31mses\r.npy", npy_header("|O", (1,)) + b"\x00" * 8)
# Readers are lazy: an unneeded member is never read, so the evil name is only
# listed; a duplicate of it is refused at listing time, with the name escaped.
fail("unneeded npz member with an escape sequence in its name", base("--motion", evil_member), 2,
     ["evil_member.npz", "keys found", "po\\x1b[31mses\\x0d"], [evil_member])
evil_dup = work / "evil_dup.npz"
with zipfile.ZipFile(evil_dup, "w") as z:
    z.writestr("po\x1b[31mses\r.npy", npy_header("<f8", (1,)) + b"\x00" * 8)
    z.writestr("po\x1b[31mses\r", npy_header("<f8", (1,)) + b"\x00" * 8)
fail("escape sequence in an npz member name", base("--motion", evil_dup), 2,
     ["evil_dup.npz/po\\x1b[31mses\\x0d", "duplicate member"], [evil_dup])
evil_json = work / "evil_key.json"
# Unneeded keys never fail a file: the evil key is named where the file's keys are listed.
evil_json.write_text('{"rotation_data": [[0.0]], "tr\\u001b[2Kans\\r": [[1, 2], [3]]}')
fail("escape sequence in a JSON key", base("--motion", evil_json), 2, ["evil_key.json", "tr\\x1b[2Kans\\x0d"],
     [evil_json])
weird_name = work / "we\x1b[31mird\rname.npz"
weird_name.write_bytes(b"PK\x05\x06" + bytes(18))
fail("control characters in a user-given file name", ["--model", weird_name, "--out", OUT], 2,
     ["we\\x1b[31mird\\x0dname.npz"], [weird_name])

# ---- the budget does not get in the way of real work ----------------------------------
if not ONLY:
    harness.expect_success("ordinary export within --memory-limit 64M",
                           [exe, "--model", MODEL, "--motion", MOTIONS / "amass_smplh.npz", "--out",
                            out_dir / "ok.glb", "--quiet", "--memory-limit", "64M"],
                           outputs=[out_dir / "ok.glb"], max_rss_mb=400)
harness.finish()
