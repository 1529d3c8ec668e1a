"""smpl_maya: drive the pose-corrective blend shapes of an smpl-export FBX in
Maya 2022+ (Python 3, maya.api.OpenMaya). See maya/README.md.

core.py (the math, metadata and weight mapping, shared with the Blender add-on)
is copied here by the build (<build>/maya/scripts/smpl_maya/core.py, the
installable package); in a source checkout it is loaded from
blender/smpl_correctives/core.py, its one source.
"""
try:
    from . import core  # noqa: F401 (the installed package)
except ImportError:  # a source checkout
    import importlib.util as _util
    import os as _os
    import sys as _sys

    _path = _os.path.join(_os.path.dirname(_os.path.abspath(__file__)), "..", "..", "..",
                          "blender", "smpl_correctives", "core.py")
    _spec = _util.spec_from_file_location(__name__ + ".core", _path)
    core = _util.module_from_spec(_spec)
    _spec.loader.exec_module(core)
    _sys.modules[__name__ + ".core"] = core
