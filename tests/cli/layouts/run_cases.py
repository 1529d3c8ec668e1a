#!/usr/bin/env python3
"""Runs the motion-layout test cases of tests/cli/layouts/<SET>_cases.py against smpl-export.

    /usr/bin/python3 tests/cli/layouts/run_cases.py --exe build/cli/smpl-export \
        --fixtures build/fixtures --web-src tests/web --cases video [--only NAME] [--work DIR] [--equivalent]

Per case: smpl-export --model FIXTURES/models/<model>.npz --motion <fixture> (a folder:
--motion-sequence) --out WORK/<name>.glb --skin-weights truncated --max-influences 4 --corrective-refit off <args>.
 - a refusal: the exit code, one line on stderr naming the problem, no output (nor temporary) left;
 - otherwise: exit 0, every `notes` substring on stderr and no `absent` one, the sidecar's
   `motion_source` when the case gives `source`, then for each output the expected vertices
   (the case module's numpy reference) as JSON and three.js playing the GLB
   (tests/web/three_node_test.mjs --anim-reference ... --tol 1e-6);
 - always: the fixture folder is unchanged (nothing written, nothing executed).
With --equivalent, each case is instead checked through today's exporter: the case module's
`equivalent()` writes the clip in our own terms (AMASS-style poses/trans/betas/fps, already
turned Y up) and that npz is exported with --up y and compared with the same reference; a case
that today's inputs cannot express is reported as such.
Prints one line per case with the worst vertex error; exits 1 when any case fails.
"""
import argparse
import glob
import importlib
import json
import os
import re
import shutil
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
TOLERANCE = 1e-6


def snapshot(folder):
    """(path, size, mtime) of every file under folder: inputs must stay as they were."""
    out = set()
    for root, _, files in os.walk(folder):
        for f in files:
            p = os.path.join(root, f)
            st = os.lstat(p)
            out.add((p, st.st_size, st.st_mtime_ns))
    return out


def node_compare(web_src, asset, reference):
    """Worst error three.js reports (baked weights and bones + driver), or an error string."""
    run = subprocess.run(["node", os.path.join(web_src, "three_node_test.mjs"), "--asset", asset,
                          "--anim-reference", reference, "--tol", str(TOLERANCE)],
                         capture_output=True, text=True)
    errors = [float(x) for x in re.findall(r"max_err_m ([0-9.eE+-]+)", run.stdout)]
    worst = max(errors) if errors else float("nan")
    if run.returncode != 0 or len(errors) < 6:
        tail = (run.stdout + run.stderr).strip().splitlines()[-12:]
        return worst, "three.js check failed (exit %d): %s" % (run.returncode, " | ".join(tail))
    return worst, None


def glb_suffix(s):
    """An output suffix as a file suffix (".track0" and ".track0.glb" are both used by the case sets)."""
    return s if s.endswith(".glb") else s + ".glb"


def outputs_of(case, work):
    """[(the case's suffix or None, output path)]."""
    suffixes = case["outputs"] or [".glb"]
    return [(None if case["outputs"] is None else s, os.path.join(work, case["name"] + glb_suffix(s)))
            for s in suffixes]


def leftovers(work, name):
    return sorted(p for p in glob.glob(os.path.join(work, "*")) if os.path.basename(p).lstrip(".").startswith(name))


def export(exe, model, motion, out, args):
    flag = "--motion-sequence" if os.path.isdir(motion) else "--motion"
    # --corrective-refit off: the reference poses the model's own posedirs (the layouts'
    # conventions are under test here; refitted deltas are checked by the round trips that
    # read the deltas from the file, tests/roundtrip/blender_roundtrip.py).
    cmd = [exe, "--model", model, flag, motion, "--out", out, "--skin-weights", "truncated",
           "--max-influences", "4", "--corrective-refit", "off"] + list(args)
    return cmd, subprocess.run(cmd, capture_output=True, text=True)


def model_path(model, fixtures):
    """A case's model: a fixture model's name ("smpl_small"), or a path under the fixtures."""
    return os.path.join(fixtures, model) if "/" in model else os.path.join(fixtures, "models", model + ".npz")


def check_refusal(case, run, work):
    want = case["refusal"]
    problems = []
    if run.returncode != want["exit"]:
        problems.append("exit %d, expected %d" % (run.returncode, want["exit"]))
    lines = run.stderr.strip("\n").split("\n") if run.stderr.strip() else []
    if len(lines) != 1:
        problems.append("stderr has %d lines, expected 1: %r" % (len(lines), run.stderr[-300:]))
    elif want["message"] not in lines[0]:
        problems.append("stderr %r lacks %r" % (lines[0], want["message"]))
    else:
        problems += ["stderr %r has %r" % (lines[0], f) for f in want.get("forbid", []) if f in lines[0]]
    left = leftovers(work, case["name"])
    if left:
        problems.append("left behind: %s" % ", ".join(os.path.basename(p) for p in left))
    return problems


