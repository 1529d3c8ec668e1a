"""Reliability cases for outputs and batch mode : inputs are never overwritten (same path, symbolic link, hard link;
model, motion, betas, UV file, DMPL basis, sidecar, the batch manifest), directories
and devices are refused as outputs and as the manifest, a manifest inside the motion
folder is refused, NaN/Inf never reach a file, batch name collisions and
a missing motion folder are refused before work, a symbolic-link loop in the
motion folder is reported per file, a SIGKILLed run leaves only dot-prefixed
temporaries that the next run removes, output and sidecar are committed
together, and batch "up to date" means same inputs and same options.
Run: /usr/bin/python3 output_cases.py SMPL_EXPORT FIXTURE_DIR WORK_DIR
"""
import json
import os
import pathlib
import re
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from harness import args, check, expect_failure, expect_success, finish, run_measured, _sha  # noqa: E402

import numpy as np  # noqa: E402  (Debian's /usr/bin/python3)

exe, fixtures, work = args()
models, motions = fixtures / "models", fixtures / "motions"


def fresh(name):
    d = work / name
    d.mkdir(parents=True)
    return d


def temps(folder):
    return sorted(p.name for p in pathlib.Path(folder).iterdir() if ".smpl.tmp-" in p.name or ".tmp" in p.name)


# -- kind 3: an output (or its sidecar) that is an input is refused, exit 1 --

def inputs_protected():
    d = fresh("protect")
    # A model whose name is the buffer of the .gltf asked for: D/body.bin is
    # what --out D/body.gltf writes beside it, so writing would destroy the model.
    bin_model = d / "body.bin"
    shutil.copy(models / "smpl_small.npz", bin_model)
    expect_failure("kinds.gltf_buffer_is_the_model",
                   [exe, "--model", bin_model, "--out", d / "body.gltf"], exit_code=1,
                   names=[str(bin_model), "would overwrite the input"], inputs=[bin_model],
                   out_dirs=[d], forbidden=[d / "body.gltf", d / "body.gltf.smpl.json"])
    model = d / "model.npz"
    shutil.copy(models / "smpl_small.npz", model)
    glb_model = d / "m.glb"  # the loaders recognise files by content, not by name
    shutil.copy(models / "smpl_small.npz", glb_model)
    expect_failure("protect.model_same_path", [exe, "--model", glb_model, "--out", glb_model],
                   exit_code=1, names=[str(glb_model)], inputs=[glb_model], out_dirs=[d])
    link = d / "link.glb"
    os.symlink(model, link)
    expect_failure("protect.model_via_output_symlink", [exe, "--model", model, "--out", link],
                   exit_code=1, names=[str(link), str(model)], inputs=[model], out_dirs=[d])
    hard = d / "hard.glb"
    os.link(model, hard)
    expect_failure("protect.model_via_hard_link", [exe, "--model", model, "--out", hard],
                   exit_code=1, names=[str(hard), str(model)], inputs=[model], out_dirs=[d])
    real = d / "real.glb"
    shutil.copy(models / "smpl_small.npz", real)
    model_link = d / "model_link.npz"
    os.symlink(real, model_link)
    expect_failure("protect.model_via_input_symlink", [exe, "--model", model_link, "--out", real],
                   exit_code=1, names=[str(real), str(model_link)], inputs=[real], out_dirs=[d])
    motion = d / "walk.fbx"
    shutil.copy(motions / "smpl_72.npz", motion)
    expect_failure("protect.motion", [exe, "--model", "builtin", "--motion", motion, "--out", motion],
                   exit_code=1, names=[str(motion)], inputs=[motion], out_dirs=[d])
    betas = d / "betas.npy"
    np.save(betas, np.linspace(-1, 1, 10))
    betas_hard = d / "betas_out.glb"
    os.link(betas, betas_hard)
    expect_failure("protect.betas_hard_link", [exe, "--model", model, "--betas-file", betas, "--out", betas_hard],
                   exit_code=1, names=[str(betas_hard), str(betas)], inputs=[betas], out_dirs=[d])
    side_betas = d / "x.glb.smpl.json"
    side_betas.write_text(json.dumps({"betas": [0.5, -0.5]}))
    expect_failure("protect.betas_is_sidecar",
                   [exe, "--model", model, "--betas-file", side_betas, "--out", d / "x.glb"],
                   exit_code=1, names=[str(side_betas)], inputs=[side_betas], out_dirs=[d],
                   forbidden=[d / "x.glb"])
    uv = d / "uv.obj"
    uv.write_text("v 0 0 0\nvt 0 0\nf 1/1 1/1 1/1\n")
    uv_link = d / "uv_out.fbx"
    os.symlink(uv, uv_link)
    expect_failure("protect.uv_symlink", [exe, "--model", model, "--uv", uv, "--out", uv_link],
                   exit_code=1, names=[str(uv_link), str(uv)], inputs=[uv], out_dirs=[d])
    # batch: a planned output that is (a symbolic link to) the model; nothing converted
    mdir, odir = fresh("protect_batch/motions"), fresh("protect_batch/out")
    for f in ("smpl_72.npz", "plain.json"):
        shutil.copy(motions / f, mdir / f)
    os.symlink(model, odir / "smpl_72.glb")
    expect_failure("protect.batch_output", [exe, "--model", model, "--motion-dir", mdir, "--out-dir", odir],
                   exit_code=1, names=[str(odir / "smpl_72.glb"), str(model)], inputs=[model, mdir],
                   out_dirs=[odir], forbidden=[odir / "plain.glb"])
    # the DMPL basis is an input too (loaders recognise it by content, not by name)
    dmpl_dir = fixtures / "dmpl" / "amass"
    basis = d / "d.glb"
    shutil.copy(dmpl_dir / "dmpls" / "female" / "model.npz", basis)
    expect_failure("protect.dmpl_basis", [exe, "--model", dmpl_dir / "smplh" / "female" / "model.npz",
                                          "--dmpl", basis, "--out", basis],
                   exit_code=1, names=[str(basis)], inputs=[basis], out_dirs=[d],
                   forbidden=[f"{basis}.smpl.json"])


