#!/usr/bin/python3
"""Plants plausible one-line bugs one at a time and reports the ones no test catches.

Each mutant below is a bug someone could write (or once did): an exact piece
of a source file and its replacement. For each one the script checks that the
piece occurs exactly once, applies it, rebuilds the targets, runs the tests
that guard that code (a ctest -R pattern) and restores the file, whatever
happens. A mutant is killed when the build or a test fails; survivors are
listed and the exit status is 1. Run by hand, not in CI (minutes per mutant):

    scripts/mutate.py BUILD_DIR                 # every mutant
    scripts/mutate.py BUILD_DIR --only NAME...  # some of them
    scripts/mutate.py BUILD_DIR --list

BUILD_DIR is a configured build with the tests on (SMPL_TEST_SET all, the
default), e.g. `cmake -S . -B build -DCMAKE_BUILD_TYPE=Release`. The tree must
have no uncommitted change to a mutated file (the script refuses otherwise).
Add a mutant when a bug slips past the tests: the test that catches it and the
mutant land together.
"""
import argparse
import pathlib
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent

# name, file, old text, new text, ctest -R pattern, build targets
MUTANTS = [
    ("unit_offsets_swapped", "exporter/pipeline.cpp",
     "c.offset = diagonal ? 1.0 : 0.5;", "c.offset = diagonal ? 0.5 : 1.0;",
     r"UnitEncoding\.|SplitEncoding\.|RuntimeCore\.", ["unit_tests"]),
    ("fbx_rest_deform_percent_fraction", "writers/fbx/fbx_morphs.cpp",
     "addDouble(100.0 * target.rest_weight)", "addDouble(target.rest_weight)",
     r"FbxWriter\.", ["unit_tests"]),
    ("skin_fit_prior_not_renormalised", "core/math/skin_weight_fit.cpp",
     "  prior /= prior.sum();\n", "",
     r"FitSkinWeights\.", ["unit_tests"]),
    ("guard_forgets_gltf_buffer", "request/run_paths.cpp",
     "      paths.outputs.push_back(buffer);", "      (void)buffer;",
     r"RunPaths\.|reliability\.output", ["unit_tests", "smpl-export"]),
    ("unreal_axes_without_y_flip",
     "unreal/SmplCorrectives/Source/SmplCorrectives/Public/SmplCorrectivesCore.h",
     "return {1, 0, 0, 0, 0, 1, 0, 1, 0};", "return {1, 0, 0, 0, 0, -1, 0, 1, 0};",
     r"RuntimeCore\.", ["unit_tests"]),
    ("qanim_rotation_scale", "writers/gltf/gltf_animation.cpp",
     "xyzw[i])) * 32767.0f", "xyzw[i])) * 32766.0f",
     r"GltfQuantizedAnimation\.|qanim", ["unit_tests", "smpl-export"]),
    ("qanim_weights_unsigned_scale", "writers/gltf/gltf_animation.cpp",
     "double(w[i]) * 65535.0", "double(w[i]) * 65534.0",
     r"GltfQuantizedAnimation\.|qanim", ["unit_tests", "smpl-export"]),
    ("uv_not_flipped", "writers/gltf/gltf_streams.cpp",
     "out[i] = 1.0f - out[i];", "out[i] = out[i];",
     r"GltfWriter\.|UvSource\.|Pipeline\.", ["unit_tests"]),
    ("split_diagonal_scale_sign", "exporter/pipeline.cpp",
     "parts.push_back(CorrectiveLayout{n, name, -0.5, 0.0, true});",
     "parts.push_back(CorrectiveLayout{n, name, 0.5, 0.0, true});",
     r"SplitEncoding\.|RuntimeCore\.", ["unit_tests"]),
    ("unit_base_mesh_not_shifted", "exporter/pipeline.cpp",
     "if (o.encoding == CorrectiveEncoding::Unit) shiftBaseMesh(shift, &mesh);", "",
     r"UnitEncoding\.|web\.three\..*_unit", ["unit_tests", "smpl-export"]),
    ("temp_without_o_excl", "core/os/files_posix.cpp",
     "O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC",
     "O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC",
     r"FileIo\.", ["unit_tests"]),
    ("sidecar_not_an_output", "request/run_paths.cpp",
     "    paths.outputs.push_back(out + \".smpl.json\");", "",
     r"RunPaths\.|reliability\.output", ["unit_tests", "smpl-export"]),
    ("ibm_sign", "writers/gltf/gltf_skeleton.cpp",
     "m[size_t(12 + c)] = float(-s.rest_world(k, c));", "m[size_t(12 + c)] = float(s.rest_world(k, c));",
     r"GltfWriter\.", ["unit_tests"]),
]


def run(cmd, cwd, log):
    with open(log, "a") as out:
        out.write(f"\n$ {' '.join(map(str, cmd))}\n")
        out.flush()
        return subprocess.run(cmd, cwd=cwd, stdout=out, stderr=subprocess.STDOUT).returncode


def dirty(path):
    return subprocess.run(["git", "diff", "--quiet", "--", path], cwd=ROOT).returncode != 0


def try_mutant(m, build, log):
    name, rel, old, new, tests, targets = m
    path = ROOT / rel
    text = path.read_text()
    if text.count(old) != 1:
        return "stale", f"{rel}: the text to mutate occurs {text.count(old)} times (update the list)"
    path.write_text(text.replace(old, new))
    try:
        if run(["cmake", "--build", build, "-j2", "--target", *targets], ROOT, log) != 0:
            return "killed", "build fails"
        rc = run(["ctest", "--test-dir", build, "-R", tests, "-j2", "--timeout", "900"], ROOT, log)
        return ("killed", "tests fail") if rc != 0 else ("survived", f"ctest -R '{tests}' passes")
    finally:
        path.write_text(text)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build", nargs="?", help="configured build directory with the tests on")
    ap.add_argument("--only", nargs="+", metavar="NAME")
    ap.add_argument("--list", action="store_true", help="print the mutants and exit")
    args = ap.parse_args()
    chosen = [m for m in MUTANTS if not args.only or m[0] in args.only]
    if args.list:
        for m in MUTANTS:
            print(f"{m[0]:38} {m[1]}")
        return 0
    if not args.build:
        ap.error("BUILD_DIR is required")
    if args.only and len(chosen) != len(set(args.only)):
        unknown = set(args.only) - {m[0] for m in MUTANTS}
        ap.error(f"unknown mutant(s): {', '.join(sorted(unknown))} (see --list)")
    for m in chosen:
        if dirty(m[1]):
            print(f"mutate: {m[1]} has uncommitted changes; commit or stash them first", file=sys.stderr)
            return 2
    build = pathlib.Path(args.build).resolve()
    log = build / "mutate.log"
    log.write_text("")
    survivors = 0
    for i, m in enumerate(chosen, 1):
        start = time.time()
        verdict, why = try_mutant(m, build, log)
        survivors += verdict != "killed"
        print(f"[{i}/{len(chosen)}] {verdict:8} {m[0]:38} {why} ({time.time() - start:.0f} s)",
              flush=True)
    # The last build leaves the binaries of the restored tree.
    run(["cmake", "--build", build, "-j2"], ROOT, log)
    print(f"mutate: {len(chosen) - survivors} of {len(chosen)} killed; log: {log}")
    return 1 if survivors else 0


if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    print(__doc__.strip())  # --help: the usage above, and nothing else
    sys.exit(0)

if __name__ == "__main__":
    sys.exit(main())
