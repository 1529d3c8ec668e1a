"""Several Python threads exporting at once give the bytes of one thread alone (the GIL is
released during the work, so they do run at once); hostile, truncated and malformed inputs
raise smpl_export errors, never crash the interpreter and never run code."""
import io
import os
import pickle
import threading
import zipfile

import numpy as np
import pytest

from conftest import FIXTURES, MODELS, VIDEO

AMASS = FIXTURES / "motions" / "amass_smplx.npz"


def test_threads_export_the_same_bytes(se):
    model = se.load_model(MODELS / "smplx_small.npz")
    smpl = se.load_model(MODELS / "smpl_small.npz")
    jobs = [(model, str(AMASS), "glb"), (model, str(AMASS), "fbx"), (model, None, "bvh"),
            (smpl, str(VIDEO / "wham" / "wham_output.pkl"), "glb")]
    frames = {"frames": "0:40"}  # short clips: the test is about concurrency, not length

    def one(m, x, f):
        return se.export(m, motion=x, format=f, **(frames if x else {}))

    expected = [one(*job) for job in jobs]
    results = {}
    errors = []

    def work(i):
        try:
            m = jobs[i % len(jobs)][0]
            results[i] = one(*jobs[i % len(jobs)])
            v, _ = m.forward(None, np.zeros((3, len(m.joint_names), 3)))
            assert v.shape[0] == 3
        except Exception as e:  # reported below
            errors.append(e)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(8)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors, errors
    for i, data in results.items():
        assert data == expected[i % len(jobs)], f"thread {i}"


def test_gil_is_released_while_exporting(se):
    """A Python thread keeps running while another exports (it would stall with the GIL held)."""
    model = se.load_model(MODELS / "smplx_small.npz")
    ticks = []
    done = threading.Event()

    def ticker():
        while not done.is_set():
            ticks.append(1)
            done.wait(0.001)

    t = threading.Thread(target=ticker)
    t.start()
    before = len(ticks)
    for _ in range(2):
        se.export(model, motion=str(AMASS), format="fbx", frames="0:60")
    done.set()
    t.join()
    assert len(ticks) - before > 5


class Boom:
    def __reduce__(self):
        return (os.system, ("touch " + os.environ.get("BOOM_MARKER", "/tmp/boom"),))


def hostile_inputs(tmp_path):
    marker = tmp_path / "executed"
    os.environ["BOOM_MARKER"] = str(marker)
    evil = tmp_path / "evil.pkl"
    evil.write_bytes(pickle.dumps({"poses": Boom(), "trans": np.zeros((2, 3))}))
    truncated = tmp_path / "truncated.npz"
    truncated.write_bytes(AMASS.read_bytes()[:700])
    garbage = tmp_path / "garbage.pt"
    garbage.write_bytes(os.urandom(4096))
    bomb = tmp_path / "bomb.npz"  # a member that claims 2^40 elements
    buf = io.BytesIO()
    np.lib.format.write_array_header_1_0(buf, {"descr": "<f8", "fortran_order": False,
                                               "shape": (1 << 20, 1 << 20)})
    with zipfile.ZipFile(bomb, "w") as z:
        z.writestr("poses.npy", buf.getvalue() + b"\0" * 64)
        z.writestr("trans.npy", buf.getvalue())
    return marker, [evil, truncated, garbage, bomb, VIDEO / "hostile" / "wham_output.pkl",
                    FIXTURES / "motions" / "bad_nan.npz", FIXTURES / "motions" / "bad_joints.npz"]


def test_hostile_files_raise(se, tmp_path):
    model = se.load_model(MODELS / "smpl_small.npz")
    marker, files = hostile_inputs(tmp_path)
    for path in files:
        with pytest.raises(se.InputError) as e:
            se.read_motion(path, model=model)
        assert e.value.exit_code == 2 and "\n" not in str(e.value)
        with pytest.raises(se.InputError):
            se.export(model, motion=str(path))
        with pytest.raises(se.InputError):
            se.load_model(path)
    assert not marker.exists(), "a pickle ran code"


def test_hostile_dicts_raise(se):
    model = se.load_model(MODELS / "smpl_small.npz")
    cases = [
        {"poses": np.zeros((4, 72)), "trans": np.zeros((3, 3))},       # lengths differ
        {"poses": np.full((4, 72), np.nan), "trans": np.zeros((4, 3))},  # NaN
        {"poses": np.zeros((4, 71)), "trans": np.zeros((4, 3))},       # not 3 per joint
        {"poses": np.array([object()] * 4), "trans": np.zeros((4, 3))},  # objects
        {1: np.zeros((4, 72))},                                          # a key that is no name
        {"nothing": np.zeros(3)},                                        # no layout
    ]
    for data in cases:
        with pytest.raises(se.InputError):
            se.export(model, motion=data)
    with pytest.raises(TypeError):
        se.read_motion(42)