# -- directories, devices and the batch manifest as outputs --

def output_kinds():
    d = fresh("kinds")
    folder = d / "folder.glb"
    folder.mkdir()
    expect_failure("kinds.out_is_a_folder", [exe, "--model", "builtin", "--out", folder],
                   exit_code=1, names=[str(folder), "is a directory"], inputs=[folder], out_dirs=[d],
                   forbidden=[f"{folder}.smpl.json"])
    for device in ("/dev/full", "/dev/null"):  # no format extension: refused as such
        expect_failure(f"kinds.out_is_{device[5:]}", [exe, "--model", "builtin", "--out", device],
                       exit_code=1, names=[device], out_dirs=[d])
        link = d / f"{device[5:]}.glb"  # a device under an output's name
        os.symlink(device, link)
        expect_failure(f"kinds.out_links_to_{device[5:]}", [exe, "--model", "builtin", "--out", link],
                       exit_code=1, names=[str(link), "character device"], out_dirs=[d],
                       forbidden=[f"{link}.smpl.json"])
    gltf_side = d / "b.bin"  # the buffer of b.gltf
    gltf_side.mkdir()
    expect_failure("kinds.gltf_buffer_is_a_folder", [exe, "--model", "builtin", "--out", d / "b.gltf"],
                   exit_code=1, names=[str(gltf_side), "is a directory"], out_dirs=[d],
                   forbidden=[d / "b.gltf", d / "b.gltf.smpl.json"])
    model = d / "model.npz"
    shutil.copy(models / "smpl_small.npz", model)
    mdir, odir = fresh("kinds/motions"), work / "kinds" / "out"
    for f in ("smpl_72.npz", "plain.json"):
        shutil.copy(motions / f, mdir / f)
    batch = [exe, "--model", model, "--motion-dir", mdir, "--out-dir", odir, "-q", "--manifest"]
    outputs = [odir / "smpl_72.glb", odir / "plain.glb"]
    expect_failure("manifest.is_the_model", batch + [model], exit_code=1, names=[str(model)],
                   inputs=[model, mdir], out_dirs=[d], forbidden=outputs)
    expect_failure("manifest.is_a_motion", batch + [mdir / "plain.json"], exit_code=1,
                   names=[str(mdir / "plain.json"), "would overwrite the input"], inputs=[model, mdir],
                   out_dirs=[d], forbidden=outputs)
    expect_failure("manifest.is_an_output", batch + [odir / "plain.glb"], exit_code=1,
                   names=[str(odir / "plain.glb"), "(--manifest) are the same file"], inputs=[model, mdir],
                   out_dirs=[d], forbidden=outputs)
    # /dev/full through a link: were the guard broken, the atomic write would
    # replace the link, not the device node (the tests may run as root)
    full = d / "full.jsonl"
    os.symlink("/dev/full", full)
    expect_failure("manifest.is_dev_full", batch + [full], exit_code=1,
                   names=[str(full), "character device"], inputs=[model, mdir], out_dirs=[d],
                   forbidden=outputs)
    check("manifest.dev_full_untouched", os.path.islink(full) and pathlib.Path("/dev/full").is_char_device())
    expect_failure("manifest.in_the_motion_folder", batch + [mdir / "run.jsonl"], exit_code=1,
                   names=[str(mdir / "run.jsonl"), str(mdir), "--motion-dir"], inputs=[model, mdir],
                   out_dirs=[d], forbidden=outputs + [mdir / "run.jsonl"])
    expect_success("manifest.elsewhere_is_written", batch + [d / "run.jsonl"],
                   outputs=outputs + [d / "run.jsonl"], inputs=[model, mdir])


