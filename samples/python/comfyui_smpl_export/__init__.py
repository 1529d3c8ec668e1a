"""A minimal ComfyUI custom node: an SMPL-X parameter dict into a GLB (docs/python.md "ComfyUI").

Copy this folder into ComfyUI/custom_nodes/ with smpl_export installed in ComfyUI's Python
(`pip install --no-build-isolation --no-index .` from an smpl-export checkout, or its wheel).
Input SMPLX_PARAMS: a dict of SMPL-X fit parameters, numpy arrays or torch tensors of T frames:
global_orient (T,3), body_pose (T,63) axis-angle radians, transl (T,3) metres, betas (B,) or
(T,B); optional left_hand_pose / right_hand_pose (T,45), jaw_pose (T,3), expression (T,E)
(the reader table's "fit" layout, docs/motions.md). The GLB is written atomically into
ComfyUI's output folder; the node returns its path.
"""
import os

import smpl_export as se

_MODELS = {}  # path -> Model: a model is read once per process


def _model(path):
    if path not in _MODELS:
        _MODELS[path] = se.load_model(path)
    return _MODELS[path]


def _output_folder():
    try:
        import folder_paths  # ComfyUI's
        return folder_paths.get_output_directory()
    except ImportError:  # outside ComfyUI (the sample's test)
        return os.getcwd()


class SmplxToGlb:
    """SMPL-X parameters -> a rigged, animated GLB (pose correctives baked as morph targets)."""

    CATEGORY = "smpl_export"
    FUNCTION = "export"
    RETURN_TYPES = ("STRING",)
    RETURN_NAMES = ("glb_path",)
    OUTPUT_NODE = True

    @classmethod
    def INPUT_TYPES(cls):
        return {"required": {
            "smplx_params": ("SMPLX_PARAMS",),
            "model_path": ("STRING", {"default": "models/smplx/SMPLX_NEUTRAL.npz"}),
            "fps": ("FLOAT", {"default": 30.0, "min": 1.0, "max": 240.0}),
            "filename": ("STRING", {"default": "smplx_motion.glb"}),
        }}

    def export(self, smplx_params, model_path, fps, filename):
        model = _model(model_path)
        name = os.path.basename(filename)
        out = os.path.join(_output_folder(), name)
        # the clip is named after the file, as the CLI names it after the motion file
        motion = se.read_motion(dict(smplx_params), model=model, name=os.path.splitext(name)[0],
                                source_fps=fps)
        return (se.export(model, motion=motion, out=out),)


NODE_CLASS_MAPPINGS = {"SmplxToGlb": SmplxToGlb}
NODE_DISPLAY_NAME_MAPPINGS = {"SmplxToGlb": "SMPL-X to GLB (smpl_export)"}