def check_notes(case, run):
    """Notes are on stderr (docs/cli.md "Outputs")."""
    problems = ["stderr lacks %r" % n for n in case.get("notes", []) if n not in run.stderr]
    problems += ["stderr has %r" % n for n in case.get("absent", []) if n in run.stderr]
    if problems:
        problems.append("stderr was: %s" % " | ".join(run.stderr.strip().splitlines()))
    return problems


def motion_source(sidecar):
    """The first clip's source as {layout, track, frames: [first, last]} (docs/file-contract.md
    "Metadata": animations[i].source, end_frame exclusive), or None."""
    clips = sidecar.get("animations")
    if not isinstance(clips, list) or not clips or not isinstance(clips[0].get("source"), dict):
        return None
    s = clips[0]["source"]
    return {"layout": s.get("layout"), "track": s.get("track"),
            "frames": [s.get("first_frame"), s.get("end_frame", 0) - 1]}


def check_source(case, path, sfx):
    """The sidecar's clip source: the case's `source`, or with --track all the output's track id."""
    want = case.get("source")
    if sfx is not None:
        want = {"track": re.match(r"\.track(.+?)(\.glb)?$", sfx).group(1)}
    if not want:
        return []
    try:
        with open(path + ".smpl.json", encoding="utf-8") as fh:
            got = motion_source(json.load(fh))
    except (OSError, ValueError) as e:
        return ["sidecar: %s" % e]
    if not isinstance(got, dict):
        return ["sidecar has no animations[0].source object"]
    return ["motion_source.%s is %r, expected %r" % (k, got.get(k), v) for k, v in want.items() if got.get(k) != v]


def run_case(mod, case, a, work):
    """(worst error, [problems])."""
    for p in leftovers(work, case["name"]):
        os.remove(p) if os.path.isfile(p) else shutil.rmtree(p)
    model = model_path(case["model"], a.fixtures)
    motion = os.path.join(a.fixtures, case["fixture"])
    outs = outputs_of(case, work)
    args = [x.replace("{fixtures}", a.fixtures) for x in case["args"]]  # fixture paths in options
    cmd, run = export(a.exe, model, motion, os.path.join(work, case["name"] + ".glb"), args)
    if case["refusal"]:
        return 0.0, check_refusal(case, run, work)
    if run.returncode != 0:
        return float("nan"), ["exit %d: %s (%s)" % (run.returncode, run.stderr.strip(), " ".join(cmd))]
    problems = check_notes(case, run)
    refs = mod.expected(case, a.fixtures)
    worst = 0.0
    if case["outputs"] and os.path.exists(os.path.join(work, case["name"] + ".glb")):
        problems.append("%s.glb written besides the per-track outputs" % case["name"])
    for sfx, path in outs:
        ref = refs if sfx is None else refs[sfx]
        if not os.path.exists(path):
            problems.append("no output %s" % os.path.basename(path))
            continue
        problems += check_source(case, path, sfx)
        ref_path = path + ".expected.json"
        with open(ref_path, "w", encoding="utf-8") as fh:
            json.dump(ref, fh)
        err, problem = node_compare(a.web_src, path, ref_path)
        worst = max(worst, err) if err == err else err
        if problem:
            problems.append("%s: %s" % (os.path.basename(path), problem))
        for pattern, value in ref.get("numbers", {}).items():  # a note's number, printed with 3 decimals
            found = re.search(pattern, run.stderr)
            if not found:
                problems.append("stderr lacks a note matching %r (numpy: %.3f)" % (pattern, value))
            elif abs(float(found.group(1)) - value) > 0.0015:
                problems.append("note says %s, numpy %.3f: %r" % (found.group(1), value, pattern))
    problems += check_wrong_readings(mod, case, a, refs)
    return worst, problems


WRONG_MIN = 1e-3  # metres: a plausible wrong reading must be at least this far from the right one


def check_wrong_readings(mod, case, a, refs):
    """Each `wrong` reading of the case (video_cases.py wrong_expected) must be >= 1 mm from the right
    reference at some checked frame (the largest vertex distance): the export matches the right
    reference within 1e-6 m at every frame, so that match rules the wrong reading out."""
    problems = []
    right = refs if case["outputs"] is None else refs[sorted(refs)[0]]
    for label, change in case.get("wrong", []):
        wrong = mod.wrong_expected(case, a.fixtures, change)
        gap = max(float(np.linalg.norm(np.array(r) - np.array(w), axis=1).max())
                  for r, w in zip(right["vertices"], wrong["vertices"]))
        print("    wrong reading %-40s %.3f mm (largest over frames)" % (label + ":", 1000 * gap))
        if gap < WRONG_MIN:
            problems.append("the wrong reading '%s' is only %.3g mm away" % (label, 1000 * gap))
    return problems