# -- kind 4: NaN / Inf / float overflow never reach a file --

def refused_without_output(name, argv, out, folder, accepted):
    """A run that must fail with no output, sidecar or temporary; `accepted`
    lists (exit code, substrings of the last stderr line) that are correct."""
    code, _, err, rss, _ = run_measured(argv)
    last = (err.strip().splitlines() or [""])[-1]
    ok = any(code == c and all(n in last for n in names) for c, names in accepted)
    clean = not os.path.lexists(out) and not os.path.lexists(f"{out}.smpl.json") and not temps(folder)
    check(name, ok and clean and last.startswith("Error"),
          f"exit {code}, peak {rss:.0f} MB, {'clean' if clean else 'files left'}: {last[:200]}")


def non_finite():
    d = fresh("finite")
    huge = d / "huge_trans.npz"
    poses = np.zeros((8, 72))
    trans = np.zeros((8, 3))
    trans[3] = [1e39, 0, 0]  # finite as a double, beyond float32: an Inf key in the file
    np.savez(huge, poses=poses, trans=trans, fps=np.array(30.0))
    # The input validators may reject the input first (exit
    # 1 or 2, naming it); otherwise the final asset check must (exit 3, naming
    # the output and the value). Either way: no file.
    for ext in ("glb", "fbx"):
        out = d / f"huge.{ext}"
        refused_without_output(f"finite.huge_translation_{ext}",
                               [exe, "--model", "builtin", "--motion", huge, "--out", out], out, d,
                               [(3, [str(out), "root translation", "float32"]), (2, [str(huge)])])
    out = d / "betas.glb"
    refused_without_output("finite.huge_betas", [exe, "--model", "builtin", "--betas", "1e300", "--out", out],
                           out, d, [(3, [str(out), "float32"]), (1, ["--betas"]), (2, ["betas"])])


# -- kind 6: batch name collisions and a missing motion folder --

def batch_refusals():
    mdir, odir = fresh("collide/motions"), fresh("collide/out")
    shutil.copy(motions / "smpl_72.npz", mdir / "walk.npz")
    shutil.copy(motions / "plain.json", mdir / "walk.json")
    shutil.copy(motions / "smpl_72.npz", mdir / "run.npz")
    for threads in ("1", "2"):
        expect_failure(f"batch.name_collision_threads{threads}",
                       [exe, "--model", "builtin", "--motion-dir", mdir, "--out-dir", odir, "--threads", threads],
                       exit_code=1, names=[str(mdir / "walk.npz"), str(mdir / "walk.json"), str(odir / "walk.glb")],
                       inputs=[mdir], out_dirs=[odir], forbidden=[odir / "walk.glb", odir / "run.glb"])
    missing = work / "no_such_motions"
    expect_failure("batch.missing_motion_dir",
                   [exe, "--model", "builtin", "--motion-dir", missing, "--out-dir", work / "missing_out"],
                   exit_code=2, names=[str(missing)], forbidden=[work / "missing_out"])
    expect_failure("batch.force_needs_batch_mode", [exe, "--model", "builtin", "--out", odir / "x.glb", "--force"],
                   exit_code=1, names=["--force"], forbidden=[odir / "x.glb"])
    not_dir = work / "collide" / "file_not_dir"
    not_dir.write_text("x")
    expect_failure("batch.motion_dir_is_a_file",
                   [exe, "--model", "builtin", "--motion-dir", not_dir, "--out-dir", odir],
                   exit_code=2, names=[str(not_dir)], out_dirs=[odir])


