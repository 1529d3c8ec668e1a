"""The wheel (scripts/release.sh's step: pip wheel with Debian's setuptools, offline) installs
with `pip install --no-index` into a fresh `python3 -m venv --system-site-packages`, imports and
exports the CLI's bytes; so does `pip install .` from the checkout. The extension is this build
tree's (SMPL_BUILD_DIR: no second compile)."""
import glob
import os
import subprocess
import sys

from conftest import SOURCE, cli_bytes

PYTHON = "/usr/bin/python3"


def clean_env():
    env = dict(os.environ)
    env.pop("PYTHONPATH", None)  # the venv must find its own copy, not the build tree's
    return env


def run(args, **kw):
    done = subprocess.run(args, capture_output=True, text=True, **kw)
    assert done.returncode == 0, f"{' '.join(map(str, args))}\n{done.stdout}\n{done.stderr}"
    return done.stdout


def check_venv(venv, tmp_path, expected):
    out = tmp_path / "from_venv.glb"
    code = ("import smpl_export as se, sys; print(se.__file__); "
            "open(sys.argv[1], 'wb').write(se.export(se.load_model('builtin')))")
    where = run([str(venv / "bin" / "python"), "-c", code, str(out)], cwd=tmp_path, env=clean_env())
    assert str(venv) in where, where
    assert out.read_bytes() == expected


def test_wheel_installs_offline_into_a_venv(tmp_path):
    env = dict(clean_env(), SMPL_BUILD_DIR=os.environ.get("SMPL_BUILD_DIR", str(SOURCE / "build")))
    dist = tmp_path / "dist"
    run([PYTHON, "-m", "pip", "wheel", "--no-build-isolation", "--no-index", "--no-deps", "-w",
         str(dist), str(SOURCE)], env=env)
    wheels = glob.glob(str(dist / "smpl_export-*-cp3*-linux_x86_64.whl"))
    assert len(wheels) == 1, os.listdir(dist)
    expected = cli_bytes(tmp_path, "builtin", "glb")
    venv = tmp_path / "venv"
    run([PYTHON, "-m", "venv", "--system-site-packages", str(venv)])
    run([str(venv / "bin" / "pip"), "install", "--no-index", wheels[0]], env=clean_env())
    check_venv(venv, tmp_path, expected)
    # pip install . from the checkout, offline
    venv2 = tmp_path / "venv2"
    run([PYTHON, "-m", "venv", "--system-site-packages", str(venv2)])
    run([str(venv2 / "bin" / "pip"), "install", "--no-build-isolation", "--no-index", str(SOURCE)],
        env=env)
    check_venv(venv2, tmp_path, expected)
