"""Reliability cases of the second hostile sweep ("nothing lost, round 2"), the
core/io and writing parts:
  - temporaries: a symbolic link planted under the old predictable temporary
    name (".NAME.smpl.tmp-PID") or at the output's own name is never followed
    (its target outside the folder stays byte-identical, the output is a
    regular file); temporary names are unpredictable; legal output names of
    229-245 bytes are written (their sidecar fits NAME_MAX), longer ones get
    one error line that keeps the reason;
  - two processes exporting different betas to the same --out, 200 races per
    format: the output, its .bin and its sidecar always come from one run;
  - batch "up to date" checks the output's bytes: an output truncated to 100
    bytes, or a .gltf missing its .bin, is rebuilt;
  - a model file that shrinks while it is mapped (npz members read in place,
    pickles parsed from the mapping) ends with one error line naming it,
    never SIGBUS;
  - files that are not what they claim (3 GB sparse files as --uv, --betas-file,
    --dmpl, --motion; --model /dev/stdin) are refused at once with megabytes of
    memory;
  - UV and DMPL values beyond float32 are load errors naming the input and key;
  - a motion file name that is not UTF-8 is escaped into the outputs;
  - numbers: 0x10, +4, " 4", 1e1 (integers) refused by every numeric option;
  - `> /dev/full`: exit 4 with one line on stderr.
Run: /usr/bin/python3 safety_cases.py SMPL_EXPORT FIXTURE_DIR WORK_DIR
"""
import hashlib
import json
import os
import pathlib
import re
import shutil
import signal
import struct
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from harness import args, check, expect_failure, expect_success, finish, run_measured  # noqa: E402

exe, fixtures, work = args()
fixtures, work = fixtures.resolve(), work.resolve()  # links below point at absolute paths
MODEL = fixtures / "models" / "smpl_small.npz"
MOTIONS = fixtures / "motions"
DMPL = fixtures / "dmpl"
ONLY = os.environ.get("SMPL_RELIABILITY_ONLY", "")  # run only the groups whose name contains this
FAST = ["--skin-weights", "truncated", "-q"]  # the cases test the writing, not the weight fit


def fresh(name):
    d = work / name
    d.mkdir(parents=True)
    return d


def sha(path):
    return hashlib.sha256(pathlib.Path(path).read_bytes()).hexdigest()


def leftovers(folder):
    return sorted(p.name for p in pathlib.Path(folder).iterdir() if ".tmp" in p.name)


def last_line(err):
    lines = [l for l in err.splitlines() if l.strip()]
    return lines[-1] if lines else ""


# -- temporaries: planted links, unpredictable names, long names ---------------------------------

def spawn_paused(argv):
    """Forks a child that waits for a byte on a pipe before exec'ing argv, so that
    the parent knows the child's pid (the old temporary name) before it runs."""
    r, w = os.pipe()
    pid = os.fork()
    if pid == 0:
        os.close(w)
        os.read(r, 1)
        devnull = os.open(os.devnull, os.O_RDWR)
        os.dup2(devnull, 0)
        os.dup2(devnull, 1)
        os.execv(str(argv[0]), [str(a) for a in argv])
    os.close(r)
    return pid, w


def planted_links():
    """The reported attack: in a shared, group-writable output folder, links under
    the names the old code would open (.NAME.smpl.tmp-PID, for output and sidecar)
    and at the output's own name, all pointing at a file outside the folder."""
    shared, outside = fresh("planted/shared"), fresh("planted/outside")
    os.chmod(shared, 0o2775)
    target = outside / "precious.txt"
    target.write_text("not yours to overwrite\n")
    before = sha(target)
    out = shared / "o.glb"
    pid, go = spawn_paused([exe, "--model", MODEL, "--out", out] + FAST)
    links = [shared / f".o.glb.smpl.tmp-{pid}", shared / f".o.glb.smpl.json.smpl.tmp-{pid}",
             shared / f".o.glb.smpl.tmp-{pid}-old", out]
    for link in links:
        os.symlink(target, link)
    os.write(go, b"x")
    os.close(go)
    _, status = os.waitpid(pid, 0)
    code = os.waitstatus_to_exitcode(status)
    check("temp.planted_links_export_succeeds", code == 0, f"exit {code}")
    check("temp.planted_links_target_untouched", sha(target) == before,
          f"target now {target.read_text()[:60]!r}")
    regular = out.is_file() and not out.is_symlink() and \
        pathlib.Path(f"{out}.smpl.json").is_file() and not pathlib.Path(f"{out}.smpl.json").is_symlink()
    check("temp.output_is_a_regular_file_not_the_link", regular,
          f"{out}: {'symlink' if out.is_symlink() else 'file'}")
    still = [l.name for l in links[:3] if l.is_symlink() and os.readlink(l) == str(target)]
    check("temp.planted_temp_links_left_alone", len(still) == 3, f"links left: {still}")
    check("temp.glb_is_ours", out.read_bytes()[:4] == b"glTF", "output does not start with glTF")