# -- kind 2: a symbolic-link loop or unreadable entry is reported per file --

def symlink_loop():
    mdir, odir = fresh("loop/motions"), fresh("loop/out")
    shutil.copy(motions / "smpl_72.npz", mdir / "good.npz")
    shutil.copy(motions / "plain.json", mdir / "also_good.json")
    os.symlink("loop.npz", mdir / "loop.npz")            # points at itself
    os.symlink("b.json", mdir / "a.json")                # a <-> b
    os.symlink("a.json", mdir / "b.json")
    os.symlink("nowhere.npz", mdir / "dangling.npz")
    os.symlink(".", mdir / "sub")                        # a folder loop: never entered
    (mdir / "folder.npz").mkdir()
    code, out, err, rss, secs = run_measured([exe, "--model", "builtin", "--motion-dir", mdir, "--out-dir", odir])
    errors = [l for l in err.splitlines() if l.startswith("Error")]
    converted = sorted(p.name for p in odir.iterdir())
    want = ["also_good.glb", "also_good.glb.smpl.json", "good.glb", "good.glb.smpl.json"]
    problems = []
    if code != 3:
        problems.append(f"exit {code}, expected 3")
    if converted != want:
        problems.append(f"outputs {converted}")
    for name in ("loop.npz", "a.json", "b.json", "dangling.npz"):
        if not any(str(mdir / name) in l for l in errors):
            problems.append(f"no error line for {name}")
    if len(errors) != 4:
        problems.append(f"{len(errors)} error lines: {errors}")
    if "folder.npz: not a regular file" not in err:  # a note: on stderr
        problems.append("folder.npz not reported")
    if "batch: 2 converted, 0 up to date, 4 failed" not in out:
        problems.append(f"summary: {out.strip().splitlines()[-1:]}")
    check("batch.symlink_loop", not problems, "; ".join(problems) or f"exit {code}, {secs:.1f} s")


# -- kind 7: a SIGKILLed run leaves at most dot-temporaries; the next run removes them --

