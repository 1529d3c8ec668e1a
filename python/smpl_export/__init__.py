"""smpl_export: SMPL / SMPL-H / SMPL-X / MANO bodies and motions to glTF/GLB, FBX and BVH, in process.

The five calls (docs/python.md)::

    import smpl_export as se
    model = se.load_model("SMPLX_NEUTRAL.npz")          # or "builtin" (the demo body)
    verts, joints = model.forward(betas, poses, trans)  # numpy (T,V,3), (T,K,3), metres
    motion = se.read_motion("hmr4d_results.pt", model=model)
    data = se.export(model, motion=motion, format="glb")  # bytes: what the CLI writes
    se.cli(["--model", "builtin", "--out", "body.glb"])   # the command line, in process

This file is the thin Python layer over the compiled module ``_smpl_export``
(python/bindings/): keyword options become the command line's options
(``max_influences=4`` is ``--max-influences 4``; the CLI's own parser and
checks run on them), torch tensors become numpy arrays (``detach().cpu()``;
the module does not link torch), and errors become ``Error`` subclasses
carrying the CLI's exit code. The heavy work runs in C++ without the GIL.
"""
import os
import warnings

from . import _smpl_export as _core

__version__ = _core.__version__
__all__ = ["load_model", "read_motion", "export", "cli", "Model", "Motion", "Error", "UsageError",
           "InputError", "ExportError", "OutputError", "Note"]

Model = _core.Model
Motion = _core.Motion


class Error(ValueError):
    """An export failed: ``str(error)`` is the CLI's one-line message ("Error loading walk.npz:
    ..."), ``exit_code`` the exit code the CLI would return (1 usage, 2 input, 3 export, 4 output)."""

    def __init__(self, message, exit_code=3):
        super().__init__(message)
        self.exit_code = exit_code


class UsageError(Error):
    """Exit code 1: an option's value, a conflict between options, a shape or count in an argument."""


class InputError(Error):
    """Exit code 2: a model or motion that cannot be read (missing keys, wrong shapes, NaN, hostile)."""


class ExportError(Error):
    """Exit code 3: the asset could not be built (nothing is written)."""


class OutputError(Error):
    """Exit code 4: the output could not be written (nothing is left half-written)."""


class Note(UserWarning):
    """What an export or a read assumed or left out (the CLI's "note:" lines), as a warning."""


_core._set_error_classes({1: UsageError, 2: InputError, 3: ExportError, 4: OutputError})

# Options that are this API's arguments, or belong to the command line only
# (batch mode, printing): refused as keywords, naming what to use instead.
_NOT_KEYWORDS = {
    "model": "the first argument (a Model from load_model)",
    "motion": "the motion= argument",
    "out": "the out= argument",
    "format": "the format= argument (the output's format)",
    "betas": "the betas= argument",
    "motion_dir": "smpl_export.cli([...]) (batch mode)",
    "out_dir": "smpl_export.cli([...]) (batch mode)",
    "manifest": "smpl_export.cli([...]) (batch mode)",
    "shard": "smpl_export.cli([...]) (batch mode)",
    "force": "smpl_export.cli([...]) (batch mode)",
    "quiet": "nothing (notes are warnings of class smpl_export.Note)",
    "help": "help(smpl_export) or smpl_export.cli(['--help'])",
    "version": "smpl_export.__version__",
}
# The options that decide how a motion is read: a Motion keeps them (read_motion).
_READING = ("source_fps", "source_params", "up", "track", "flat_hand_mean")
_TABLE = {name[2:].replace("-", "_"): takes_value for name, takes_value in _core._options()}


def _numpy(value):
    """A torch tensor (anything with detach/cpu/numpy) as a numpy array, other values unchanged."""
    if hasattr(value, "detach") and hasattr(value, "cpu") and hasattr(value, "numpy"):
        return value.detach().cpu().numpy()
    return value


