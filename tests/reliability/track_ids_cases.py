"""Reliability cases of the track-id sweep: every key of a multi-person motion
file becomes an exact, distinct track id or a refusal that names it.

WHAM's results are a dict keyed by track id (joblib.dump). The keys here are what
Python allows: ints beyond int64 (pickle LONG1), tuples, floats, None, bytes, numpy
int64 scalars 2^53 and 2^53 + 1 (equal as doubles) and 2^63 - 1, uint64 2^64 - 1;
and keys that name one track twice (1 and '1', b'7' and '7'). `--track all` must
write one output per key under its exact id, `--track ID` must pick an exact big
id, colliding keys must be refused naming the motion file and both keys, and
`--frames` past a short track must fail before any track is written.
Run: /usr/bin/python3 track_ids_cases.py SMPL_EXPORT FIXTURE_DIR WORK_DIR
"""
import json
import pathlib
import sys

import joblib
import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from harness import args, check, expect_failure, expect_success, finish  # noqa: E402

exe, fixtures, work = args()
fixtures, work = fixtures.resolve(), work.resolve()
MODEL = fixtures / "models" / "smpl_small.npz"
FAST = ["--skin-weights", "truncated", "-q"]  # the cases test the ids, not the weight fit


def wham(name, ids, lengths=None):
    """A WHAM results dict (pose (T,72), trans, betas, frame_ids) keyed by `ids`, in its
    own folder: (motion path, out dir)."""
    d = work / name
    (d / "out").mkdir(parents=True)
    rng = np.random.default_rng(3)
    results = {}
    for k, tid in enumerate(ids):
        n = lengths[k] if lengths else 4
        results[tid] = {"pose": (0.2 * rng.standard_normal((n, 72))).astype(np.float32),
                        "trans": rng.standard_normal((n, 3)).astype(np.float32),
                        "betas": np.zeros((n, 10), np.float32),
                        "frame_ids": np.arange(n, dtype=np.int64)}
    motion = d / "wham_output.pkl"
    joblib.dump(results, motion)
    return motion, d / "out"


def sidecar_ids(out):
    """The track ids the sidecars record, sorted."""
    ids = []
    for side in out.glob("*.smpl.json"):
        text = json.loads(side.read_text())
        found = []

        def walk(n):
            if isinstance(n, dict):
                if isinstance(n.get("source"), dict) and "track" in n["source"]:
                    found.append(n["source"]["track"])
                for v in n.values():
                    walk(v)
            elif isinstance(n, list):
                for v in n:
                    walk(v)
        walk(text)
        ids += found[:1]
    return sorted(ids)


def all_tracks(name, keys, expected_ids):
    """--track all over `keys`: exit 0, one output per key, sidecars with `expected_ids`."""
    motion, out = wham(name, keys)
    expect_success(f"ids.{name}_all_exported",
                   [exe, "--model", MODEL, "--motion", motion, "--track", "all",
                    "--out", out / "body.glb"] + FAST, inputs=[motion])
    glbs = sorted(p.name for p in out.glob("*.glb"))
    check(f"ids.{name}_one_output_per_key", len(glbs) == len(keys), f"{glbs}")
    check(f"ids.{name}_exact_ids", sidecar_ids(out) == sorted(expected_ids),
          f"{sidecar_ids(out)} expected {sorted(expected_ids)}")
    return motion, out


big = 2 ** 64 + 5  # pickled as LONG1: beyond int64 and uint64
all_tracks("big_int", [big, 0], [str(big), "0"])
all_tracks("tuple_float_none", [(1, "a"), 2.5, None, 3], ["(1, 'a')", "2.5", "None", "3"])
motion, out = all_tracks("numpy_int64", [np.int64(2 ** 53), np.int64(2 ** 53 + 1),
                                         np.int64(2 ** 63 - 1), np.uint64(2 ** 64 - 1)],
                         [str(2 ** 53), str(2 ** 53 + 1), str(2 ** 63 - 1), str(2 ** 64 - 1)])
