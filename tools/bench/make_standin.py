#!/usr/bin/python3
"""Full-size SMPL stand-in for smpl-bench's load and whole-process rows.

Writes OUTDIR/:
  standin_smpl_py2.pkl   Python 2 chumpy pickle, protocol 2, as the released
                         SMPL .pkl files are written: SHORT_BINSTRING keys,
                         array payloads as py2 str (BINSTRING, read as latin-1
                         bytes), v_template and shapedirs as chumpy.ch.Ch,
                         J_regressor as scipy.sparse.csc_matrix
  standin_smpl_stored.npz    the same arrays, np.savez (stored members)
  standin_smpl_deflated.npz  the same arrays, np.savez_compressed
6890 vertices, 24 joints, 207 pose features, 10 betas; random values (not a
body: timing only). Usage: make_standin.py OUTDIR
"""
import os
import struct
import sys

import numpy as np
import scipy.sparse as sp

N, BETAS = 6890, 10
PARENTS = [-1, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 9, 9, 12, 13, 14, 16, 17, 18, 19, 20, 21]


def model():
    rng = np.random.default_rng(13)
    k = len(PARENTS)
    joints = np.zeros((k, 3))
    joints[0] = [0.0, 0.9, 0.0]
    for j in range(1, k):
        step = rng.normal(size=3)
        joints[j] = joints[PARENTS[j]] + 0.15 * step / np.linalg.norm(step)
    v_template = joints[np.arange(N) % k] + 0.05 * rng.normal(size=(N, 3))
    dist = np.linalg.norm(v_template[:, None, :] - joints[None, :, :], axis=2)
    weights = np.exp(-((dist / 0.1) ** 2)) + 1e-9
    weights /= weights.sum(axis=1, keepdims=True)
    regressor = np.zeros((k, N))
    for j in range(k):
        near = np.argsort(dist[:, j])[:10]
        regressor[j, near] = 0.1
    faces = np.stack([np.arange(N - 2), np.arange(1, N - 1), np.arange(2, N)], 1).astype(np.uint32)
    return dict(
        v_template=v_template, weights=weights, f=faces,
        posedirs=0.005 * rng.normal(size=(N, 3, 9 * (k - 1))),
        shapedirs=0.01 * rng.normal(size=(N, 3, BETAS)),
        J_regressor=sp.csc_matrix(regressor),
        kintree_table=np.array([[2**32 - 1] + PARENTS[1:], list(range(k))], dtype=np.int64),
        J=joints, bs_style="lbs", bs_type="lrotmin")


class Py2Writer:
    """The opcodes Python 2's cPickle writes at protocol 2 (tests/fixtures/make_pickle_cases.py)."""

    def __init__(self):
        self.out = bytearray(b"\x80\x02")
        self.memo = 0
        self.globals = {}

    def put(self):
        self.out += b"q" + bytes([self.memo]) if self.memo < 256 else b"r" + struct.pack("<I", self.memo)
        self.memo += 1

    def global_(self, module, name):
        if (module, name) in self.globals:
            i = self.globals[(module, name)]
            self.out += b"h" + bytes([i]) if i < 256 else b"j" + struct.pack("<I", i)
            return
        self.out += b"c" + module.encode() + b"\n" + name.encode() + b"\n"
        self.globals[(module, name)] = self.memo
        self.put()

    def string(self, b):
        b = b if isinstance(b, bytes) else b.encode("latin-1")
        self.out += (b"U" + bytes([len(b)]) if len(b) < 256 else b"T" + struct.pack("<i", len(b))) + b
        self.put()

    def int_(self, v):
        self.out += b"K" + bytes([v]) if 0 <= v < 256 else b"J" + struct.pack("<i", v)

    def tuple_(self, emitters):
        self.out += b"("
        for e in emitters:
            e()
        self.out += b"t"
        self.put()

    def ndarray(self, a):
        self.global_("numpy.core.multiarray", "_reconstruct")
        self.global_("numpy", "ndarray")
        self.out += b"K\x00\x85"
        self.put()
        self.string("b")
        self.out += b"\x87R"
        self.put()
        fortran = a.flags.f_contiguous and not a.flags.c_contiguous
        raw = a.tobytes(order="F" if fortran else "C")

        def dtype():
            self.global_("numpy", "dtype")
            self.string(a.dtype.str[1:])
            self.out += b"K\x00K\x01\x87R"
            self.put()
            self.tuple_([lambda: self.int_(3), lambda: self.string(a.dtype.str[0]), lambda: self.out.extend(b"NNN"),
                         lambda: self.int_(-1), lambda: self.int_(-1), lambda: self.int_(0)])
            self.out += b"b"
        self.tuple_([lambda: self.int_(1), lambda: self.tuple_([(lambda n: lambda: self.int_(n))(n) for n in a.shape]),
                     dtype, lambda: self.out.extend(b"\x88" if fortran else b"\x89"), lambda: self.string(raw)])
        self.out += b"b"

    def dict_(self, items):
        self.out += b"}"
        self.put()
        self.out += b"("
        for key, emit in items:
            self.string(key)
            emit()
        self.out += b"u"

    def ch(self, x):
        self.global_("chumpy.ch", "Ch")
        self.out += b")\x81"
        self.put()
        self.dict_([("x", lambda: self.ndarray(x))])
        self.out += b"b"

    def csc(self, m):
        self.global_("copy_reg", "_reconstructor")
        self.tuple_([lambda: self.global_("scipy.sparse.csc", "csc_matrix"),
                     lambda: self.global_("__builtin__", "object"), lambda: self.out.extend(b"N")])
        self.out += b"R"
        self.put()
        self.dict_([("_shape", lambda: self.tuple_([lambda: self.int_(m.shape[0]), lambda: self.int_(m.shape[1])])),
                    ("indices", lambda: self.ndarray(m.indices)), ("indptr", lambda: self.ndarray(m.indptr)),
                    ("data", lambda: self.ndarray(m.data))])
        self.out += b"b"


def write_pickle(path, m):
    w = Py2Writer()
    items = []
    for k, v in m.items():
        if k in ("v_template", "shapedirs"):
            items.append((k, (lambda x: lambda: w.ch(x))(v)))
        elif sp.issparse(v):
            items.append((k, (lambda x: lambda: w.csc(x))(v)))
        elif isinstance(v, str):
            items.append((k, (lambda x: lambda: w.string(x))(v)))
        else:
            items.append((k, (lambda x: lambda: w.ndarray(x))(v)))
    w.dict_(items)
    w.out += b"."
    with open(path, "wb") as fh:
        fh.write(w.out)


def main(out):
    os.makedirs(out, exist_ok=True)
    m = model()
    write_pickle(os.path.join(out, "standin_smpl_py2.pkl"), m)
    arrays = {k: (v.toarray() if sp.issparse(v) else v) for k, v in m.items() if not isinstance(v, str)}
    np.savez(os.path.join(out, "standin_smpl_stored.npz"), **arrays)
    np.savez_compressed(os.path.join(out, "standin_smpl_deflated.npz"), **arrays)


if __name__ == "__main__":
    main(sys.argv[1])
