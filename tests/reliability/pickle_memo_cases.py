"""Reliability cases for memo-shared pickles:
"a 16 KB pickle that shares memo objects peaks at 3.5-4 GB before it loads".
The fixture containers/memo_shared.pkl (tests/fixtures/make_containers.py) is
16655 bytes: 400 keys share one list of 1000 references to one list of 1000
floats, 3.2 GB as doubles. Given as a model and as a motion, each run must end
with one error line naming the file and the pickle's own bound (at most 256
bytes per input byte, at least 64 MiB), exit 2, no output, and a peak RSS far
below the gigabytes the file would have grown to. A second copy padded to
1 MiB (the bound is then 256 MiB) checks that the bound follows the input.
Run: /usr/bin/python3 tests/reliability/pickle_memo_cases.py SMPL_EXPORT FIXTURE_DIR WORK_DIR
"""
import pathlib
import shutil
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import harness  # noqa: E402

exe, fixtures, work = harness.args()
MODEL = fixtures / "models" / "smpl_small.npz"
out_dir = work / "out"
out_dir.mkdir()
OUT = out_dir / "o.glb"
memo = work / "memo_shared.pkl"
shutil.copy(fixtures / "containers" / "memo_shared.pkl", memo)
bound = "exceeds the limit of 67108864 bytes for an input of 16655 bytes"
harness.expect_failure("memo-shared 16 KB pickle as --model", [exe, "--model", memo, "--out", OUT],
                       exit_code=2, names=["memo_shared.pkl", bound], inputs=[memo],
                       out_dirs=[out_dir], forbidden=[OUT], max_rss_mb=250)
harness.expect_failure("memo-shared 16 KB pickle as --motion",
                       [exe, "--model", MODEL, "--motion", memo, "--out", OUT, "--quiet"],
                       exit_code=2, names=["memo_shared.pkl", bound], inputs=[memo],
                       out_dirs=[out_dir], forbidden=[OUT], max_rss_mb=250)
# The same pickle followed by 1 MiB of ignored bytes: 256 MiB allowed, still refused.
padded = work / "memo_padded.pkl"
padded.write_bytes(memo.read_bytes() + bytes(1 << 20))
harness.expect_failure("memo-shared pickle padded to 1 MiB as --model",
                       [exe, "--model", padded, "--out", OUT], exit_code=2,
                       names=["memo_padded.pkl", "exceeds the limit of 272699136 bytes for an input of 1065231 bytes"],
                       inputs=[padded], out_dirs=[out_dir], forbidden=[OUT], max_rss_mb=500)
harness.finish()
