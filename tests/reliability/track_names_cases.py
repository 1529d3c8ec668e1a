"""Reliability cases of the third hostile sweep ("nothing lost, round 3"): track ids
that come from a motion file never become paths.

WHAM's track ids are the keys of its results dict, and `--track all` names each
output `<stem>.track<ID>.<ext>`. The ids here are hostile: a climbing id
(`X/../../outside/victim`) with a planted folder `<stem>.trackX` in the output
folder, a planted link `<stem>.track -> outside`, `.`, `..`, control bytes, a
300-digit id, and an --out stem so long that the tracks' names cannot be made.
Each case checks that nothing outside the output folder is created or changed,
that every output is one plain, printable file name in the output folder, that
the sidecar records the id as the file has it, and that a name that cannot be
made fails before any track is written.
Run: /usr/bin/python3 track_names_cases.py SMPL_EXPORT FIXTURE_DIR WORK_DIR
"""
import collections
import hashlib
import json
import os
import pathlib
import sys

import joblib
import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from harness import args, check, expect_failure, expect_success, finish  # noqa: E402

exe, fixtures, work = args()
fixtures, work = fixtures.resolve(), work.resolve()
MODEL = fixtures / "models" / "smpl_small.npz"
FAST = ["--skin-weights", "truncated", "-q"]  # the cases test the naming, not the weight fit


def wham_results(ids, length=4):
    """WHAM demo.py's layout (results[_id] = {pose (T,72), trans (T,3), betas (T,10),
    frame_ids (T,)}; joblib.dump), keyed by the given ids."""
    results = collections.defaultdict(dict)
    rng = np.random.default_rng(7)
    for k, tid in enumerate(ids):
        results[tid]["pose"] = (0.2 * rng.standard_normal((length, 72))).astype(np.float32)
        results[tid]["trans"] = rng.standard_normal((length, 3)).astype(np.float32)
        results[tid]["betas"] = np.zeros((length, 10), np.float32)
        results[tid]["frame_ids"] = np.arange(k, k + length, dtype=np.int64)
    return results


def case_folder(name, ids):
    """(folder, motion, out dir, outside dir) with a WHAM file of `ids` in it."""
    d = work / name
    (d / "out").mkdir(parents=True)
    (d / "outside").mkdir()
    motion = d / "wham_output.pkl"
    joblib.dump(wham_results(ids), motion)
    return d, motion, d / "out", d / "outside"


def tree(folder):
    """{relative path: sha256 or 'link -> target' or 'dir'} of everything under folder."""
    out = {}
    for p in sorted(pathlib.Path(folder).rglob("*")):
        rel = str(p.relative_to(folder))
        if p.is_symlink():
            out[rel] = "link -> " + os.readlink(p)
        elif p.is_dir():
            out[rel] = "dir"
        else:
            out[rel] = hashlib.sha256(p.read_bytes()).hexdigest()
    return out


def plain_names(folder):
    """Names in `folder` that are not one printable component (none expected)."""
    bad = []
    for p in pathlib.Path(folder).iterdir():
        n = p.name
        if not n.isprintable() or n in (".", "..") or "/" in n or "\\" in n:
            bad.append(repr(n))
    return bad


def find_key(node, key):
    """The first value under `key` anywhere in a JSON tree, or None."""
    if isinstance(node, dict):
        if key in node:
            return node[key]
        node = list(node.values())
    if isinstance(node, list):
        for child in node:
            found = find_key(child, key)
            if found is not None:
                return found
    return None


def sidecar_tracks(out_dir):
    """{output file name: the sidecar's track id} for every output's sidecar."""
    tracks = {}
    for side in pathlib.Path(out_dir).glob("*.smpl.json"):
        clips = find_key(json.loads(side.read_text()), "animations") or [{}]
        tracks[side.name[:-len(".smpl.json")]] = clips[0].get("source", {}).get("track", "")
    return tracks


