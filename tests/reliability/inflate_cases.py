"""Reliability cases of compressed streams that inflate far past what they hold:
a compressed joblib file whose zlib stream goes on with 2 GiB of zeros after the
pickle's STOP (joblib.load reads the pickle and never looks further), one whose
2 GiB of zeros are an array the pickle needs, and a torch .pt whose deflated
storage record inflates to 2 GiB. Each input is ~2 MB; none may cost more than
a fraction of a GiB: nothing past what the parser needs is inflated, and the
input-scaled bound (256 x the file's size, at least 64 MiB) ends the rest with
one line naming the input.
The zero runs are written as one precomputed deflate block repeated after full
flushes (each block starts from an empty window, so the copies decode alike):
zlib writes the same bytes, only ~100 x faster to build.
Run: /usr/bin/python3 inflate_cases.py SMPL_EXPORT FIXTURE_DIR WORK_DIR
"""
import collections
import io
import pathlib
import sys
import zipfile
import zlib

import joblib
import numpy as np
import torch

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from harness import args, expect_failure, expect_success, finish  # noqa: E402

exe, fixtures, work = args()
MODEL = fixtures.resolve() / "models" / "smpl_small.npz"
OUT = work / "out" / "x.glb"
OUT.parent.mkdir()
CHUNK = 16 << 20  # joblib writes an array's bytes in 16 MiB chunks (NumpyArrayWrapper.write_array)
ZERO = bytes(CHUNK)
_raw = zlib.compressobj(9, zlib.DEFLATED, -15)
ZERO_BLOCK = _raw.compress(ZERO) + _raw.flush(zlib.Z_FULL_FLUSH)


