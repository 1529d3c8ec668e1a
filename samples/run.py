#!/usr/bin/python3
"""Runs every smpl-export example of the README and the docs pages on small synthetic files.

The examples are read from README.md and the pages in DOC_PAGES (the pages
the README's sections moved to), not copied here: every line of an indented
code block that starts with `smpl-export ` and every inline code span
`smpl-export ...` (the "What you have -> the command" table). In every
docs/*.md page, a fenced block right after a `<!-- runnable -->` line is
runnable too: each of its lines that starts with `smpl-export ` is an
example. Lines with shell variables or "..." are templates, not examples, and
are skipped.
The README's file names (SMPL_NEUTRAL.npz, walk_poses.npz, models/, ...)
are created in a sandbox as copies of synthetic fixtures written by
tests/fixtures/make_*.py (random arrays with the real layouts; never model
files from the authors), then each command runs verbatim there with the
given smpl-export first on PATH. A command passes when it exits 0 and its
--out file (or a file in its --out-dir) exists.

    /usr/bin/python3 samples/run.py --exe build/cli/smpl-export [--fixtures build/fixtures]
        [--readme README.md] [--docs docs] [--work /tmp/smpl-samples]

--fixtures reuses fixtures the build already generated (CTest does this);
without it the fixture scripts are run into <work>/fixtures. Exit 0 when every
example passes, 1 otherwise (each failure printed with its output).
Needs numpy (Debian's /usr/bin/python3).
"""
import argparse
import glob
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCRIPTS = ["make_models.py", "make_motions.py", "make_motion_formats.py", "make_released_layouts.py",
           "make_generation_layouts.py", "make_dmpl.py", "make_video_layouts.py"]
MIN_EXAMPLES = 15  # the README and its pages have 34; fewer means the extraction broke
# The pages that hold the README's former sections: all their examples run.
DOC_PAGES = ["getting-started.md", "install.md", "inputs.md", "options.md", "skin-weights.md", "animation.md",
             "batch.md", "outputs.md", "engines.md", "web.md", "performance.md", "development.md"]
RUNNABLE = "<!-- runnable -->"

# README name -> fixture (relative to the fixture directory). Folders are copied whole.
FILES = {
    "SMPL_NEUTRAL.npz": "models/smpl_small.npz",
    "SMPL_NEUTRAL.pkl": "models/smpl_small_p2.pkl",
    "basicModel_f_lbs_10_207_0_v1.0.0.pkl": "models/smpl_small_p2.pkl",
    "SMPLH_NEUTRAL.npz": "models/smplh_small.npz",
    "SMPLX_NEUTRAL.npz": "released/smplx_release.npz",
    "M.npz": "models/smpl_small.npz",
    "fit.npz": "released/betas_rows_differ.npz",
    "walk_poses.npz": "motions/amass_smplh.npz",
    "walk.npz": "motions/smpl_72.npz",
    "x_stageii.npz": "released/amass_stageii.npz",
    "dance.smpl": "formats/codec_root.smpl",
    "000.pkl": "formats/fit_pca.pkl",
    "gBR_sBM_cAll_d04_mBR0_ch01.pkl": "formats/aist.pkl",
    "models": "released/smpl_folder",
    "subject": "released/mixed_gender",
    "CMU/01": "formats/subject",
    "amass/walk_poses.npz": "motions/amass_smplh.npz",
    "amass/smpl_72.npz": "motions/smpl_72.npz",
    "smplh/female/model.npz": "dmpl/amass/smplh/female/model.npz",
    "dmpls/female/model.npz": "dmpl/amass/dmpls/female/model.npz",
    "run_poses.npz": "dmpl/amass_smplh_dmpl.npz",
    "body_models": "dmpl/amass",
    "amass_dmpl/run_poses.npz": "dmpl/amass_smplh_dmpl.npz",
    "wham_output.pkl": "layouts/video/wham/wham_output.pkl",
    "vibe_output.pkl": "layouts/video/vibe/vibe_output.pkl",
    "demo_video.pkl": "layouts/video/phalp/demo_video.pkl",
    "hmr4d_results.pt": "layouts/video/gvhmr/hmr4d_results.pt",
    "results.pkl": "layouts/video/prompthmr/results.pkl",
    "results/seq": "layouts/video/tram/seq",
    "video_results.npz": "layouts/video/romp/video_results.npz",
    "output/smpl": "layouts/video/easymocap/smpl",
    "demo_out/smplx": "layouts/video/smplerx/smplx",
    # motion-generation, hand and camera-frame layouts (make_generation_layouts.py)
    "clip.npy": "layouts/generation/motionx/smplx322_walk.npy",
    "example_smplx_poses.npy": "layouts/generation/bare/example_smplx_poses.npy",
    "sample00_rep00_smpl_params.npy": "layouts/generation/mdm/sample00_rep00_smpl_params.npy",
    "MANO_RIGHT.pkl": "models/mano_small_p2.pkl",
    "hand.npz": "layouts/generation/hamer/left_hand.npz",
    "hamer_out": "layouts/generation/hamer/hands3",
    "SMPLX_NEUTRAL_2020.npz": "released/smplx_release.npz",
    "2_scott_0_1_1.npz": "layouts/generation/beat2/2_scott_0_1_1_output.npz",
    "smplifyx/000.pkl": "layouts/generation/fits/smplifyx_000.pkl",
}