def _tree(value):
    """Dicts, lists and tuples with their tensors as numpy arrays (what the readers read)."""
    if isinstance(value, dict):
        return {k: _tree(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_tree(v) for v in value]
    value = _numpy(value)
    if hasattr(value, "__array__") and not _is_numpy(value):
        import numpy
        return numpy.asarray(value)
    return value


def _is_numpy(value):
    return type(value).__module__ == "numpy"


def _text(name, value):
    """A keyword's value as the command line types it."""
    if isinstance(value, bool):
        raise TypeError(f"{name}: expected a value, got {value!r}")
    value = _numpy(value)
    if isinstance(value, str):
        return value
    if hasattr(value, "__array__") or isinstance(value, (list, tuple)):
        import numpy
        array = numpy.asarray(value).reshape(-1)
        return ",".join(repr(float(v)) if array.dtype.kind == "f" else str(v) for v in array.tolist())
    return repr(value) if isinstance(value, float) else str(value)


def _arguments(function, options, allowed=None):
    """Keywords -> CLI arguments ("--max-influences", "4"), through the CLI's option table.
    TypeError names an unknown keyword (or one this call does not take)."""
    args = []
    for key, value in options.items():
        if key in _NOT_KEYWORDS:
            raise TypeError(f"{function}() got an unexpected keyword argument '{key}': "
                            f"use {_NOT_KEYWORDS[key]}")
        if key not in _TABLE or (allowed is not None and key not in allowed):
            where = "" if key not in _TABLE else " (not a reading option: give it to export())"
            raise TypeError(f"{function}() got an unexpected keyword argument '{key}'{where}")
        if value is None or value is False:
            continue
        option = "--" + key.replace("_", "-")
        if not _TABLE[key]:
            if value is not True:
                raise TypeError(f"{key}: a flag, expected True or False, got {value!r}")
            args.append(option)
        else:
            args += [option, _text(key, value)]
    return args


def _warn(notes):
    for note in notes:
        warnings.warn(note, Note, stacklevel=3)


def load_model(path):
    """Load a body model once: any model file the CLI reads (SMPL/SMPL-H/SMPL-X/MANO .npz or .pkl,
    SMPLX_*.npz, a .glb/.fbx exported by smpl-export) or "builtin" (the demo body).

    Returns a Model: .family ('smpl', 'smplh', 'smplx', 'mano'), .joint_names (K names),
    .parents (K ints, -1 for the root), .num_betas (B), .num_expression (E), .num_vertices (V),
    .forward(). Raises InputError (exit 2) for a file that cannot be read. The GIL is released
    while the file is read.
    """
    return _core._load_model(os.fspath(path))


def _forward(self, betas, poses, trans=None, expression=None, dtype="float32"):
    """Vertices and joints of the body for T poses (docs/file-contract.md "The math").

    betas: (B,) or (T,B) shape coefficients (B <= num_betas; None: zeros).
    poses: (T,K,3) or (T,3K) axis-angle in radians, or (T,K,3,3) rotation matrices; local to
        each joint's parent, in the model's joint order (joint_names).
    trans: (T,3) or (3,) root translation in metres, or None.
    expression: (E,) or (T,E) SMPL-X expression coefficients, or None.
    dtype: "float32" (default) or "float64" for the outputs.
    Inputs may be numpy arrays, torch tensors (any device: copied to the CPU) or anything with
    __array__; float32/float64 C-contiguous arrays are read in place.
    Returns (vertices (T,V,3), joints (T,K,3)) in metres, model axes (Y up for the released
    models). UsageError for wrong shapes, counts above the model's, NaN. The GIL is released.
    """
    return self._forward(_numpy(betas), _numpy(poses), _numpy(trans), _numpy(expression), dtype)


Model.forward = _forward


def read_motion(motion, model=None, track=None, name="motion", **options):
    """Read one track of a motion: a file of any layout the CLI reads (AMASS .npz, GVHMR .pt,
    WHAM/4D-Humans .pkl, SMPLCodec .smpl, ...; docs/motions.md), or a dict of arrays in any of
    those layouts (numpy arrays or torch tensors; a flat dict reads as np.savez of it would, a
    nested one as torch.save of it would).

    model: a Model: rotations come in its joint order (joints the motion lacks at rest) and fit
        hands (PCA coefficients) are resolved through its basis; None: the motion's own order.
    track: a track id of a multi-person file, "longest" (default) ("all" is export-only).
    name: the clip name of a dict (a file's is its stem).
    options: the reading options of the CLI: source_fps=R, source_params="global"|"incam",
        up="y"|"z"|"-y", flat_hand_mean=True. The Motion keeps them: export() reads it so.
    Returns a Motion: .rotations (T,K,3,3), .trans (T,3) metres, .betas (B,) or None,
    .expression (T,E) or None, .fps, .layout (the reader table's name), .notes (the CLI's notes),
    .track, .gender, .joint_names. InputError (exit 2) for a file or dict that cannot be read
    (missing keys, wrong shapes, NaN, hostile pickles: nothing is executed). GIL released.
    """
    if track is not None:
        options["track"] = track
    reading = _arguments("read_motion", options, _READING)
    value = os.fspath(motion) if isinstance(motion, (str, os.PathLike)) else None
    if value is None:
        if not isinstance(motion, dict):
            raise TypeError("read_motion() expects a path or a dict of arrays, got "
                            f"{type(motion).__name__}")
        value = _tree(motion)
    result = _core._read_motion(value, name, reading, model)
    return result


def _reading_of(motion, options):
    """The reading options of an export of `motion`: the Motion's own (as CLI arguments). The
    same option given to export() again must say the same, else UsageError: the motion was read
    with the other (read it again to change it)."""
    kept, i = {}, 0
    args = list(motion.reading_options)
    while i < len(args):
        takes = _TABLE[args[i][2:].replace("-", "_")]
        kept[args[i]] = args[i + 1] if takes else ""
        i += 2 if takes else 1
    for key in [k for k in _READING if k in options]:
        given = _arguments("export", {key: options.pop(key)})
        option = "--" + key.replace("_", "-")
        value = given[1] if len(given) > 1 else ("" if given else None)
        if kept.get(option) != value:
            raise UsageError(f"Error in arguments: {option} {value or ''}: the motion was read "
                             f"with {option} {kept.get(option, '(not given)')}; read it again "
                             "with the option to change it", 1)
    return args


def export(model, motion=None, betas=None, format="glb", out=None, **options):
    """Export the model (and a motion) as the CLI would: the same request, the same bytes.

    model: a Model (load_model).
    motion: None (the rest pose), a path, a Motion (read_motion), or a dict of arrays in any
        layout the readers know (numpy or torch values; read as read_motion reads it).
    betas: (B,) shape coefficients (--betas), or None (the motion's, else zeros).
    format: "glb" (default), "fbx", "bvh", "gltf" (needs gltf_embed=True in memory), "xml"
        (MJCF; with a motion it needs out: its qpos .npz is a second file) when out is
        None; with out, its extension decides.
    out: None: return the output's bytes (nothing is written); a path: write it atomically,
        with its sidecar <out>.smpl.json, as the CLI does, and return the path.
    options: every CLI option, '-' -> '_' (max_influences=4 or "all", up="-y", preset="web",
        fps=30, origin="floor", root_bone=True, ...; docs/cli.md). An unknown keyword raises
        TypeError naming it; a reading option that conflicts with the Motion's is a UsageError.
    Notes (the CLI's "note:" lines) are warnings of class Note. Errors: Error subclasses with
    the CLI's message and exit_code. The GIL is released while it loads, bakes and writes.
    """
    _arguments("export", options)  # TypeError for an unknown keyword, before any reading
    if isinstance(motion, dict):
        motion = read_motion(motion, model=model, **{k: options[k] for k in _READING if k in options})
    target = os.fspath(out) if out is not None else f"memory.{format}"
    head = ["--model", model.path, "--out", target]
    motion_object = None
    if isinstance(motion, Motion):
        options = dict(options)
        head += ["--motion", motion.source] + _reading_of(motion, options)
        motion_object = motion
    elif motion is not None:
        head += ["--motion", os.fspath(motion)]
    args = _arguments("export", options)
    if betas is not None:
        args += ["--betas", _text("betas", betas)]
    result, notes = _core._export(head + args, model, motion_object, out is None)
    _warn(notes)
    return result


def cli(args):
    """Run the smpl-export command line in this process: ``cli(["--model", "m.npz", "--motion",
    "walk.npz", "--out", "walk.glb"])``. Prints what the CLI prints (to the process's stdout and
    stderr) and returns its exit code (0 ok, 1 usage, 2 input, 3 export, 4 output). The GIL is
    released while it runs."""
    return _core._cli([os.fspath(a) for a in args])
