"""The API's names, facts of a model, option keywords and errors (docs/python.md)."""
import pathlib
import warnings

import numpy as np
import pytest

from conftest import MODELS, VIDEO, run_cli


def test_package_ships_stubs_and_shim(se):
    folder = pathlib.Path(se.__file__).parent
    assert (folder / "__init__.pyi").is_file() and (folder / "py.typed").is_file()
    assert list(folder.glob("_smpl_export*.so"))
    for name in ("load_model", "read_motion", "export", "cli", "Model", "Motion", "Error"):
        assert hasattr(se, name)


def test_model_facts(se):
    model = se.load_model(MODELS / "smplx_small.npz")
    assert model.family == "smplx"
    assert len(model.joint_names) == 55 and model.joint_names[0] == "pelvis"
    assert model.parents[0] == -1 and len(model.parents) == 55
    assert model.num_betas == 300 and model.num_expression == 100
    builtin = se.load_model("builtin")
    assert builtin.family == "smpl" and builtin.num_vertices > 0


def test_errors_carry_the_cli_exit_code(se):
    with pytest.raises(se.InputError) as e:
        se.load_model(MODELS / "missing.npz")
    assert e.value.exit_code == 2 and isinstance(e.value, ValueError)
    assert str(e.value).startswith("Error loading ") and "missing.npz" in str(e.value)
    model = se.load_model("builtin")
    with pytest.raises(se.UsageError) as e:
        se.export(model, max_influences=0)
    assert e.value.exit_code == 1 and "--max-influences" in str(e.value)
    # the CLI says the same line with the same code
    code, err = run_cli("--model", "builtin", "--out", "/tmp/unused.glb", "--max-influences", "0",
                        check=False)
    assert code == 1 and err.strip() == str(e.value)


def test_unknown_keyword_is_a_type_error(se):
    model = se.load_model("builtin")
    with pytest.raises(TypeError, match="max_influence'"):
        se.export(model, max_influence=4)
    with pytest.raises(TypeError, match="'fps'"):
        se.read_motion(VIDEO / "wham" / "wham_output.pkl", fps=30)
    with pytest.raises(TypeError, match="'out_dir'"):
        se.export(model, out_dir="x")


def test_options_reach_the_cli_parser(se):
    model = se.load_model("builtin")
    # a flag, a number, a choice and a list: refused where the CLI refuses them
    with pytest.raises(se.UsageError, match="--fbx-units"):
        se.export(model, format="glb", fbx_units="cm")
    with pytest.raises(se.UsageError, match="--draco"):
        se.export(model, format="fbx", draco=True)
    data = se.export(model, format="glb", max_influences="all", name="hero", betas=[0.5, -0.25])
    assert data[:4] == b"glTF" and b'"hero"' in data


def test_cli_in_process(se, tmp_path):
    out = tmp_path / "body.glb"
    assert se.cli(["--model", "builtin", "--out", str(out), "--quiet"]) == 0
    assert out.read_bytes() == se.export(se.load_model("builtin"))
    assert se.cli(["--model", "builtin", "--out", str(out), "--max-influences", "0"]) == 1
    assert se.cli(["--model", str(tmp_path / "none.npz"), "--out", str(out)]) == 2


def test_export_to_a_path_writes_atomically_with_sidecar(se, tmp_path):
    model = se.load_model("builtin")
    out = tmp_path / "walk.glb"
    assert se.export(model, out=out) == str(out)
    assert out.read_bytes() == se.export(model)
    assert (tmp_path / "walk.glb.smpl.json").is_file()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["walk.glb", "walk.glb.smpl.json"]
    with pytest.raises(se.UsageError):  # the CLI's guard: an output that is a folder
        se.export(model, out=tmp_path)


def test_notes_are_warnings(se):
    model = se.load_model(MODELS / "smpl_small.npz")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        se.export(model, motion=str(VIDEO / "wham" / "wham_output.pkl"))
    notes = [str(w.message) for w in caught if issubclass(w.category, se.Note)]
    assert any("track 1 of 3" in n for n in notes), notes


def test_motion_keeps_its_reading_options(se):
    model = se.load_model(MODELS / "smpl_small.npz")
    wham = VIDEO / "wham" / "wham_output.pkl"
    motion = se.read_motion(wham, model=model, track="0", source_fps=25)
    assert motion.track == "0" and motion.fps == 25
    assert se.export(model, motion=motion) == se.export(model, motion=str(wham), track="0", source_fps=25)
    assert se.export(model, motion=motion, track="0") == se.export(model, motion=motion)
    with pytest.raises(se.UsageError, match="--track"):
        se.export(model, motion=motion, track="1")


def test_forward_shapes_and_errors(se):
    model = se.load_model(MODELS / "smpl_small.npz")
    poses = np.zeros((2, 24, 3))
    v, j = model.forward(None, poses)
    assert v.shape == (2, model.num_vertices, 3) and j.shape == (2, 24, 3) and v.dtype == np.float32
    v64, _ = model.forward(np.zeros(model.num_betas), poses.reshape(2, 72), dtype="float64")
    assert v64.dtype == np.float64 and v64.flags.owndata
    with pytest.raises(se.UsageError, match="poses"):
        model.forward(None, np.zeros((2, 23, 3)))
    with pytest.raises(se.UsageError, match="NaN"):
        model.forward(None, np.full((1, 24, 3), np.nan))
    with pytest.raises(se.UsageError, match="betas"):
        model.forward(np.zeros(model.num_betas + 1), poses)