def killed_run():
    d = fresh("kill")
    long_motion = d / "long.npz"
    t = np.arange(450) / 30.0  # 15 s at 1000 fps: a 35 MB FBX, about 2 s, 250 MB
    poses = np.zeros((t.size, 72))
    poses[:, 3:] = 0.3 * np.sin(t[:, None] * np.linspace(0.5, 3, 69)[None, :])
    np.savez(long_motion, poses=poses, fps=np.array(30.0))
    out = d / "big.fbx"
    for attempt in range(3):  # the write lasts tens of ms; poll for its temporary, then SIGKILL
        proc = subprocess.Popen([str(exe), "--model", "builtin", "--motion", str(long_motion), "--fps", "1000",
                                 "--out", str(out), "-q"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        seen = []
        deadline = time.monotonic() + 120
        while proc.poll() is None and time.monotonic() < deadline:
            seen = [n for n in os.listdir(d) if n.startswith(".big.fbx.smpl.tmp-")]
            if seen:
                break
            time.sleep(0.001)
        caught = proc.poll() is None and bool(seen)
        proc.send_signal(signal.SIGKILL)
        _, status, usage = os.wait4(proc.pid, 0)  # the kernel's own peak-memory accounting
        proc.returncode = os.waitstatus_to_exitcode(status)
        if caught:
            break
        for name in os.listdir(d):  # finished before the poll saw it: try again
            if name != "long.npz":
                os.unlink(d / name)
    left = sorted(n for n in os.listdir(d) if n != "long.npz")
    peak = usage.ru_maxrss / 1024.0
    check("kill.caught_mid_write", caught and peak < 600,
          f"temporary seen: {seen}, exit {proc.returncode}, peak {peak:.0f} MB")
    check("kill.only_dot_temporaries_left",
          all(n.startswith(".") and ".smpl.tmp-" in n for n in left) and left,
          f"left: {left}")
    # ".<output>.smpl.tmp-<8 hex tag>-<16 hex random>" (core/io/file_io.h): named
    # after the output, unpredictable (no pid: a link planted under a guessed
    # name is never followed, safety_cases.py).
    ours = re.compile(r"^\.big\.fbx(\.smpl\.json)?\.smpl\.tmp-[0-9a-f]{8}-[0-9a-f]{16}(-old)?$")
    check("kill.temporary_named_after_output_unpredictably",
          all(ours.match(n) and str(proc.pid) not in n for n in left), f"left: {left}")
    # Another output's temporary (same pattern) and a live writer's temporary
    # of this output (its flock held by another process) are not touched.
    other = d / ("." + left[0][1:].replace("big.fbx", "other.fbx", 1))
    other.write_text("x")
    live = d / (left[0][:-16] + "0123456789abcdef")
    live.write_text("x")
    holder = subprocess.Popen([sys.executable, "-c", "import fcntl, sys, time; f = open(sys.argv[1]); "
                               "fcntl.flock(f, fcntl.LOCK_EX); print('locked', flush=True); time.sleep(120)",
                               str(live)], stdout=subprocess.PIPE)
    holder.stdout.readline()
    expect_success("kill.next_run_succeeds", [exe, "--model", "builtin", "--out", out, "-q"], outputs=[out])
    holder.kill()
    holder.wait()
    left = sorted(n for n in os.listdir(d) if n != "long.npz")
    check("kill.next_run_removed_stale_temporaries",
          left == sorted([other.name, live.name, "big.fbx", "big.fbx.smpl.json"]), f"left: {left}")
    # Batch: stale temporaries of planned outputs (even up-to-date ones) go:
    # a forced rebuild killed mid-write leaves them, the next run removes them.
    mdir, odir = fresh("kill_batch/motions"), fresh("kill_batch/out")
    shutil.copy(long_motion, mdir / "a.npz")
    argv = [exe, "--model", "builtin", "--motion-dir", mdir, "--out-dir", odir, "--fps", "1000", "-q"]
    expect_success("kill.batch_first_run", argv, outputs=[odir / "a.glb"], timeout=600)
    stale = []
    for attempt in range(3):
        proc = subprocess.Popen([str(a) for a in argv + ["--force"]], stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL)
        deadline = time.monotonic() + 120
        while proc.poll() is None and time.monotonic() < deadline and not stale:
            stale = [odir / n for n in os.listdir(odir) if n.startswith(".a.glb.smpl.tmp-")]
            time.sleep(0.001)
        proc.send_signal(signal.SIGKILL)
        proc.wait()
        if stale:
            break
    check("kill.batch_killed_mid_write", bool(stale), f"left: {sorted(os.listdir(odir))}")
    expect_success("kill.batch_rerun", argv, stderr_contains=["batch: 0 converted, 1 up to date, 0 failed"])
    check("kill.batch_removed_stale_temporaries", not any(os.path.lexists(s) for s in stale) and
          not [n for n in os.listdir(odir) if ".smpl.tmp-" in n], f"left: {sorted(os.listdir(odir))}")


# -- kind 9: output and sidecar are committed together --

def pair_commit():
    d = fresh("pair")
    out = d / "a.glb"
    side = pathlib.Path(f"{out}.smpl.json")
    expect_success("pair.first_export", [exe, "--model", "builtin", "--out", out, "-q"], outputs=[out, side])
    old_out = _sha(out)
    side.unlink()
    side.mkdir()
    (side / "keep").write_text("x")  # a folder where the sidecar goes: refused before any work
    # (a rename that fails after that check, and the pair's rollback, are the
    # unit tests FileIo.* of writeFilesTogether)
    expect_failure("pair.sidecar_is_a_folder_keeps_old_output",
                   [exe, "--model", "builtin", "--max-influences", "2", "--out", out, "-q"],
                   exit_code=1, names=[str(side), "is a directory"], inputs=[out], out_dirs=[d])
    check("pair.old_output_unchanged", os.path.isfile(out) and _sha(out) == old_out)
    out2 = d / "b.glb"
    side2 = pathlib.Path(f"{out2}.smpl.json")
    expect_success("pair.second_export", [exe, "--model", "builtin", "--out", out2, "-q"], outputs=[out2, side2])
    out2.unlink()
    out2.mkdir()
    (out2 / "keep").write_text("x")  # a folder where the output goes: the old sidecar must stay
    expect_failure("pair.output_is_a_folder_keeps_old_sidecar",
                   [exe, "--model", "builtin", "--max-influences", "2", "--out", out2, "-q"],
                   exit_code=1, names=[str(out2), "is a directory"], inputs=[side2], out_dirs=[d])


# -- kind 10: batch up to date = same inputs and same options --

def up_to_date():
    mdir, odir = fresh("fresh/motions"), fresh("fresh/out")
    for f in ("smpl_72.npz", "plain.json"):
        shutil.copy(motions / f, mdir / f)
    base = [exe, "--motion-dir", mdir, "--out-dir", odir]
    side = odir / "smpl_72.glb.smpl.json"

    def run(name, extra, summary, model="builtin"):
        expect_success(name, base + ["--model", model] + extra, stderr_contains=[summary],
                       outputs=[odir / "smpl_72.glb", side])

    def influences():
        return json.loads(side.read_text())["max_influences"]

    run("uptodate.first", [], "batch: 2 converted, 0 up to date, 0 failed")
    run("uptodate.unchanged_skips", [], "batch: 0 converted, 2 up to date, 0 failed")
    run("uptodate.threads_do_not_matter", ["--threads", "1"], "batch: 0 converted, 2 up to date, 0 failed")
    run("uptodate.builtin_option_change_rebuilds", ["--max-influences", "2"],
        "batch: 2 converted, 0 up to date, 0 failed")
    check("uptodate.rebuilt_with_new_option", influences() == 2, f"max_influences {influences()}")
    run("uptodate.same_new_options_skip", ["--max-influences", "2"], "batch: 0 converted, 2 up to date, 0 failed")
    run("uptodate.force_rebuilds", ["--max-influences", "2", "--force"],
        "batch: 2 converted, 0 up to date, 0 failed")
    run("uptodate.betas_change_rebuilds", ["--max-influences", "2", "--betas", "0.5"],
        "batch: 2 converted, 0 up to date, 0 failed")
    model = work / "fresh" / "model.npz"
    shutil.copy(models / "smpl_small.npz", model)
    run("uptodate.other_model_rebuilds", [], "batch: 2 converted, 0 up to date, 0 failed", model=model)
    run("uptodate.same_model_skips", [], "batch: 0 converted, 2 up to date, 0 failed", model=model)
    # Another model's bytes under the same name, with an old time: still rebuilt.
    shutil.copy(models / "smplh_small.npz", model)
    os.utime(model, (1e9, 1e9))
    run("uptodate.model_content_change_rebuilds", [], "batch: 2 converted, 0 up to date, 0 failed", model=model)
    # Output folder = motion folder: our sidecars (*.smpl.json) are not motions.
    same = fresh("fresh/same")
    shutil.copy(motions / "smpl_72.npz", same / "smpl_72.npz")
    same_argv = [exe, "--model", "builtin", "--motion-dir", same, "--out-dir", same]
    expect_success("uptodate.out_dir_is_motion_dir", same_argv, outputs=[same / "smpl_72.glb"],
                   stderr_contains=["batch: 1 converted, 0 up to date, 0 failed"])
    expect_success("uptodate.out_dir_is_motion_dir_rerun", same_argv,
                   stderr_contains=["batch: 0 converted, 1 up to date, 0 failed"])
    # A damaged sidecar (no producer record) is rebuilt.
    side.write_text("{}")
    run("uptodate.damaged_sidecar_rebuilds", [], "batch: 1 converted, 1 up to date, 0 failed", model=model)


inputs_protected()
output_kinds()
non_finite()
batch_refusals()
symlink_loop()
killed_run()
pair_commit()
up_to_date()
finish()
