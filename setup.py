"""The Python module smpl_export as a wheel: CMake builds the extension (target
smpl_export_python, python/CMakeLists.txt) and setuptools packages it with the shim
python/smpl_export/ (__init__.py, __init__.pyi, py.typed). Offline with Debian's setuptools:
    /usr/bin/python3 -m pip install --no-build-isolation --no-index .
SMPL_BUILD_DIR=DIR reuses a configured build tree (its objects); the default is
build-python/ in the checkout (Release, tests off, ccache when present). Needs cmake, g++,
pybind11-dev and the build dependencies of scripts/setup-deps.sh --build.
"""
import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent
VERSION = (ROOT / "VERSION").read_text().split()[0]


class CMakeBuild(build_ext):
    """Builds _smpl_export with the project's CMake and puts it where setuptools expects it."""

    def build_extension(self, ext):
        build = pathlib.Path(os.environ.get("SMPL_BUILD_DIR", ROOT / "build-python")).resolve()
        if not (build / "CMakeCache.txt").exists():
            args = ["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                    "-DSMPL_BUILD_TESTS=OFF", f"-DPython3_EXECUTABLE={sys.executable}"]
            if shutil.which("ccache"):
                args.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
            subprocess.run(args, check=True)
        jobs = os.environ.get("SMPL_BUILD_JOBS", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(build), "-j", jobs, "--target", "smpl_export_python"],
                       check=True)
        built = sorted((build / "python" / "smpl_export").glob("_smpl_export*.so"))
        if not built:
            raise RuntimeError(f"no _smpl_export*.so in {build}/python/smpl_export: is pybind11-dev "
                               "installed (the module is built only when it is found)?")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[-1], target)


(ROOT / "build-python").mkdir(exist_ok=True)
setup(
    name="smpl_export",
    version=VERSION,
    description="SMPL / SMPL-H / SMPL-X / MANO bodies and motions to glTF/GLB, FBX and BVH, in process",
    long_description=(ROOT / "docs" / "python.md").read_text(encoding="utf-8")
    if (ROOT / "docs" / "python.md").exists() else "",
    long_description_content_type="text/markdown",
    license="See LICENSE",
    python_requires=">=3.8",
    install_requires=["numpy"],
    packages=["smpl_export"],
    package_dir={"": "python"},
    package_data={"smpl_export": ["__init__.pyi", "py.typed"]},
    ext_modules=[Extension("smpl_export._smpl_export", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
    # setuptools' own scratch files out of the checkout's build/ (a CMake tree) and python/
    options={"build": {"build_base": str(ROOT / "build-python" / "setuptools")},
             "egg_info": {"egg_base": str(ROOT / "build-python")}},
)
