"""read_motion on many layouts, each compared with the CLI's bake of the same file: the GLB's
rotation channels (local joint rotations, float32 quaternions) are the Motion's rotations in the
model's joint order, frame for frame (the root is left out: the bake turns it upright), at the
rate the Motion reports; and the Motion's notes are the ones the CLI prints."""
import numpy as np
import pytest

from conftest import FIXTURES, GENERATION, MODELS, VIDEO, glb_rotations, quaternion_matrices, run_cli

M = FIXTURES / "motions"
CASES = [  # (label, motion file, model fixture, reading options)
    ("amass_smplx", M / "amass_smplx.npz", "smplx_small", {}),
    ("amass_smplh", M / "amass_smplh.npz", "smplh_small", {}),
    ("plain_smpl", M / "smpl_72.npz", "smpl_small", {}),
    ("matrices", M / "matrices.npz", "smpl_small", {}),
    ("wham", VIDEO / "wham" / "wham_output.pkl", "smpl_small", {"track": "0", "source_fps": 25}),
    ("vibe", VIDEO / "vibe" / "vibe_output.pkl", "smpl_small", {}),
    ("phalp", VIDEO / "phalp" / "demo_video.pkl", "smpl_small", {"track": "2"}),
    ("gvhmr", VIDEO / "gvhmr" / "hmr4d_results.pt", "smplx_small", {"source_params": "incam"}),
    ("gvhmr_hands", VIDEO / "gvhmr_hands" / "hmr4d_results.pt", "smplx_small", {}),
    ("tram", VIDEO / "tram" / "seq" / "hps" / "hps_track_0.npy", "smpl_small", {}),
    ("romp", VIDEO / "romp" / "video_results.npz", "smpl_small", {}),
    ("bev", VIDEO / "bev" / "video_results.npz", "smpl_small", {}),
    ("mdm", GENERATION / "mdm" / "sample00_rep00_smpl_params.npy", "smpl_small", {}),
    ("motionx", GENERATION / "motionx" / "smplx322_walk.npy", "smplx_small", {}),
    ("bare_poses", GENERATION / "bare" / "example_smplx_poses.npy", "smplx_small", {}),
    ("bare_poses_pt", GENERATION / "bare" / "smplh_poses.pt", "smplh_small", {}),
    ("beat2", GENERATION / "beat2" / "2_scott_0_1_1_output.npz", "smplx_small", {}),
    ("smplifyx", GENERATION / "fits" / "smplifyx_000.pkl", "smplx_small", {"up": "y"}),
    ("prompthmr", VIDEO / "prompthmr" / "results.pkl", "smplx_small", {"track": "1"}),
    ("mcs", VIDEO / "prompthmr" / "world4d.mcs", "smplx_small", {"track": "0"}),
]


def cli_args(options):
    out = []
    for key, value in options.items():
        out += ["--" + key.replace("_", "-"), str(value)]
    return out


@pytest.mark.parametrize("label,path,model_name,options", CASES, ids=[c[0] for c in CASES])
def test_read_motion_matches_the_cli_bake(se, tmp_path, label, path, model_name, options):
    model_path = MODELS / f"{model_name}.npz"
    model = se.load_model(model_path)
    motion = se.read_motion(path, model=model, **options)
    glb = tmp_path / "bake.glb"
    _, stderr = run_cli("--model", model_path, "--motion", path, "--out", glb, *cli_args(options),
                        quiet=False)
    channels, times = glb_rotations(glb.read_bytes())
    rotations = motion.rotations
    frames = rotations.shape[0]
    assert rotations.shape == (frames, len(model.joint_names), 3, 3)
    assert motion.trans.shape == (frames, 3)
    assert len(times) == frames
    if frames > 1:
        assert abs((times[1] - times[0]) - 1.0 / motion.fps) < 1e-5
    compared, moving = 0, 0.0
    for k, name in enumerate(model.joint_names[1:], start=1):
        if name not in channels:
            assert np.allclose(rotations[:, k], np.eye(3)), f"{name}: posed but not baked"
            continue
        baked = quaternion_matrices(channels[name])
        assert np.abs(baked - rotations[:, k]).max() < 2e-6, f"{label}: joint {name}"
        moving = max(moving, np.abs(rotations[:, k] - rotations[:, k].transpose(0, 2, 1)).max())
        compared += 1
    assert compared >= 10
    assert moving > 1e-3  # the transposed (wrong-handed) reading would be caught
    assert motion.layout and isinstance(motion.notes, list)
    for note in motion.notes:  # what the reader said, the CLI says too
        assert note in stderr, note  # the CLI prefixes the clip name


def test_layouts_are_named(se):
    model = se.load_model(MODELS / "smplx_small.npz")
    assert se.read_motion(M / "amass_smplx.npz", model=model).layout == "amass"
    assert se.read_motion(VIDEO / "gvhmr" / "hmr4d_results.pt", model=model).layout == "gvhmr"


def test_motion_arrays(se):
    model = se.load_model(MODELS / "smplx_small.npz")
    data = dict(np.load(M / "amass_smplx.npz"))
    motion = se.read_motion(data, model=model)
    assert motion.fps == float(data["mocap_frame_rate"])
    assert np.allclose(motion.trans, data["trans"])
    assert np.allclose(motion.betas, data["betas"])
    assert motion.gender == str(data["gender"])
    no_model = se.read_motion(data)
    assert no_model.rotations.shape[1] == 55 and no_model.joint_names[0] == "pelvis"