for tid in (2 ** 53 + 1, 2 ** 63 - 1):
    pick = out / f"pick{tid}.glb"
    expect_success(f"ids.numpy_int64_pick_{tid}",
                   [exe, "--model", MODEL, "--motion", motion, "--track", str(tid), "--out", pick]
                   + FAST, outputs=[pick], inputs=[motion])
    side = pathlib.Path(str(pick) + ".smpl.json")
    got = json.loads(side.read_text()) if side.exists() else {}
    check(f"ids.numpy_int64_pick_{tid}_is_that_track", f'"track": "{tid}"' in json.dumps(got),
          f"sidecar {side.name} names track {tid}")

for name, keys, shown in (("int_and_str", [1, "1"], ["1", "'1'"]),
                          ("bytes_and_str", [b"7", "7"], ["b'7'", "'7'"])):
    motion, out = wham(name, keys)
    expect_failure(f"ids.{name}_refused",
                   [exe, "--model", MODEL, "--motion", motion, "--track", "all",
                    "--out", out / "body.glb"] + FAST,
                   exit_code=2, names=[str(motion)] + shown, inputs=[motion], out_dirs=[out])
    check(f"ids.{name}_nothing_written", list(out.iterdir()) == [],
          f"{sorted(p.name for p in out.iterdir())}")

motion, out = wham("frames_past_short_track", [0, 1], lengths=[10, 3])
expect_failure("ids.frames_past_a_track_fails_before_any_write",
               [exe, "--model", MODEL, "--motion", motion, "--track", "all", "--frames", "5:8",
                "--out", out / "body.glb"] + FAST,
               exit_code=3, names=[str(motion), "track 1"], inputs=[motion], out_dirs=[out])
check("ids.frames_past_a_track_nothing_written", list(out.iterdir()) == [],
      f"{sorted(p.name for p in out.iterdir())}")

# A failure no check can foresee (the file-size limit, as a full disk): track 0
# (2 frames) fits under `ulimit -f`, track 1 (600 frames) does not. Track 0's
# output stays complete and the error says it was written; track 1 leaves nothing.
motion, out = wham("written_before", [0, 1], lengths=[2, 600])
sizes = {}
for tid in (0, 1):
    probe = work / "written_before" / f"probe{tid}.glb"
    expect_success(f"ids.written_before_probe_{tid}",
                   [exe, "--model", MODEL, "--motion", motion, "--track", str(tid), "--out", probe]
                   + FAST, outputs=[probe], inputs=[motion])
    sizes[tid] = probe.stat().st_size if probe.exists() else 0
limit_kib = (sizes[0] + sizes[1]) // 2 // 1024
check("ids.written_before_sizes_apart", sizes[0] < limit_kib * 1024 < sizes[1], f"{sizes}")
# Python ignores SIGXFSZ and exec keeps it ignored: env restores the default a shell gives.
limited = ["/usr/bin/env", "--default-signal=XFSZ", "/bin/bash", "-c",
           f'ulimit -f {limit_kib}; exec "$0" "$@"']
first = out / "body.track0.glb"
expect_failure("ids.written_before_named",
               limited + [str(a) for a in [exe, "--model", MODEL, "--motion", motion, "--track", "all",
                                           "--out", out / "body.glb"] + FAST],
               exit_code=4, names=["body.track1.glb", "written before it, complete: body.track0.glb"],
               inputs=[motion], out_dirs=[out], forbidden=[out / "body.track1.glb"])
head = first.read_bytes()[:12] if first.exists() else b""
check("ids.written_before_kept_complete",  # a GLB's header states its whole length
      head[:4] == b"glTF" and int.from_bytes(head[8:12], "little") == first.stat().st_size
      and pathlib.Path(str(first) + ".smpl.json").exists(),
      f"{sorted(p.name for p in out.iterdir())}")
finish()