def run_equivalent(mod, case, a, work):
    """Today's exporter on the clip written in our terms: (worst error, [problems]) or (None, reason)."""
    try:
        eq = mod.equivalent(case, a.fixtures)
    except TypeError:  # the generation set writes its files itself: [{suffix, motion, model, args}]
        return run_written_equivalent(mod, case, a, work)
    if isinstance(eq, str):
        return None, eq
    model = model_path(case["model"], a.fixtures)
    refs = mod.expected(case, a.fixtures)
    worst, problems = 0.0, []
    for sfx, arrays in eq:
        stem = os.path.join(work, "eq_" + case["name"] + (sfx or ".glb")[:-4])
        np.savez(stem + ".npz", **arrays)
        cmd, run = export(a.exe, model, stem + ".npz", stem + ".glb", ["--up", "y", "--quiet"])
        if run.returncode != 0:
            problems.append("exit %d: %s" % (run.returncode, run.stderr.strip()))
            continue
        ref = refs if sfx is None else refs[sfx]
        with open(stem + ".expected.json", "w", encoding="utf-8") as fh:
            json.dump(ref, fh)
        err, problem = node_compare(a.web_src, stem + ".glb", stem + ".expected.json")
        worst = max(worst, err) if err == err else err
        if problem:
            problems.append(problem)
    return worst, problems


def run_written_equivalent(mod, case, a, work):
    """--equivalent for case sets whose equivalent() writes the motions and names model and args."""
    entries = mod.equivalent(case, a.fixtures, work)
    if not entries:
        return None, "no equivalent"
    refs = mod.expected(case, a.fixtures)
    worst, problems = 0.0, []
    for e in entries:
        sfx = e["suffix"] or None
        model = model_path(e["model"], a.fixtures)
        out = e["motion"][:-4] + ".glb"
        cmd, run = export(a.exe, model, e["motion"], out, e["args"] + ["--quiet"])
        if run.returncode != 0:
            problems.append("exit %d: %s" % (run.returncode, run.stderr.strip()))
            continue
        ref = refs if sfx is None else refs[sfx]
        with open(out + ".expected.json", "w", encoding="utf-8") as fh:
            json.dump(ref, fh)
        err, problem = node_compare(a.web_src, out, out + ".expected.json")
        worst = max(worst, err) if err == err else err
        if problem:
            problems.append(problem)
    return worst, problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", required=True)
    ap.add_argument("--fixtures", required=True)
    ap.add_argument("--web-src", required=True, help="tests/web (three_node_test.mjs)")
    ap.add_argument("--cases", required=True, help="SET: tests/cli/layouts/SET_cases.py")
    ap.add_argument("--only", help="run only the case of this name")
    ap.add_argument("--work", help="folder for outputs (default: a folder under /tmp, kept)")
    ap.add_argument("--equivalent", action="store_true",
                    help="check the numpy reference through today's exporter (AMASS-style equivalents)")
    a = ap.parse_args()
    sys.path.insert(0, HERE)
    mod = importlib.import_module(a.cases + "_cases")
    work = a.work or os.path.join("/tmp", "layout_cases_" + a.cases)
    os.makedirs(work, exist_ok=True)
    cases = [c for c in mod.CASES if a.only in (None, c["name"])]
    if not cases:
        sys.exit("no case named %r in %s_cases.py" % (a.only, a.cases))
    failed = checked = 0
    for case in cases:
        before = snapshot(a.fixtures)
        if a.equivalent:
            if case["refusal"]:
                continue
            worst, problems = run_equivalent(mod, case, a, work)
            if worst is None:
                print("%-24s SKIP  not expressible today: %s" % (case["name"], problems))
                continue
        else:
            worst, problems = run_case(mod, case, a, work)
        if snapshot(a.fixtures) != before:
            problems.append("the fixture folder changed during the run")
        if not case["refusal"] and not worst <= TOLERANCE:
            problems.append("worst vertex error %s m > %g m" % (worst, TOLERANCE))
        checked += 1
        status = "FAIL" if problems else "ok"
        detail = "refused as expected" if case["refusal"] and not problems else "worst %.3e m" % worst
        print("%-24s %-4s  %s" % (case["name"], status, detail))
        for p in problems:
            print("    " + p)
        failed += bool(problems)
    skipped = len(cases) - checked
    print("%d of %d cases failed" % (failed, checked) if failed else "all %d cases passed" % checked,
          "(%d not run: refusals in --equivalent mode, or not expressible today)" % skipped if skipped else "")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