def page_examples(path, every):
    """A page's smpl-export commands: with `every`, indented lines and inline spans; always,
    the lines of fenced blocks marked runnable."""
    found, state = [], "text"  # text -> marked (after RUNNABLE) -> fence (inside its block)
    with open(path, encoding="utf-8") as f:
        for line in f:
            fence = line.strip().startswith("```")
            if state == "fence":
                state = "text" if fence else state
                if not fence and line.strip().startswith("smpl-export "):
                    found.append(line.strip())
                continue
            if state == "marked" and fence:
                state = "fence"
                continue
            state = "marked" if line.strip() == RUNNABLE else ("marked" if state == "marked" and not line.strip()
                                                               else "text")
            if every and line.startswith("    smpl-export "):
                found.append(line.strip())
            if every:
                found += re.findall(r"`(smpl-export [^`]*)`", line)
    return found


def examples(readme, docs=None):
    """The smpl-export commands of the README and the docs pages, in order, without duplicates."""
    found = page_examples(readme, True)
    for page in sorted(glob.glob(os.path.join(docs, "*.md"))) if docs else []:
        found += page_examples(page, os.path.basename(page) in DOC_PAGES)
    seen = []
    for cmd in found:
        if "$" not in cmd and "..." not in cmd and cmd not in seen:
            seen.append(cmd)
    return seen


def make_fixtures(work):
    out = os.path.join(work, "fixtures")
    os.makedirs(out, exist_ok=True)
    for script in SCRIPTS:
        subprocess.run([sys.executable, os.path.join(ROOT, "tests", "fixtures", script), out], check=True,
                       stdout=subprocess.DEVNULL)
    return out


def missing_fixtures(fixtures):
    """FILES sources absent from `fixtures` (a script missing from SCRIPTS, or a stale folder)."""
    return sorted({source for source in FILES.values() if not os.path.exists(os.path.join(fixtures, source))})