def long_names():
    d = fresh("names")
    for n in (229, 237, 245):  # the sweep's failing range; 245 + ".smpl.json" = 255 bytes
        out = d / ("n" * (n - 4) + ".glb")
        expect_success(f"names.legal_{n}_bytes", [exe, "--model", MODEL, "--out", out] + FAST,
                       outputs=[out, f"{out}.smpl.json"])
    out = d / ("m" * 242 + ".glb")  # 246 bytes: its sidecar's name would be 256
    expect_failure("names.sidecar_name_too_long", [exe, "--model", MODEL, "--out", out] + FAST,
                   exit_code=4, names=[f"{out}.smpl.json", "File name too long"], out_dirs=[d],
                   forbidden=[out])
    # A path far over 4 KiB: the line keeps its reason, the path loses its middle.
    deep = d / ("x" * 300) / ("y" * 5000) / "z.glb"
    code, _, err, _, _ = run_measured([exe, "--model", MODEL, "--out", deep] + FAST)
    line = last_line(err)
    check("names.long_path_error_keeps_reason",
          code == 4 and line.startswith("Error saving") and line.endswith("File name too long")
          and len(line.encode()) <= 4096 and "..." in line,
          f"exit {code}, {len(line)} bytes: {line[:80]!r}...{line[-60:]!r}")


def temp_names_unpredictable():
    """Polls for the temporary of a long write (a 1000 fps FBX bake) twice: named
    after the output, 8 hex of tag and 16 random hex, no pid, never the same."""
    d = fresh("tempnames")
    motion = d / "long.npz"
    t = np.arange(300) / 30.0
    poses = np.zeros((t.size, 72))
    poses[:, 3:] = 0.3 * np.sin(t[:, None] * np.linspace(0.5, 3, 69)[None, :])
    np.savez(motion, poses=poses, fps=np.array(30.0))
    pattern = re.compile(r"^\.big\.fbx\.smpl\.tmp-[0-9a-f]{8}-[0-9a-f]{16}$")
    names = []
    for attempt in range(6):
        proc = subprocess.Popen([str(exe), "--model", "builtin", "--motion", str(motion), "--fps", "1000",
                                 "--out", str(d / "big.fbx"), "-q"], stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL)
        seen = []
        while proc.poll() is None and not seen:
            seen = [n for n in os.listdir(d) if n.startswith(".big.fbx.smpl.tmp-")]
            time.sleep(0.001)
        proc.wait()
        if seen:
            names.append((seen[0], proc.pid))
        if len(names) == 2:
            break
    ok = len(names) == 2 and all(pattern.match(n) and str(p) not in n for n, p in names) and \
        names[0][0] != names[1][0] and names[0][0][:-16] == names[1][0][:-16]
    check("temp.names_unpredictable", ok, f"seen: {names}")


# -- two processes, one output ----------------------------------------------------------------

def glb_metadata(path):
    data = pathlib.Path(path).read_bytes()
    length = struct.unpack_from("<I", data, 12)[0]
    return json.loads(data[20:20 + length])["asset"]["extras"]["smpl"]