class ZlibWriter:
    """A file joblib.dump writes into: one zlib stream (RFC 1950) as joblib's
    compress=('zlib', 9) writes (joblib/compressor.py BinaryZlibFile), with each
    16 MiB run of zeros emitted as ZERO_BLOCK."""

    def __init__(self, path):
        self.f = open(path, "wb")
        self.c = zlib.compressobj(9, zlib.DEFLATED, -15)
        self.adler, self.pos = 1, 0
        self.f.write(b"\x78\xda")  # deflate, 32 KiB window, level 9

    def write(self, data):
        data = bytes(data)
        self.adler = zlib.adler32(data, self.adler)
        self.pos += len(data)
        whole = len(data) // CHUNK * CHUNK
        if whole and data[:whole] == bytes(whole):
            self.f.write(self.c.flush(zlib.Z_FULL_FLUSH) + ZERO_BLOCK * (whole // CHUNK))
            data = data[whole:]
        self.f.write(self.c.compress(data))
        return len(data)

    def tell(self):
        return self.pos

    def close(self):
        self.f.write(self.c.flush() + self.adler.to_bytes(4, "big"))
        self.f.close()


def wham(pose):
    """WHAM demo.py's results layout (results[_id] = {pose, trans, betas, frame_ids})."""
    r = collections.defaultdict(dict)
    r[0]["pose"] = pose
    r[0]["trans"] = np.zeros((len(pose), 3), np.float32)
    r[0]["betas"] = np.zeros((len(pose), 10), np.float32)
    r[0]["frame_ids"] = np.arange(len(pose))
    return r


def joblib_file(path, value, trailing_zero_chunks=0):
    w = ZlibWriter(path)
    joblib.dump(value, w)
    for _ in range(trailing_zero_chunks):
        w.write(ZERO)
    w.close()
    return path


# ---- joblib: 2 GiB of zeros after STOP --------------------------------------
rng = np.random.default_rng(3)
after = joblib_file(work / "after_stop.pkl", wham((0.2 * rng.standard_normal((4, 72))).astype(np.float32)),
                    trailing_zero_chunks=128)
expect_success("joblib with 2 GiB of zeros after the pickle's STOP",
               [exe, "--model", MODEL, "--motion", after, "--out", OUT, "--quiet"],
               outputs=[OUT], inputs=[after], max_rss_mb=700)  # 522 MB measured; copying growth: 778
OUT.unlink(missing_ok=True)

# ---- joblib: a 2 GiB array the pickle needs -----------------------------------
def write_zeros(self, array, pickler):
    """joblib's NumpyArrayWrapper.write_array (joblib/numpy_pickle.py: one
    padding-length byte, 0xff padding to the alignment, then the C-order bytes)
    for an all-zero array, written in 16 MiB chunks without materialising it."""
    align = self.safe_get_numpy_array_alignment_bytes()
    if align is not None:
        pad = align - ((pickler.file_handle.tell() + 1) % align)
        pickler.file_handle.write(bytes([pad]) + b"\xff" * pad)
    for _ in range(array.nbytes // CHUNK):
        pickler.file_handle.write(ZERO)
    pickler.file_handle.write(bytes(array.nbytes % CHUNK))


real_write = joblib.numpy_pickle.NumpyArrayWrapper.write_array
joblib.numpy_pickle.NumpyArrayWrapper.write_array = write_zeros
try:
    inside = joblib_file(work / "inside.pkl", wham(np.broadcast_to(np.float32(0), ((1 << 29) // 72, 72))))
finally:
    joblib.numpy_pickle.NumpyArrayWrapper.write_array = real_write
# The bound here is ~616 MiB; the output buffer doubles in place (realloc:
# pages moved, not copied), so the peak is the bound plus the program (628 MB
# measured); a growth that copies held 512 MiB and 616 MiB at once (1141 MB).
expect_failure("joblib whose 2 GiB array is inside the pickle",
               [exe, "--model", MODEL, "--motion", inside, "--out", OUT, "--quiet"],
               exit_code=2, names=["inside.pkl", "compressed stream inflates past", "input-scaled bound"],
               inputs=[inside], out_dirs=[OUT.parent], forbidden=[OUT], max_rss_mb=800)


# ---- torch: a deflated storage record of 2 GiB --------------------------------
class ZeroCompressor:
    """zipfile's deflate compressor for a member of zero chunks (ZERO_BLOCK each)."""

    def __init__(self):
        self.c = zlib.compressobj(9, zlib.DEFLATED, -15)

    def compress(self, data):
        return ZERO_BLOCK if bytes(data) == ZERO else self.c.compress(data)

    def flush(self):
        return self.c.flush()


def torch_bomb(path, numel):
    """torch.save({'x': zeros(4)}) with its storage record replaced by 2 GiB of
    deflated zeros and the storage's numel in data.pkl set to `numel`."""
    buf = io.BytesIO()
    torch.save({"x": torch.zeros(4)}, buf)
    src = zipfile.ZipFile(buf)
    real = zipfile._get_compressor
    with zipfile.ZipFile(path, "w") as dst:
        for info in src.infolist():
            data = src.read(info.filename)
            if info.filename.endswith("/data.pkl"):
                assert b"cpuq\x06K\x04" in data  # the storage's numel (protocol 2: no frames)
                data = data.replace(b"cpuq\x06K\x04", b"cpuq\x06J" + numel.to_bytes(4, "little"))
            if not info.filename.endswith("/data/0"):
                dst.writestr(info.filename, data)
                continue
            zipfile._get_compressor = lambda *a, **k: ZeroCompressor()
            try:
                zi = zipfile.ZipInfo(info.filename)
                zi.compress_type = zipfile.ZIP_DEFLATED
                with dst.open(zi, "w", force_zip64=True) as m:
                    for _ in range(128):
                        m.write(ZERO)
            finally:
                zipfile._get_compressor = real
    return path


for name, numel, phrase in [("small", 4, "its storage needs 16"),
                            ("large", 1 << 29, "compressed storages inflate past")]:
    pt = torch_bomb(work / f"{name}.pt", numel)
    expect_failure(f"torch .pt with a 2 GiB deflated storage ({name} numel declared)",
                   [exe, "--model", MODEL, "--motion", pt, "--out", OUT, "--quiet"],
                   exit_code=2, names=[f"{name}.pt", phrase], inputs=[pt], out_dirs=[OUT.parent],
                   forbidden=[OUT], max_rss_mb=1024)

finish()
