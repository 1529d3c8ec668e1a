"""Reliability cases of folders of per-frame files and of writes cut short.

--motion-sequence DIR: an entry named like a frame (`000003.json`) that is no
readable file (a link loop, a link to a folder, a FIFO, a link to /dev/zero) or
whose number has 13 digits fails the run naming it (exit 2, nothing written);
--skip-bad-frames skips each with a note naming it. A FIFO is never opened (the
run would block: the timeout catches it). Three files numbered 0, 1 and 10^6
are an error (a gap of 999,998 held frames > --max-held-frames, default 1000),
and --max-held-frames is bounded (100,000).
Writes: `ulimit -f` (SIGXFSZ ignored, so the write fails with EFBIG) and a
closed stdout (SIGPIPE ignored, EPIPE) are write errors: exit 4, one line
naming the output, no temporary left, an existing output unchanged.
Run: /usr/bin/python3 frames_cases.py SMPL_EXPORT FIXTURE_DIR WORK_DIR
"""
import json
import os
import pathlib
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from harness import args, check, expect_failure, expect_success, finish  # noqa: E402

exe, fixtures, work = args()
fixtures, work = fixtures.resolve(), work.resolve()
MODEL = fixtures / "models" / "smpl_small.npz"
FAST = ["--skin-weights", "truncated", "--corrective-refit", "off"]


def easymocap_frame(path, value):
    """One EasyMocap frame file: a list of persons, each SMPL Rh/Th/poses/shapes."""
    person = {"id": 0, "Rh": [[0.0, 0.0, 0.0]], "Th": [[0.0, 0.0, 0.01 * (value % 100)]],
              "poses": [[0.01 * (value % 100)] * 72], "shapes": [[0.0] * 10]}
    path.write_text(json.dumps([person]), encoding="utf-8")


def sequence(name, numbers=(0, 1, 2)):
    """(case folder, frame folder, out dir) with EasyMocap frames `numbers`."""
    d = work / name
    seq, out = d / "seq", d / "out"
    seq.mkdir(parents=True)
    out.mkdir()
    for n in numbers:
        easymocap_frame(seq / f"{n:06d}.json", n)
    (seq / "notes.txt").write_text("not a frame\n")  # stays summarised as ignored
    return d, seq, out


def export(seq, out, *more):
    return [exe, "--model", MODEL, "--motion-sequence", seq, "--out", out / "body.glb", *FAST,
            *more]


def plant_loop(seq):
    os.symlink("000003.json", seq / "000003.json")  # a link to itself: ELOOP


def plant_folder_link(seq):
    (seq / "sub").mkdir()
    os.symlink("sub", seq / "000003.json")


def plant_fifo(seq):
    os.mkfifo(seq / "000003.json")


def plant_dev_zero(seq):
    os.symlink("/dev/zero", seq / "000003.json")


def plant_13_digits(seq):
    easymocap_frame(seq / "0000000000003.json", 3)


BAD = [("loop", "000003.json", plant_loop),
       ("folder_link", "000003.json", plant_folder_link),
       ("fifo", "000003.json", plant_fifo),
       ("dev_zero_link", "000003.json", plant_dev_zero),
       ("13_digits", "0000000000003.json", plant_13_digits)]

for kind, entry, plant in BAD:
    d, seq, out = sequence(f"bad_{kind}")
    plant(seq)
    expect_failure(f"frames.bad_{kind}", export(seq, out), exit_code=2,
                   names=[str(seq / entry), "--skip-bad-frames"], out_dirs=[out],
                   forbidden=[out / "body.glb", out / "body.glb.smpl.json"], timeout=60)
    code, _, err = (lambda r: (r.returncode, r.stdout, r.stderr))(
        subprocess.run([str(a) for a in export(seq, out, "--skip-bad-frames")],
                       capture_output=True, text=True, timeout=60, stdin=subprocess.DEVNULL))
    check(f"frames.skip_{kind}",
          code == 0 and f"skipped {seq / entry}: " in err and (out / "body.glb").exists()
          and "3 files joined (frames 0-2)" in err,
          f"exit {code}: {err.strip()[-400:]!r}")