def races():
    d = fresh("race")
    for ext, count in (("glb", 200), ("gltf", 100)):
        out = d / f"r.{ext}"
        side = pathlib.Path(f"{out}.smpl.json")
        mixed, failed = [], []
        for race in range(count):
            a, b = f"{0.01 * (race % 50) + 0.5:.2f}", f"{-0.01 * (race % 50) - 0.5:.2f}"
            procs = [subprocess.Popen([str(exe), "--model", str(MODEL), "--betas", betas, "--out", str(out)]
                                      + FAST, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
                     for betas in (a, b)]
            for p in procs:
                _, err = p.communicate()
                if p.returncode != 0:
                    failed.append(err.decode(errors="replace").strip()[-200:])
            sidecar = json.loads(side.read_text())
            files = {r["file"]: r for r in sidecar["producer"]["outputs"]}
            meta = glb_metadata(out) if ext == "glb" else json.loads(out.read_text())["asset"]["extras"]["smpl"]
            same = meta["betas"] == sidecar["betas"] and files[out.name]["sha256"] == sha(out)
            if ext == "gltf":
                same = same and files["r.bin"]["sha256"] == sha(d / "r.bin") and \
                    json.loads(out.read_text())["buffers"][0]["byteLength"] == os.path.getsize(d / "r.bin")
            if not same:
                mixed.append(race)
        check(f"race.{ext}_{count}_races_one_consistent_set", not mixed and not failed,
              f"{len(mixed)} mixed {mixed[:5]}, {len(failed)} failed {failed[:1]}")
        check(f"race.{ext}_no_temporaries_left", not leftovers(d), f"left: {leftovers(d)}")


# -- batch up to date checks the outputs themselves --------------------------------------------

def batch_truncated():
    mdir, odir = fresh("uptodate/motions"), fresh("uptodate/out")
    shutil.copy(MOTIONS / "smpl_72.npz", mdir / "walk.npz")
    for fmt in ("glb", "gltf"):
        argv = [exe, "--model", MODEL, "--motion-dir", mdir, "--out-dir", odir, "--format", fmt] + FAST[:2]
        out = odir / f"walk.{fmt}"
        expect_success(f"uptodate.{fmt}_first", argv, outputs=[out],
                       stderr_contains=["batch: 1 converted, 0 up to date"])
        expect_success(f"uptodate.{fmt}_unchanged_skips", argv, stderr_contains=["batch: 0 converted, 1 up to date"])
        whole = sha(out)
        os.truncate(out, 100)  # the sweep's case
        expect_success(f"uptodate.{fmt}_truncated_output_rebuilt", argv,
                       stderr_contains=["batch: 1 converted, 0 up to date"])
        check(f"uptodate.{fmt}_rebuilt_whole", sha(out) == whole, f"{os.path.getsize(out)} bytes")
        # Same size, one byte changed: only the recorded hash tells (the size check alone would skip it).
        for edited in [out] + ([odir / "walk.bin"] if fmt == "gltf" else []):
            data = bytearray(edited.read_bytes())
            data[len(data) // 2] ^= 0xFF
            edited.write_bytes(bytes(data))
            expect_success(f"uptodate.{fmt}_edited_{edited.suffix[1:]}_same_size_rebuilt", argv,
                           stderr_contains=["batch: 1 converted, 0 up to date"])
            check(f"uptodate.{fmt}_edited_{edited.suffix[1:]}_rebuilt_whole", sha(out) == whole,
                  f"{os.path.getsize(out)} bytes")
        if fmt == "gltf":
            (odir / "walk.bin").unlink()
            expect_success("uptodate.gltf_missing_bin_rebuilt", argv, outputs=[odir / "walk.bin"],
                           stderr_contains=["batch: 1 converted, 0 up to date"])


# -- a mapped model that shrinks ------------------------------------------------------------------

def big_model(copies):
    """smpl_small tiled `copies` times (a valid model with 288 * copies vertices):
    its posedirs is 200 MB at 140 copies, read from the mapping."""
    m = dict(np.load(MODEL))
    n = m["v_template"].shape[0]
    big = {"v_template": np.tile(m["v_template"], (copies, 1)),
           "shapedirs": np.tile(m["shapedirs"], (copies, 1, 1)),
           "posedirs": np.tile(m["posedirs"], (copies, 1, 1)),
           "J_regressor": np.tile(m["J_regressor"], (1, copies)) / copies,
           "weights": np.tile(m["weights"], (copies, 1)),
           "kintree_table": m["kintree_table"],
           "f": np.concatenate([m["f"] + i * n for i in range(copies)]).astype(np.uint32)}
    return big


def shrinking_model():
    d = fresh("shrink")
    model = big_model(140)
    pristine_npz, pristine_pkl = d / "pristine.npz", d / "pristine.pkl"
    np.savez(pristine_npz, **model)  # stored members: read in place from the mapping
    import pickle
    with open(pristine_pkl, "wb") as f:
        pickle.dump(model, f, protocol=4)  # parsed from the mapping
    out = d / "o.glb"
    for kind, pristine in (("npz", pristine_npz), ("pkl", pristine_pkl)):
        target = d / f"model.{kind}"
        # The load finishes, then --max-influences 1000 is refused (exit 1): the
        # time of a whole load, and "the file was read in full".
        argv = [exe, "--model", target, "--out", out, "--max-influences", "1000"]
        shutil.copyfile(pristine, target)
        start = time.monotonic()
        code, _, err, _, _ = run_measured(argv)
        load = time.monotonic() - start
        check(f"shrink.{kind}_baseline_loads", code == 1 and "--max-influences" in err, f"exit {code}: {err[-120:]}")
        # Truncate after 0, 10, 20, ... ms until two runs were caught mid-read (the
        # read is a fraction of the run: process start, then the mapping is read,
        # then the checks), at most up to the whole run's time.
        outcomes, signals, hits = [], [], 0
        for attempt in range(int(load / 0.01) + 1):
            shutil.copyfile(pristine, target)
            proc = subprocess.Popen([str(a) for a in argv], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
            time.sleep(0.01 * attempt)
            os.truncate(target, 4096)  # another process rewrites the file in place
            _, err = proc.communicate()
            line = last_line(err.decode(errors="replace"))
            outcomes.append((proc.returncode, line[:100]))
            if proc.returncode < 0:
                signals.append((proc.returncode, line))
            elif proc.returncode == 2 and "shrank while it was being read" in line and str(target) in line:
                hits += 1
            elif not ((proc.returncode == 1 and "--max-influences" in line) or
                      (proc.returncode == 2 and line.startswith("Error") and str(target) in line)):
                signals.append((proc.returncode, line))  # anything else is wrong too
            if hits >= 2:
                break
        check(f"shrink.{kind}_never_a_signal", not signals, f"bad outcomes: {signals[:2]}")
        check(f"shrink.{kind}_shrinking_reported_with_the_file", hits >= 1,
              f"load {load:.2f} s, {hits} hits in {len(outcomes)}: {outcomes[:4]}")
    check("shrink.no_output", not out.exists() and not leftovers(d), f"left: {leftovers(d)}")
    for big in d.iterdir():  # 450 MB of models: not kept in the build tree
        big.unlink()


# -- files that are not what they claim ----------------------------------------------------------

def sparse(path, size, head=b""):
    with open(path, "wb") as f:
        f.write(head)
        f.truncate(size)
    return path


def not_what_they_claim():
    d = fresh("claims")
    out = d / "o.glb"
    g3 = 3 << 30
    common = dict(out_dirs=[d], forbidden=[out], max_rss_mb=100, timeout=60)
    cases = [
        ("uv_obj", ["--uv", sparse(d / "uv.obj", g3)], "not a UV file"),
        ("uv_npy", ["--uv", sparse(d / "big_uv.npy", g3, b"\x93NUMPY\x01\x00")], "too large for a UV file"),
        ("betas_npy", ["--betas-file", sparse(d / "betas.npy", g3)], "not a betas file"),
        ("betas_npy_header", ["--betas-file", sparse(d / "hb.npy", g3, b"\x93NUMPY\x01\x00")],
         "too large for a betas file"),
        ("betas_npz", ["--betas-file", sparse(d / "betas.npz", g3)], "not a betas file"),
        ("betas_json", ["--betas-file", sparse(d / "betas.json", g3, b'{"betas": [')], "too large for a betas file"),
        ("dmpl", ["--dmpl", sparse(d / "dmpl.npz", g3)], "not a DMPL basis"),
        ("motion_zeros", ["--motion", sparse(d / "walk.json", g3)], "not a motion file"),
        ("motion_pickle", ["--motion", sparse(d / "walk.pkl", g3, b"\x80\x04")], "too large for a motion file"),
        ("motion_json", ["--motion", sparse(d / "run.json", g3, b'{"poses": [')], "too large for a motion file"),
    ]
    np.save(d / "big_ft.npy", np.zeros((1, 3)))  # the pair's partner, so big_uv.npy is read
    for name, extra, what in cases:
        path = str(extra[1])
        before = os.stat(path)  # size and time: hashing 3 GB twice per case would cost minutes
        expect_failure(f"claims.sparse_3GB_{name}", [exe, "--model", MODEL, "--out", out] + extra + FAST,
                       exit_code=2, names=[path, what], **common)
        after = os.stat(path)
        check(f"claims.sparse_3GB_{name}_unchanged",
              (after.st_size, after.st_mtime_ns) == (before.st_size, before.st_mtime_ns), path)
    expect_failure("claims.sparse_3GB_model", [exe, "--model", sparse(d / "m.npz", g3), "--out", out] + FAST,
                   exit_code=2, names=[str(d / "m.npz"), "not a model file"], **common)
    # --model /dev/stdin with a pipe on stdin: not a model (both model readers map the file).
    proc = subprocess.run(["/bin/sh", "-c", f'head -c 1000000 /dev/zero | "$0" --model /dev/stdin --out "$1" -q',
                           str(exe), str(out)], capture_output=True, timeout=60)
    line = last_line(proc.stderr.decode(errors="replace"))
    check("claims.model_dev_stdin_pipe", proc.returncode == 2 and "/dev/stdin" in line and "a pipe" in line
          and not out.exists(), f"exit {proc.returncode}: {line}")


# -- values checked where they enter --------------------------------------------------------------

def values_at_entry():
    d = fresh("values")
    out = d / "o.glb"
    n = np.load(MODEL)["v_template"].shape[0]
    faces = np.load(MODEL)["f"]
    uv = d / "huge_uv.npy"
    coords = np.full((n, 2), 0.5)
    coords[7, 1] = 1e39  # finite as a double, Inf as the float32 the file stores
    np.save(uv, coords)
    np.save(d / "huge_ft.npy", faces.astype(np.int64) % n)
    expect_failure("values.uv_npy_beyond_float32", [exe, "--model", MODEL, "--uv", uv, "--out", out] + FAST,
                   exit_code=2, names=["huge_uv.npy", "UV coordinates element 15 is 1e+39"], inputs=[uv],
                   out_dirs=[d], forbidden=[out])
    obj = d / "huge.obj"
    obj.write_text("vt 0.5 0.5\nvt 1e39 0\n" + "".join(f"f {a+1}/1 {b+1}/2 {c+1}/1\n" for a, b, c in faces))
    expect_failure("values.uv_obj_beyond_float32", [exe, "--model", MODEL, "--uv", obj, "--out", out] + FAST,
                   exit_code=2, names=[f"{obj}:2", "'vt' element 0 is 1e+39"], inputs=[obj], out_dirs=[d],
                   forbidden=[out])
    model = fixtures / "models" / "smplh_small.npz"
    eigvec = np.load(DMPL / "dmpl_smplh_small.npz")["eigvec"].copy()
    eigvec[5, 1, 2] = 1e39
    basis = d / "huge_dmpl.npz"
    np.savez(basis, eigvec=eigvec)
    motion = DMPL / "amass_smplh_dmpl.npz"
    expect_failure("values.dmpl_basis_beyond_float32",
                   [exe, "--model", model, "--motion", motion, "--dmpl", basis, "--out", out] + FAST,
                   exit_code=2, names=[str(basis), "'eigvec' element", "1e+39"], inputs=[basis], out_dirs=[d],
                   forbidden=[out])
    m = dict(np.load(motion))
    m["dmpls"] = m["dmpls"].copy()
    m["dmpls"][4, 3] = -1e39
    huge_motion = d / "huge_dmpls.npz"
    np.savez(huge_motion, **m)
    expect_failure("values.dmpl_coefficients_beyond_float32",
                   [exe, "--model", model, "--motion", huge_motion, "--dmpl", DMPL / "dmpl_smplh_small.npz",
                    "--out", out] + FAST,
                   exit_code=2, names=[str(huge_motion), "'dmpls' frame 4 column 3 is -1e+39"],
                   inputs=[huge_motion], out_dirs=[d], forbidden=[out])


# -- file-name bytes into outputs ----------------------------------------------------------------

def file_name_bytes():
    d = fresh("bytes")
    raw = os.fsencode(str(d)) + b"/walk\xff\xfe.npz"
    shutil.copy(MOTIONS / "smpl_72.npz", raw)
    cafe = d / "caf\u00e9.npz"
    shutil.copy(MOTIONS / "smpl_72.npz", cafe)
    for ext in ("glb", "gltf", "fbx"):
        out = d / f"o.{ext}"
        argv = [str(exe), "--model", str(MODEL), "--motion", raw, "--motion", str(cafe), "--out", str(out)] + FAST
        proc = subprocess.run(argv, capture_output=True, timeout=120)
        ok = proc.returncode == 0 and out.exists()
        detail = f"exit {proc.returncode}: {proc.stderr.decode(errors='replace').strip()[-200:]}"
        if ok and ext != "fbx":
            doc = glb_metadata(out) if ext == "glb" else None
            text = json.loads(out.read_text()) if ext == "gltf" else None
            if ext == "glb":
                data = out.read_bytes()
                length = struct.unpack_from("<I", data, 12)[0]
                text = json.loads(data[20:20 + length].decode("utf-8"))  # strict UTF-8
            names = [a["name"] for a in text["animations"]]
            ok = names == ["walk\\xff\\xfe", "caf\u00e9"]
            detail = f"animations {names}"
        elif ok:
            data = out.read_bytes()
            ok = b"walk\\xff\\xfe" in data and b"walk\xff" not in data and "caf\u00e9".encode() in data
            detail = "escaped name in the FBX" if ok else "FBX lacks the escaped name"
        check(f"bytes.non_utf8_motion_name_{ext}", ok, detail)
        side = json.loads(pathlib.Path(f"{out}.smpl.json").read_bytes().decode("utf-8")) if ok else {}
        check(f"bytes.sidecar_is_utf8_{ext}", ok and "producer" in side, "")


# -- numbers ------------------------------------------------------------------------------------

def numbers():
    d = fresh("numbers")
    out = d / "o.glb"
    for option, value in (("--max-influences", "0x10"), ("--threads", "0x10"), ("--shape-keys", "1e1"),
                          ("--max-influences", "+4"), ("--max-influences", " 4"), ("--corrective-epsilon", "0x1p-10"),
                          ("--memory-limit", "0x10G"), ("--memory-limit", "+1G"), ("--betas", "0x1")):
        expect_failure(f"numbers.{option}_{value.strip() or 'blank'}",
                       [exe, "--model", "builtin", "--out", out, option, value], exit_code=1,
                       names=[option], out_dirs=[d], forbidden=[out])
    expect_success("numbers.decimal_forms_accepted",
                   [exe, "--model", MODEL, "--out", out, "--betas", "0.5, -1.2e-1,.5", "--memory-limit", "1.5G",
                    "--max-influences", "8"] + FAST, outputs=[out])


# -- stdout write errors --------------------------------------------------------------------------

def dev_full():
    d = fresh("full")
    out = d / "o.glb"
    with open("/dev/full", "w") as full:
        proc = subprocess.run([str(exe), "--model", str(MODEL), "--out", str(out), "--skin-weights", "truncated"],
                              stdout=full, stderr=subprocess.PIPE, timeout=120)
    lines = [l for l in proc.stderr.decode(errors="replace").splitlines() if l.strip()]
    check("stdout.dev_full_exit_4_one_line",
          proc.returncode == 4 and len(lines) == 1 and lines[0].startswith("Error writing standard output")
          and "No space left on device" in lines[0], f"exit {proc.returncode}: {lines}")
    with open("/dev/full", "w") as full:
        proc = subprocess.run([str(exe), "--model", str(MODEL), "--out", str(out)] + FAST,
                              stdout=full, stderr=subprocess.PIPE, timeout=120)
    check("stdout.dev_full_quiet_is_fine", proc.returncode == 0, f"exit {proc.returncode}")
    with open("/dev/full", "w") as full:
        proc = subprocess.run([str(exe), "--help"], stdout=full, stderr=subprocess.PIPE, timeout=60)
    check("stdout.dev_full_help", proc.returncode == 4, f"exit {proc.returncode}")


GROUPS = [("planted", planted_links), ("names", long_names), ("tempnames", temp_names_unpredictable),
          ("race", races), ("uptodate", batch_truncated), ("shrink", shrinking_model),
          ("claims", not_what_they_claim), ("values", values_at_entry), ("bytes", file_name_bytes),
          ("numbers", numbers), ("stdout", dev_full)]
for name, group in GROUPS:
    if not ONLY or ONLY in name:
        group()
finish()