def climbing_id():
    """The sweep's attack: a folder `body.trackX` planted in the output folder and an id
    `X/../../outside/victim`; the old naming wrote outside/victim.glb (exit 0)."""
    victim_id = "X/../../outside/victim"
    d, motion, out, outside = case_folder("climb", [victim_id, "0"])
    (out / "body.trackX").mkdir()
    victim = outside / "victim.glb"
    victim.write_bytes(b"not yours to overwrite\n")
    before = tree(outside)
    expect_success("names.climbing_id_exports", [exe, "--model", MODEL, "--motion", motion,
                                                 "--track", "all", "--out", out / "body.glb"] + FAST,
                   outputs=[out / "body.track0.glb", out / "body.trackX%2F..%2F..%2Foutside%2Fvictim.glb"],
                   inputs=[motion])
    check("names.climbing_id_outside_untouched", tree(outside) == before,
          f"outside now {sorted(tree(outside))}")
    check("names.climbing_id_planted_folder_empty", list((out / "body.trackX").iterdir()) == [],
          f"{sorted(p.name for p in (out / 'body.trackX').iterdir())}")
    tracks = sidecar_tracks(out)
    check("names.sidecar_keeps_the_id",
          tracks.get("body.trackX%2F..%2F..%2Foutside%2Fvictim.glb") == victim_id, f"{tracks}")


def planted_track_link():
    """A link `body.track -> <outside>` and an id that starts with '/': the old naming
    wrote through the link into the outside folder."""
    d, motion, out, outside = case_folder("link", ["/victim", "1"])
    os.symlink(outside, out / "body.track")
    before = tree(outside)
    expect_success("names.planted_link_exports", [exe, "--model", MODEL, "--motion", motion,
                                                  "--track", "all", "--out", out / "body.glb"] + FAST,
                   outputs=[out / "body.track%2Fvictim.glb", out / "body.track1.glb"], inputs=[motion])
    check("names.planted_link_outside_untouched", tree(outside) == before,
          f"outside now {sorted(tree(outside))}")


def odd_ids():
    """'.', '..', control bytes and an escape sequence, a 300-digit id, an empty id and a
    '%': every output one printable name in the output folder, all distinct, .gltf
    buffers beside them."""
    ids = [".", "..", "a\nb\x1b[2J", "7" * 300, "", "50%", "Jos\u00e9"]
    d, motion, out, outside = case_folder("odd", ids)
    expect_success("names.odd_ids_export", [exe, "--model", MODEL, "--motion", motion,
                                            "--track", "all", "--out", out / "body.gltf"] + FAST,
                   outputs=[out / "body.track%2E.gltf", out / "body.track%2E%2E.gltf",
                            out / "body.tracka%0Ab%1B%5B2J.gltf", out / "body.track%.gltf",
                            out / "body.track50%25.gltf", out / "body.trackJos%C3%A9.gltf"],
                   inputs=[motion])
    gltfs = sorted(p.name for p in out.glob("*.gltf"))
    check("names.odd_ids_one_output_each", len(gltfs) == len(ids), f"{gltfs}")
    check("names.odd_ids_plain_names", plain_names(out) == [], f"{plain_names(out)}")
    longest = max((len(n.encode()) for n in os.listdir(out)), default=0)
    check("names.odd_ids_bounded", longest <= len("body.track") + 64 + len(".gltf.smpl.json"),
          f"longest name {longest} bytes")
    check("names.odd_ids_outside_empty", tree(outside) == {} and tree(d).keys() >= {"out"},
          f"{tree(outside)}")
    tracks = sidecar_tracks(out)
    check("names.odd_ids_sidecars_keep_ids", sorted(tracks.values()) == sorted(ids),
          f"{sorted(tracks.values())!r}")


def names_checked_before_writing():
    """An --out stem long enough that the tracks' sidecar names pass NAME_MAX: the run
    fails before the first track is written (the old run committed earlier tracks)."""
    d, motion, out, outside = case_folder("long", ["0", "1", "2" * 40])
    stem = "s" * 200  # 200 + ".track0.glb.smpl.json" fits NAME_MAX; ".track" + 40 digits does not
    expect_failure("names.too_long_fails_before_any_write",
                   [exe, "--model", MODEL, "--motion", motion, "--track", "all",
                    "--out", out / f"{stem}.glb"] + FAST,
                   exit_code=4, names=["File name too long"], inputs=[motion], out_dirs=[out],
                   forbidden=[out / f"{stem}.track0.glb", out / f"{stem}.track1.glb"])
    check("names.too_long_nothing_written", list(out.iterdir()) == [],
          f"{sorted(p.name for p in out.iterdir())}")


climbing_id()
planted_track_link()
odd_ids()
names_checked_before_writing()
finish()