# Every bad entry of one folder is named, one note each, in one run.
d, seq, out = sequence("skip_all")
os.symlink("000003.json", seq / "000003.json")
(seq / "sub").mkdir()
os.symlink("sub", seq / "000004.json")
os.mkfifo(seq / "000005.json")
os.symlink("/dev/zero", seq / "000006.json")
plant_13_digits(seq)
r = subprocess.run([str(a) for a in export(seq, out, "--skip-bad-frames")], capture_output=True,
                   text=True, timeout=60, stdin=subprocess.DEVNULL)
skipped = [line for line in r.stderr.splitlines() if ": skipped " in line]
check("frames.skip_all_named", r.returncode == 0 and len(skipped) == 5,
      f"exit {r.returncode}, {len(skipped)} skip notes: {r.stderr.strip()[-600:]!r}")

# A gap of 999,998 frames: an error naming both frames, before any is held.
d, seq, out = sequence("gap", numbers=(0, 1, 1000000))
expect_failure("frames.gap_default", export(seq, out), exit_code=2,
               names=[str(seq), "frames 1 and 1000000", "--max-held-frames"], out_dirs=[out],
               forbidden=[out / "body.glb"], max_rss_mb=300)
expect_failure("frames.gap_limit_bounded", export(seq, out, "--max-held-frames", "2000000"),
               exit_code=1, names="--max-held-frames", out_dirs=[out], forbidden=[out / "body.glb"])
expect_failure("frames.gap_over_given", export(seq, out, "--max-held-frames", "100000"),
               exit_code=2, names=[str(seq), "at most 100000"], out_dirs=[out],
               forbidden=[out / "body.glb"], max_rss_mb=300)
d, seq, out = sequence("gap_small", numbers=(0, 1, 5))
expect_failure("frames.gap_over_small", export(seq, out, "--max-held-frames", "2"),
               exit_code=2, names="frames 1 and 5", out_dirs=[out], forbidden=[out / "body.glb"])
expect_success("frames.gap_within", export(seq, out, "--max-held-frames", "3"),
               outputs=[out / "body.glb"], stderr_contains=["without a detection: 3"])

# ulimit -f: the write fails (EFBIG), not the process (SIGXFSZ).
d, seq, out = sequence("ulimit")
old = out / "body.glb"
old.write_bytes(b"previous output\n")
(out / "body.glb.smpl.json").write_text("{}\n")
# The harness forks from Python, which ignores SIGXFSZ, and an ignored signal
# stays ignored across exec: env restores the default a shell would give.
limited = ["/usr/bin/env", "--default-signal=XFSZ", "/bin/bash", "-c", 'ulimit -f 10; exec "$0" "$@"']
limited += [str(a) for a in export(seq, out)]
expect_failure("frames.ulimit_f", limited, exit_code=4, names=str(old),
               inputs=[old, out / "body.glb.smpl.json"], out_dirs=[out])
r = subprocess.run(limited, capture_output=True, text=True, timeout=120, stdin=subprocess.DEVNULL)
errors = [line for line in r.stderr.splitlines() if line.strip()]
check("frames.ulimit_f_one_line", len(errors) == 1 and errors[0].startswith("Error"),
      f"stderr: {r.stderr.strip()[-400:]!r}")

# A closed stdout (`| head -0`): the summary's write fails with EPIPE, not the process.
d, seq, out = sequence("closed_stdout")
rd, wr = os.pipe()
os.close(rd)
p = subprocess.Popen([str(a) for a in export(seq, out)], stdout=wr, stderr=subprocess.PIPE,
                     stdin=subprocess.DEVNULL, text=True)
os.close(wr)
err = p.communicate(timeout=120)[1]
check("frames.closed_stdout", p.returncode == 4 and "Error writing standard output" in err,
      f"exit {p.returncode}: {err.strip()[-300:]!r}")

finish()