def sandbox(fixtures, work):
    box = os.path.join(work, "sandbox")
    shutil.rmtree(box, ignore_errors=True)
    os.makedirs(box)
    for name, source in FILES.items():
        src, dst = os.path.join(fixtures, source), os.path.join(box, name)
        os.makedirs(os.path.dirname(dst), exist_ok=True)
        (shutil.copytree if os.path.isdir(src) else shutil.copyfile)(src, dst)
    # --betas-file betas.npy (3 betas) and a UV pair for M.npz (one uv per vertex, ft = the model's faces).
    np.save(os.path.join(box, "betas.npy"), np.array([0.5, -1.2, 0.3]))
    model = np.load(os.path.join(box, "M.npz"))
    rng = np.random.default_rng(7)
    np.save(os.path.join(box, "body_uv.npy"), rng.random((model["v_template"].shape[0], 2)))
    np.save(os.path.join(box, "body_ft.npy"), model["f"].astype(np.int64))
    # a.npz / b.npz: the fixture motions repeated past the README's --frames 0:600.
    for name, source in (("a.npz", "motions/amass_smplh.npz"), ("b.npz", "motions/smpl_72.npz")):
        long_motion(os.path.join(fixtures, source), os.path.join(box, name), 660)
    return box


def long_motion(src, dst, frames):
    """`src` with its per-frame arrays (first axis T, as long as poses) repeated to `frames` frames."""
    d = dict(np.load(src))
    t = d["poses"].shape[0]
    for key, value in d.items():
        if value.ndim >= 1 and value.shape[0] == t:
            d[key] = np.resize(value, (frames,) + value.shape[1:])
    np.savez(dst, **d)


def outputs_exist(args, box):
    """Whether the --out file / some file in --out-dir exists (commands without either pass on exit 0);
    with --track all, the per-track outputs <out stem>.track<ID>.<ext>."""
    if "--track" in args and args[args.index("--track") + 1] == "all" and "--out" in args:
        stem, ext = os.path.splitext(os.path.join(box, args[args.index("--out") + 1]))
        folder = os.path.dirname(stem)
        tracks = [f for f in os.listdir(folder) if f.startswith(os.path.basename(stem) + ".track") and f.endswith(ext)]
        return "" if tracks else "--out %s: no %s.track<ID>%s outputs (--track all)" % (stem + ext, stem, ext)
    for flag, check in (("--out", os.path.isfile), ("--out-dir", lambda d: os.path.isdir(d) and os.listdir(d))):
        if flag in args:
            target = os.path.join(box, args[args.index(flag) + 1])
            if not check(target):
                return flag + " " + target + " missing"
    return ""


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--exe", required=True, help="the smpl-export binary to test")
    p.add_argument("--readme", default=os.path.join(ROOT, "README.md"))
    p.add_argument("--docs", default=os.path.join(ROOT, "docs"), help="folder of the docs pages")
    p.add_argument("--fixtures", help="fixture directory the build generated (default: generate)")
    p.add_argument("--work", help="scratch directory (default: a new temporary one)")
    p.add_argument("--min-examples", type=int, default=MIN_EXAMPLES,
                   help="fewer examples found is a failure (a test of one page lowers it)")
    a = p.parse_args()
    work = a.work or tempfile.mkdtemp(prefix="smpl-samples-")
    fixtures = a.fixtures or make_fixtures(work)
    missing = missing_fixtures(fixtures)
    if missing:
        print("%s: no %s (written by which tests/fixtures/make_*.py? %s)" % (
            fixtures, ", ".join(missing), "run them with --fixtures" if a.fixtures else "add it to SCRIPTS"))
        return 1
    box = sandbox(fixtures, work)
    env = dict(os.environ, PATH=os.path.dirname(os.path.abspath(a.exe)) + os.pathsep + os.environ["PATH"])
    cmds = examples(a.readme, a.docs)
    failed = 0
    for cmd in cmds:
        args = shlex.split(cmd)
        r = subprocess.run(args, cwd=box, env=env, capture_output=True, text=True)
        problem = "exit %d" % r.returncode if r.returncode != 0 else outputs_exist(args, box)
        print(("FAIL " if problem else "ok   ") + cmd + ("  (" + problem + ")" if problem else ""))
        if problem:
            failed += 1
            print("     " + (r.stdout + r.stderr).strip().replace("\n", "\n     "))
    print("%d README and docs examples, %d failed" % (len(cmds), failed))
    if len(cmds) < a.min_examples:
        print("expected at least %d examples in %s: the extraction found too few" % (a.min_examples, a.readme))
        return 1
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
