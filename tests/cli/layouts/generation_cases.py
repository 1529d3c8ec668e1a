"""Layout cases of the motion-generation tools (docs/motions.md, "Motion-generation tools,
hand and camera-frame fits"):
Motion-X smplx_322, MDM smpl_params / results, HumanML3D joints, HaMeR hands, BEAT2 /
EMAGE, camera-frame fits, VPoser latents, bare pose arrays and an unknown layout. The fixtures are written by
tests/fixtures/make_generation_layouts.py into FIXTURE_DIR/layouts/generation/.

CASES: one dict per case, the format every layouts/*_cases.py shares:
  name      the case (also the output stem: WORK/<name>.glb)
  fixture   the motion, relative to FIXTURE_DIR (a folder when "sequence" is true)
  sequence  optional; true: the fixture is a folder given as --motion-sequence DIR
  model     FIXTURE_DIR/models/<model>.npz (mano_left_small: the mirrored mano_small
            written by make_generation_layouts.py)
  args      extra smpl-export arguments
  outputs   None, or the output suffixes of --track all (WORK/<name><suffix>.glb)
  frames    three clip-relative frames; with outputs, a dict suffix -> three frames
  notes     substrings stderr (the notes) must contain
  refusal   None, or {"exit": 2, "message": substring of the one stderr line,
            "forbid": substrings that line must not contain}
  wrong     optional; [(label, change)]: plausible wrong readings of the file, each of which
            must be >= 1 mm from the right one (run_cases.py check_wrong_readings calls
            wrong_expected(case, fixture_dir, change); change {"reading": name} is read by the
            case's decoder)

expected(case, fixture_dir) -> {"fps", "frames", "num_vertices", "vertices"} (Y-up metres,
weights pruned to 4 influences as --skin-weights truncated --max-influences 4 exports them),
or {suffix: that dict} for cases with outputs. It implements each tool's conventions from
the tool's own code (cited per function) and the body model's math in numpy
(tests/roundtrip/model_math.py and the local matrix helpers below), independently of the
C++ code.

equivalent(case, fixture_dir, work_dir) -> [{"suffix", "motion", "model", "args"}]: the
same motion in today's terms (a plain .npz: poses (T,J,3,3) rotation matrices in the
model's joint order after every convention of the tool, trans (T,3), betas, fps; camera
frames pre-rotated into Y-up; animated expressions as a DMPL basis of the expression
directions with --dmpl-joints fixed, whose math is the fixed-joint expression math), so
that today's smpl-export checks this reference and the comparison chain. None for refusals.

authors_expression_cost(case, fixture_dir): the largest vertex distance (m) between the
exported fixed-joint expression math and the published one (joints regressed from the
expressive template), over every baked frame, with the pruned weights: the number the
exporter's closing note reports.
"""
import glob
import os
import pickle
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "roundtrip"))
import model_math  # noqa: E402

INFLUENCES = 4
MIRROR_X = np.diag([-1.0, 1.0, 1.0])     # HaMeR's left hands: x -> -x
CAMERA_TO_Y_UP = np.diag([1.0, -1.0, -1.0])  # --up -y: half turn about x, (x,y,z) -> (x,-y,-z)
VPOSER = "a VPoser latent: decode it with VPoser first"
G = "layouts/generation/"  # make_generation_layouts.py writes FIXTURE_DIR/layouts/generation/
POSITIONS = "joint positions, no rotations: fit a body first, e.g. with SMPLify"
BARE_TRANSPOSED = ("(T,K,3) read as (T,3,K)", {"reading": "transposed"})

CASES = [
    # Motion-X smplx_322 (.npy (T,322) float32): Y-up world, 30 fps (documented), flat hands.
    {"name": "motionx_smplx322", "fixture": G + "motionx/smplx322_walk.npy",
     "model": "smplx_small", "args": [], "outputs": None, "frames": [0, 11, 23],
     "notes": ["30 fps", "--expression-keys", "face_shape"], "refusal": None},
    {"name": "motionx_smplx322_expr10", "fixture": G + "motionx/smplx322_walk.npy",
     "model": "smplx_small", "args": ["--expression-keys", "10"], "outputs": None,
     "frames": [0, 12, 23], "notes": ["30 fps", "dropped", "betas-only skeleton"],
     "refusal": None},
    {"name": "motionx_smplx172", "fixture": G + "motionx/smplx172_walk.npy",
     "model": "smplx_small", "args": [], "outputs": None, "frames": [0, 7, 23],
     "notes": ["30 fps"], "refusal": None},
    # MDM render_mesh output: 6D rows (PyTorch3D), root translation relative to frame 0, 20 fps.
    {"name": "mdm_smpl_params", "fixture": G + "mdm/sample00_rep00_smpl_params.npy",
     "model": "smpl_small", "args": [], "outputs": None, "frames": [0, 14, 29],
     "notes": ["20 fps"], "refusal": None},
    {"name": "mdm_results_positions", "fixture": G + "mdm/results.npy",
     "model": "smpl_small", "args": [], "outputs": None, "frames": None, "notes": [],
     "refusal": {"exit": 2, "message": POSITIONS, "forbid": ["shape file"]}},
    {"name": "humanml3d_joints", "fixture": G + "humanml3d/new_joints_000021.npy",
     "model": "smpl_small", "args": [], "outputs": None, "frames": None, "notes": [],
     "refusal": {"exit": 2, "message": POSITIONS, "forbid": ["shape file"]}},
    {"name": "humanml3d_features", "fixture": G + "humanml3d/new_joint_vecs_000021.npy",
     "model": "smpl_small", "args": [], "outputs": None, "frames": None, "notes": [],
     "refusal": {"exit": 2, "message": "fit a body first, e.g. with SMPLify",
                 "forbid": ["shape file"]}},
    # HaMeR: right-hand MANO params in camera coordinates; left hands mirrored.
    {"name": "hamer_right", "fixture": G + "hamer/right_hand.npz", "model": "mano_small",
     "args": [], "outputs": None, "frames": [0, 9, 19],
     "notes": ["--up -y", "30 fps", "per-frame rows differ"], "refusal": None},
    {"name": "hamer_right_up_y", "fixture": G + "hamer/right_hand.npz",
     "model": "mano_small", "args": ["--up", "y"], "outputs": None, "frames": [0, 10, 19],
     "notes": ["30 fps"], "refusal": None},
    {"name": "hamer_left_on_left_model", "fixture": G + "hamer/left_hand.npz",
     "model": "mano_left_small", "args": [], "outputs": None, "frames": [0, 9, 19],
     "notes": ["--up -y"], "refusal": None},
    {"name": "hamer_left_on_right_model", "fixture": G + "hamer/left_hand.npz",
     "model": "mano_small", "args": [], "outputs": None, "frames": [0, 9, 19],
     "notes": ["--up -y", "mirrored"], "refusal": None},
    {"name": "hamer_hands3_all", "fixture": G + "hamer/hands3", "sequence": True,
     "model": "mano_small", "args": ["--track", "all"],
     "outputs": [".track0", ".track1", ".track2"],
     "frames": {".track0": [0, 5, 11], ".track1": [0, 8, 15], ".track2": [0, 2, 3]},
     "notes": ["--up -y", "mirrored"], "refusal": None},
    {"name": "hamer_hands3_track1", "fixture": G + "hamer/hands3", "sequence": True,
     "model": "mano_small", "args": ["--track", "1"], "outputs": None, "frames": [0, 7, 15],
     "notes": ["--up -y"], "refusal": None},
    {"name": "hamer_mixed_sides", "fixture": G + "hamer/mixed_sides.npz", "model": "mano_small",
     "args": [], "outputs": None, "frames": None, "notes": [],
     "refusal": {"exit": 2, "message": "mixes left and right hands",
                 "forbid": ["shape file", "body_pose"]}},
    {"name": "hamer_tie_longest", "fixture": G + "hamer/hands_tie", "sequence": True,
     "model": "mano_small", "args": [], "outputs": None, "frames": [0, 4, 9],
     # The tie goes to the lower id (motion_tracks.cpp selectTracks; the wording of the
     # video cases, e.g. wham_world's "other tracks: 0 (0-17), 2 (2-26)").
     "notes": ["track 0 of 2 (source frames 0-9, the longest); other tracks: 1 (3-12)"],
     "refusal": None},
    # BEAT2 / EMAGE: poses (T,165) with hands relative to hands_mean, expressions (T,100), Y up.
    {"name": "beat2_expr100", "fixture": G + "beat2/2_scott_0_1_1_output.npz",
     "model": "smplx_small", "args": ["--expression-keys", "100"], "outputs": None,
     "frames": [0, 12, 23], "notes": ["betas-only skeleton"], "refusal": None},
    {"name": "beat2_expr20", "fixture": G + "beat2/2_scott_0_1_1_output.npz",
     "model": "smplx_small", "args": ["--expression-keys", "20"], "outputs": None,
     "frames": [0, 11, 23], "notes": ["dropped"], "refusal": None},
    {"name": "beat2_no_expression_keys", "fixture": G + "beat2/2_scott_0_1_1_output.npz",
     "model": "smplx_small", "args": [], "outputs": None, "frames": [0, 11, 23],
     "notes": ["--expression-keys"], "refusal": None},
    # Camera-frame fits.
    {"name": "fit_camera_up_minus_y", "fixture": G + "fits/camera_fit.pkl",
     "model": "smplx_small", "args": ["--up", "-y"], "outputs": None, "frames": [0, 6, 11],
     "notes": ["30 fps"], "refusal": None},
    {"name": "smplifyx_camera_translation", "fixture": G + "fits/smplifyx_000.pkl",
     "model": "smplx_small", "args": [], "outputs": None, "frames": [0, 0, 0],
     "notes": ["--up -y"], "refusal": None},
    # Bare pose arrays: one numeric array, read as AMASS reads `poses`; no trans, no betas,
    # Y up, 30 fps assumed. The SMPL-X one as MHR's example_smplx_poses.npy (flat hands).
    {"name": "bare_smplx_example", "fixture": G + "bare/example_smplx_poses.npy",
     "model": "smplx_small", "args": [], "outputs": None, "frames": [0, 3, 7],
     "notes": ["a bare pose array (8,165): read as SMPL-X poses (55 joints, axis-angle) in the "
               "model's joint order; no translation or betas in the file", "assumed 30 fps"],
     "refusal": None,
     "wrong": [("hands_mean added to the hands", {"reading": "hands_mean_added"}),
               ("(T,3K) read as (T,3,K)", {"reading": "transposed"})]},
    {"name": "bare_smpl_triples", "fixture": G + "bare/smpl_poses.npy",
     "model": "smpl_small", "args": [], "outputs": None, "frames": [0, 5, 11],
     "notes": ["read as SMPL poses (24 joints, axis-angle)", "assumed 30 fps"],
     "refusal": None, "wrong": [BARE_TRANSPOSED]},
    {"name": "bare_smplh_matrices_pt", "fixture": G + "bare/smplh_poses.pt",
     "model": "smplh_small", "args": [], "outputs": None, "frames": [0, 4, 9],
     "notes": ["read as SMPL-H poses (52 joints, rotation matrices)", "assumed 30 fps"],
     "refusal": None,
     "wrong": [("matrices transposed (column-major)", {"reading": "matrices_transposed"})]},
    {"name": "bare_joint_positions", "fixture": G + "bare/joints.npy",
     "model": "smpl_small", "args": [], "outputs": None, "frames": None, "notes": [],
     "refusal": {"exit": 2, "message": "joint positions (constant bone lengths), not rotations: "
                                       "fit a body first, e.g. with SMPLify",
                 "forbid": ["shape file"]}},
    {"name": "bare_odd_width", "fixture": G + "bare/odd.npy",
     "model": "smpl_small", "args": [], "outputs": None, "frames": None, "notes": [],
     "refusal": {"exit": 2, "message": "holds array (8,99) at the top level; not a motion layout",
                 "forbid": ["shape file"]}},
    # Honest refusals.
    {"name": "smplifyx_vposer", "fixture": G + "fits/smplifyx_vposer_000.pkl",
     "model": "smplx_small", "args": [], "outputs": None, "frames": None, "notes": [],
     "refusal": {"exit": 2, "message": VPOSER, "forbid": ["shape file"]}},
    {"name": "latent_pose_state", "fixture": G + "fits/latent_pose_state.npz",
     "model": "smplh_small", "args": [], "outputs": None, "frames": None, "notes": [],
     "refusal": {"exit": 2, "message": VPOSER, "forbid": ["shape file"]}},
    {"name": "unknown_layout", "fixture": G + "unknown/quaternion_clip.npz",
     "model": "smpl_small", "args": [], "outputs": None, "frames": None, "notes": [],
     "refusal": {"exit": 2,
                 "message": "keys found: fps, root_positions, rotations; supported layouts: "
                            "motions.md in ",
                 "forbid": ["shape file"]}},
]


def case_by_name(name):
    return next(c for c in CASES if c["name"] == name)


# ---- The body model ---------------------------------------------------------------------------

def load_model(fixture_dir, name):
    """Model arrays (model_math.load_model_npz) plus what the layouts need: the SMPL-X split of
    shapedirs into shape and expression columns (300 + 100 in v1.1, as the model loader and
    smplx do), the hand PCA and mean, the faces."""
    path = os.path.join(fixture_dir, "models", name + ".npz")
    model = model_math.load_model_npz(path)
    raw = np.load(path, allow_pickle=False)
    cols = model["shapedirs"].shape[2]
    shape_cols = cols
    if len(model["parents"]) == 55:
        shape_cols = 300 if cols > 300 else 10
    model["exprdirs"] = model["shapedirs"][:, :, shape_cols:]
    model["shapedirs"] = model["shapedirs"][:, :, :shape_cols]
    for key in ("hands_componentsl", "hands_componentsr", "hands_meanl", "hands_meanr"):
        if key in raw.files:
            model[key] = np.asarray(raw[key], dtype=np.float64)
    model["weights_pruned"] = model_math.prune(model["weights"], INFLUENCES)
    return model


def shaped(model, betas, expression=None):
    """v_shaped = v_template + S betas (+ E psi) and the rest joints J(betas) of the exported
    skeleton (the betas-only template: expressions never move it, as --dmpl-joints fixed)."""
    betas = np.asarray(betas, dtype=np.float64).reshape(-1)
    v = model["v_template"] + model["shapedirs"][:, :, :betas.size] @ betas
    joints = model["J_regressor"] @ v
    if expression is not None and np.size(expression):
        psi = np.asarray(expression, dtype=np.float64).reshape(-1)
        v = v + model["exprdirs"][:, :, :psi.size] @ psi
    return v, joints


def lbs(model, v_shaped, joints, rots, weights):
    """Posed vertices (N,3) for local rotation matrices rots (K,3,3): docs/file-contract.md
    (SMPL, Loper et al. 2015 eqs. 1-9), written for matrices (model_math.forward takes
    axis-angle)."""
    parents = model["parents"]
    features = (rots[1:] - np.eye(3)).reshape(-1)
    v_posed = v_shaped + model["posedirs"] @ features
    world = np.zeros((len(parents), 4, 4))
    for j, p in enumerate(parents):
        local = np.eye(4)
        local[:3, :3] = rots[j]
        local[:3, 3] = joints[j] - (joints[p] if p >= 0 else 0)
        world[j] = world[p] @ local if p >= 0 else local
    skin = world.copy()
    skin[:, :3, 3] -= np.einsum("kij,kj->ki", world[:, :3, :3], joints)
    blended = np.einsum("nk,kij->nij", weights, skin)
    return np.einsum("nij,nj->ni", blended[:, :3, :3], v_posed) + blended[:, :3, 3]


def check_lbs(model):
    """lbs() agrees with model_math.forward (axis-angle) on a random pose: the two
    implementations guard each other."""
    rng = np.random.default_rng(7)
    aa = rng.uniform(-0.8, 0.8, size=(len(model["parents"]), 3))
    v, j = shaped(model, np.zeros(1))
    a = lbs(model, v, j, model_math.rodrigues(aa), model["weights_pruned"])
    b, _, _ = model_math.forward(model, v, j, aa, model["weights_pruned"])
    assert np.abs(a - b).max() < 1e-12, "lbs() and model_math.forward disagree"


def pose_vertices(model, rots, trans, betas, frames, expression=None, up=np.eye(3),
                  mirror=False):
    """Exported vertices at clip frames: LBS with the pruned weights, + trans, then the
    motion world -> Y-up turn `up` applied to the whole posed body (--up); mirror: the body
    mirrored x -> -x (a right MANO showing a left hand, HaMeR's convention)."""
    out = []
    for f in frames:
        v_shaped, joints = shaped(model, betas, None if expression is None else expression[f])
        v = lbs(model, v_shaped, joints, rots[f], model["weights_pruned"])
        if mirror:
            v = v @ MIRROR_X.T
        out.append(((v + trans[f]) @ up.T).tolist())
    return out


def reference(fps, frames, model, vertices):
    return {"fps": float(fps), "frames": list(frames), "num_vertices": len(model["v_template"]),
            "vertices": vertices}


def up_matrix(case, default):
    """--up from the case's args, else the layout's default: y (identity) or -y (camera)."""
    args = case["args"]
    value = args[args.index("--up") + 1] if "--up" in args else default
    return {"y": np.eye(3), "-y": CAMERA_TO_Y_UP,
            "z": np.array([[1.0, 0, 0], [0, 0, 1], [0, -1, 0]])}[value]


def expression_keys(case):
    args = case["args"]
    return int(args[args.index("--expression-keys") + 1]) if "--expression-keys" in args else 0


def aa_rots(axis_angle):
    """(T, J*3) or (T,J,3) axis-angle -> (T,J,3,3)."""
    aa = np.asarray(axis_angle, dtype=np.float64)
    return model_math.rodrigues(aa.reshape(aa.shape[0], -1, 3))


# ---- Motion-X ---------------------------------------------------------------------------------

def motionx(case, fixture_dir):
    """IDEA-Research/Motion-X: columns as tomato_represenation/smplx2joints.py
    process_smplx_322_data slices them (322: root_orient 0:3, pose_body 3:66, pose_hand
    66:156 = left 45 then right 45 (left_hand_pose=pose_hand[..., :45]), pose_jaw 156:159,
    face_expr 159:209, face_shape 209:309, trans 309:312, betas 312:322; 172: trans 159:162,
    betas 162:172). Hands are absolute axis-angle: the SMPL-X call of
    visualization/render_world_space_motion.py is SMPLX(use_pca=False, flat_hand_mean=True),
    and the mocap subsets copy AMASS's pose_hand unchanged (mocap-dataset-process/humanml.py
    get_smplx_322). Eyes at rest (zero_pose). Y-up world (humanml.py process_pose turns the
    AMASS Z-up root and trans into Y up). 30 fps (README: "unified in 30 fps"; humanml.py
    ex_fps = 30). face_expr: SMPL-X expression coefficients 0..49 (render_world_space_motion.py
    and humanml.py face_z_align pass face_expr[:10] as `expression`); face_shape: FLAME shape,
    no SMPL-X counterpart."""
    data = np.load(os.path.join(fixture_dir, case["fixture"])).astype(np.float64)
    t, width = data.shape
    pose = np.zeros((t, 55, 3))
    pose[:, 0] = data[:, 0:3]
    pose[:, 1:22] = data[:, 3:66].reshape(t, 21, 3)
    pose[:, 25:55] = data[:, 66:156].reshape(t, 30, 3)
    pose[:, 22] = data[:, 156:159]
    trans = data[:, 309:312] if width == 322 else data[:, 159:162]
    betas_rows = data[:, 312:322] if width == 322 else data[:, 162:172]
    expr = data[:, 159:209] if width == 322 else np.zeros((t, 0))
    keys = expression_keys(case)
    return {"rots": aa_rots(pose), "trans": trans, "betas": betas_rows.mean(0),
            "expression": expr[:, :min(keys, expr.shape[1])] if keys else None, "fps": 30.0}


# ---- MDM --------------------------------------------------------------------------------------

def rotation_6d_to_matrix(d6):
    """PyTorch3D's rotation_6d_to_matrix as MDM copies it (GuyTevet/motion-diffusion-model
    utils/rotation_conversions.py): the 6 numbers are the first two ROWS of R (its
    matrix_to_rotation_6d keeps matrix[..., :2, :]); b1 = a1/|a1|, b2 = Gram-Schmidt of a2,
    b3 = b1 x b2, R = rows (b1, b2, b3). (Zhou et al. 2019 take COLUMNS: not this.)"""
    a1, a2 = d6[..., :3], d6[..., 3:]
    b1 = a1 / np.linalg.norm(a1, axis=-1, keepdims=True)
    b2 = a2 - np.sum(b1 * a2, axis=-1, keepdims=True) * b1
    b2 = b2 / np.linalg.norm(b2, axis=-1, keepdims=True)
    b3 = np.cross(b1, b2)
    return np.stack([b1, b2, b3], axis=-2)


def mdm(case, fixture_dir):
    """MDM's *_smpl_params.npy (visualize/vis_utils.py npy2obj.save_npy: np.save of a dict,
    'motion' (25,6,T): rows 0-23 the 24 SMPL joints' 6D rotations in SMPL order (row 0 the
    global orient), row 24 = [root x, y, z, 0, 0, 0] from simplify_loc2rot.py joint2smpl).
    The tool's vertices (model/rotation2xyz.py Rotation2xyz with glob=True, translation=True,
    vertstrans=True, jointstype='vertices'): SMPL with zero betas and no transl, plus
    x_translations - x_translations[:, :, [0]], the root translation relative to frame 0.
    HumanML3D world: Y up; 20 fps (sample/generate.py: fps = 20 for HumanML3D)."""
    data = np.load(os.path.join(fixture_dir, case["fixture"]), allow_pickle=True)[()]
    motion = np.asarray(data["motion"], dtype=np.float64)
    rots = rotation_6d_to_matrix(motion[:24].transpose(2, 0, 1))
    root = motion[24, :3].T
    return {"rots": rots, "trans": root - root[0], "betas": np.zeros(10), "expression": None,
            "fps": 20.0, "tool_vertices": np.asarray(data["vertices"]).transpose(2, 0, 1)}


# ---- HaMeR ------------------------------------------------------------------------------------

def mirror_rotations(rots):
    """HaMeR's right-hand pose as a left-hand pose: S R S with S = diag(-1,1,1), i.e.
    axis-angle (x, -y, -z) (brentyi/hamer_helper _hamer_helper.py flip_rotmats negates the
    log's y and z for left hands)."""
    return MIRROR_X @ rots @ MIRROR_X


def hamer_rows(data):
    """Rows of one HaMeR output dict: (global_orient (N,1,3,3), hand_pose (N,15,3,3), betas,
    is_right (N,), camera translation (N,3)). Names: the demo's (geopavlakos/hamer demo.py:
    is_right, pred_cam_t_full) or the output dict's (hamer/models/hamer.py forward_step:
    pred_mano_params nested; batch['right'])."""
    params = data.get("pred_mano_params", data)
    right = data["is_right"] if "is_right" in data else data["right"]
    rots = np.concatenate([np.asarray(params["global_orient"], np.float64),
                           np.asarray(params["hand_pose"], np.float64)], axis=1)
    return rots, np.asarray(params["betas"], np.float64), np.asarray(right) > 0.5, \
        np.asarray(data["pred_cam_t_full"], np.float64)


def hamer_track(rots, betas, right, cam_t, model_is_right, verts=None):
    """One hand as HaMeR shows it: the RIGHT MANO (HaMeR's only model) posed with the rows'
    rotations and the mean of the rows' betas (docs: per-frame betas that differ -> their
    mean), x-negated for a left hand (demo.py: verts[:,0] = (2*is_right-1)*verts[:,0]), +
    pred_cam_t_full (the demo computes it with pred_cam[:,1] negated for left hands), in camera
    coordinates. On a LEFT MANO the pose is mirrored to it (S R S), since
    MANO_LEFT(S R S) = S MANO_RIGHT(R); when the hand's side differs from the model's, the
    body is mirrored (x -> -x, winding flipped): left hand on a right model = HaMeR's own
    mirrored mesh, right hand on a left model = S MANO_LEFT(S R S) = MANO_RIGHT(R)."""
    side = bool(right[0])
    assert np.all(right == side), "a HaMeR track mixes sides"
    pose = rots if model_is_right else mirror_rotations(rots)
    return {"rots": pose, "trans": cam_t, "betas": betas.mean(0), "expression": None,
            "fps": 30.0, "mirror": side != model_is_right, "right": side, "hamer_rots": rots,
            "betas_rows": betas, "tool_vertices": verts}


def hamer_sequence_tracks(directory):
    """Per-frame files <frame>.pkl -> tracks: in each frame, the k-th hand of a side (row
    order: the demo's per person left then right) joins track 2k + is_right; a track's clip
    starts at its first frame. Returns {id: {"frames", "rows": [(frame, row dict)]}}."""
    tracks = {}
    for path in sorted(glob.glob(os.path.join(directory, "*.pkl")),
                       key=lambda p: int(os.path.basename(p).split(".")[0].split("_")[0])):
        frame = int(os.path.basename(path).split(".")[0].split("_")[0])
        with open(path, "rb") as fh:
            data = pickle.load(fh)
        rots, betas, right, cam_t = hamer_rows(data)
        rank = {False: 0, True: 0}
        for i in range(len(right)):
            tid = 2 * rank[bool(right[i])] + int(right[i])
            rank[bool(right[i])] += 1
            tracks.setdefault(tid, []).append((frame, rots[i], betas[i], right[i], cam_t[i],
                                               np.asarray(data["pred_vertices"][i], np.float64)))
    return tracks


def hamer_decoded(track, model_is_right):
    frames = [r[0] for r in track]
    assert frames == list(range(frames[0], frames[0] + len(frames))), "a gap inside a track"
    stack = [np.stack([r[i] for r in track]) for i in range(1, 6)]
    return hamer_track(stack[0], stack[1], stack[2], stack[3], model_is_right, stack[4])


def pick_track(tracks, case):
    """--track ID, or the longest (ties to the lower id)."""
    args = case["args"]
    if "--track" in args and args[args.index("--track") + 1] != "longest":
        return int(args[args.index("--track") + 1])
    return sorted(tracks, key=lambda tid: (-len(tracks[tid]), tid))[0]


def hamer(case, fixture_dir, model_is_right):
    path = os.path.join(fixture_dir, case["fixture"])
    if case.get("sequence"):
        tracks = hamer_sequence_tracks(path)
        if case["outputs"]:
            return {".track%d" % tid: hamer_decoded(tracks[tid], model_is_right) for tid in tracks}
        return hamer_decoded(tracks[pick_track(tracks, case)], model_is_right)
    data = dict(np.load(path, allow_pickle=False))
    rots, betas, right, cam_t = hamer_rows(data)
    return hamer_track(rots, betas, right, cam_t, model_is_right,
                       np.asarray(data["pred_vertices"], np.float64))


# ---- BEAT2 / EMAGE ----------------------------------------------------------------------------

def beat2(case, fixture_dir):
    """PantoMatrix/PantoMatrix emage_utils/motion_io.py beat_format_save / beat_format_load:
    poses (T,165) = 55 SMPL-X joints (emage_utils/fast_render.py: global 0:3, body 3:66, jaw
    66:69, leye 69:72, reye 72:75, left hand 75:120, right hand 120:165), betas (300,),
    expressions (T,100), trans (T,3), mocap_frame_rate 30. The SMPL-X call
    (emage_utils/npz2pose.py _get_smplx_model: use_pca=False, flat_hand_mean=False,
    num_betas=300, num_expression_coeffs=100) adds hands_meanl/r to the hand poses (smplx
    SMPLX.forward: full_pose += pose_mean). Y-up world (beat_format_save's default trans puts
    the rest feet at the origin of a Y-up body)."""
    data = np.load(os.path.join(fixture_dir, case["fixture"]), allow_pickle=False)
    return {"poses": np.asarray(data["poses"], np.float64).reshape(-1, 55, 3),
            "trans": np.asarray(data["trans"], np.float64),
            "betas": np.asarray(data["betas"], np.float64),
            "expression": np.asarray(data["expressions"], np.float64),
            "fps": float(data["mocap_frame_rate"])}


def with_hands_mean(poses, model):
    """smplx's flat_hand_mean=False: the model's hands_mean{l,r} added to the 45-d hands."""
    out = poses.copy()
    out[:, 25:40] += model["hands_meanl"].reshape(15, 3)
    out[:, 40:55] += model["hands_meanr"].reshape(15, 3)
    return out


# ---- Fits in camera coordinates ---------------------------------------------------------------

def camera_fit(case, fixture_dir, model):
    """A fit with smplx's names (vchoutas/smplx SMPLX.forward, axis-angle input, full 45-d
    hands with hands_mean added: flat_hand_mean=False, as core/motions/motion_fit.h), transl
    added to the vertices; in camera coordinates (OpenCV: x right, y down, z forward)."""
    with open(os.path.join(fixture_dir, case["fixture"]), "rb") as fh:
        data = pickle.load(fh)
    t = data["body_pose"].shape[0]
    pose = np.zeros((t, 55, 3))
    pose[:, 0] = data["global_orient"]
    pose[:, 1:22] = np.asarray(data["body_pose"], np.float64).reshape(t, 21, 3)
    pose[:, 22] = data["jaw_pose"]
    pose[:, 25:40] = np.asarray(data["left_hand_pose"], np.float64).reshape(t, 15, 3)
    pose[:, 40:55] = np.asarray(data["right_hand_pose"], np.float64).reshape(t, 15, 3)
    return {"rots": aa_rots(with_hands_mean(pose, model)),
            "trans": np.asarray(data["transl"], np.float64),
            "betas": np.asarray(data["betas"], np.float64)[0], "expression": None, "fps": 30.0}


def smplifyx(case, fixture_dir, model):
    """vchoutas/smplify-x result pickle (smplifyx/fit_single_frame.py): SMPL-X parameters
    with PCA hands (cfg_files/fit_smplx.yaml: use_pca, num_pca_comps 12, flat_hand_mean
    False: hand = coeffs @ hands_components[:12] + hands_mean, vchoutas/smplx SMPLX.forward),
    no transl (smplifyx/main.py create_transl=False): the body is placed in the camera by
    camera_rotation R_c and camera_translation t_c (smplifyx/camera.py
    PerspectiveCamera.forward: p_cam = R_c p + t_c). As a root rotation and translation:
    R_0' = R_c R_0, trans = R_c J_0 + t_c - J_0 (J_0 the rest root joint); R_c is the
    identity in SMPLify-X (only the translation is optimised)."""
    with open(os.path.join(fixture_dir, case["fixture"]), "rb") as fh:
        data = pickle.load(fh)
    pose = np.zeros((1, 55, 3))
    pose[:, 0] = data["global_orient"]
    pose[:, 1:22] = np.asarray(data["body_pose"], np.float64).reshape(1, 21, 3)
    pose[:, 22] = data["jaw_pose"]
    pose[:, 23] = data["leye_pose"]
    pose[:, 24] = data["reye_pose"]
    for side, first in (("l", 25), ("r", 40)):
        coeffs = np.asarray(data["left_hand_pose" if side == "l" else "right_hand_pose"],
                            np.float64)
        comps = model["hands_components" + side][:coeffs.shape[1]]
        pose[:, first:first + 15] = (coeffs @ comps).reshape(1, 15, 3)
    rots = aa_rots(with_hands_mean(pose, model))
    betas = np.asarray(data["betas"], np.float64)[0]
    r_c = np.asarray(data["camera_rotation"], np.float64)[0]
    t_c = np.asarray(data["camera_translation"], np.float64)[0]
    j0 = shaped(model, betas)[1][0]
    rots[:, 0] = r_c @ rots[:, 0]
    return {"rots": rots, "trans": (r_c @ j0 + t_c - j0)[None], "betas": betas,
            "expression": None, "fps": 30.0}


# ---- Bare pose arrays --------------------------------------------------------------------------

def load_array(path):
    """The file's one array: np.load for .npy, torch.load for torch.save of a tensor."""
    if path.endswith(".pt"):
        import torch
        return torch.load(path, map_location="cpu", weights_only=True).numpy().astype(np.float64)
    return np.load(path, allow_pickle=False).astype(np.float64)


def bare(case, fixture_dir, model):
    """A bare pose array, read as AMASS's `poses` (human_body_prior BodyModel: full_pose in the
    model's joint order, SMPL-X root, body 1-21, jaw, eyes, left hand 25-39, right 40-54;
    hands absolute as MHR's tools/smpl_mhr_conversion/example.py poses them with
    smplx.SMPLX(flat_hand_mean=True)): (T,3K) and (T,K,3) axis-angle, (T,K,3,3) row-major
    matrices (R[i][j] at [..., i, j]). No translation, no betas, 30 fps assumed. Wrong
    readings (case["reading"]): hands_mean_added (flat_hand_mean=False), transposed (the
    numbers of a frame taken as (3,K)), matrices_transposed (column-major matrices)."""
    data = load_array(os.path.join(fixture_dir, case["fixture"]))
    t, k = data.shape[0], len(model["parents"])
    reading = case.get("reading")
    if data.ndim == 4:
        rots = data.swapaxes(-1, -2) if reading == "matrices_transposed" else data
    else:
        aa = data.reshape(t, 3, k).transpose(0, 2, 1) if reading == "transposed" \
            else data.reshape(t, k, 3)
        if reading == "hands_mean_added":
            aa = with_hands_mean(aa, model)
        rots = aa_rots(aa)
    return {"rots": rots, "trans": np.zeros((t, 3)), "betas": np.zeros(1), "expression": None,
            "fps": 30.0}


def wrong_expected(case, fixture_dir, change):
    """The reference of a plausible wrong reading of the case's file: change {"reading": name}
    names a reading the case's decoder knows (bare: hands_mean_added, transposed,
    matrices_transposed)."""
    c = dict(case)
    c.update(change)
    return expected(c, fixture_dir)


# ---- Expected vertices ------------------------------------------------------------------------

def decoded(case, fixture_dir, model):
    """The motion after all of the tool's conventions: rots (T,K,3,3) in the model's joint
    order, trans (T,3) in the motion's world, betas, expression (T,E) or None, fps, the
    layout's default up axis, mirror (a body mirrored x -> -x)."""
    name = case["name"]
    if name.startswith("motionx"):
        d, up = motionx(case, fixture_dir), "y"
    elif name.startswith("mdm"):
        d, up = mdm(case, fixture_dir), "y"
    elif name.startswith("hamer"):
        # The model's side from its file stem, as the decoder spec says (MANO_LEFT.pkl).
        d, up = hamer(case, fixture_dir, model_is_right="left" not in case["model"].lower()), "-y"
    elif name.startswith("beat2"):
        b = beat2(case, fixture_dir)
        keys = expression_keys(case)
        d = {"rots": aa_rots(with_hands_mean(b["poses"], model)), "trans": b["trans"],
             "betas": b["betas"], "fps": b["fps"],
             "expression": b["expression"][:, :keys] if keys else None}
        up = "y"
    elif name.startswith("fit_camera"):
        d, up = camera_fit(case, fixture_dir, model), "y"
    elif name.startswith("smplifyx"):
        d, up = smplifyx(case, fixture_dir, model), "-y"
    elif name.startswith("bare"):
        d, up = bare(case, fixture_dir, model), "y"
    else:
        raise KeyError("no decoder for case " + name)
    return d, up


def tool_consistency(case, model, d, fixture_dir):
    """The file's own vertices (MDM's 'vertices', HaMeR's pred_vertices) against this reading
    of its parameters, with all of the model's weights as the tool skins: guards the reading
    (6D rows, rotation order, mirroring) with numbers the writing side computed. Returns the
    largest difference (m); float32 files agree to ~1e-6."""
    tool = d.get("tool_vertices")
    if tool is None:
        return 0.0
    worst = 0.0
    if case["name"].startswith("mdm"):
        v_shaped, joints = shaped(model, d["betas"])
        for f in range(len(tool)):
            mine = lbs(model, v_shaped, joints, d["rots"][f], model["weights"]) + d["trans"][f]
            worst = max(worst, np.abs(mine - tool[f]).max())
        return worst
    right = load_model(fixture_dir, "mano_small")        # pred_vertices: the right MANO, per-frame
    for f in range(len(tool)):                            # betas, un-mirrored, no camera
        v_shaped, joints = shaped(model, d["betas_rows"][f])
        mine = lbs(model, v_shaped, joints, d["rots"][f], model["weights"])
        if d["mirror"]:
            mine = mine @ MIRROR_X.T
        theirs = tool[f] if d["right"] else tool[f] @ MIRROR_X.T
        worst = max(worst, np.abs(mine - theirs).max())
        v_r, j_r = shaped(right, d["betas_rows"][f])
        plain = lbs(right, v_r, j_r, d["hamer_rots"][f], right["weights"])
        worst = max(worst, np.abs(plain - tool[f]).max())
    return worst


def one_reference(case, model, d, up, frames, fixture_dir):
    err = tool_consistency(case, model, d, fixture_dir)
    assert err < 1e-5, "%s: the file's own vertices differ from this reading by %g m" % (
        case["name"], err)
    verts = pose_vertices(model, d["rots"], d["trans"], d["betas"], frames, d.get("expression"),
                          up_matrix(case, up), d.get("mirror", False))
    return reference(d["fps"], frames, model, verts)


def expected(case, fixture_dir):
    assert case["refusal"] is None, "a refusal has no expected vertices"
    model = load_model(fixture_dir, case["model"])
    check_lbs(model)
    d, up = decoded(case, fixture_dir, model)
    if case["outputs"]:
        return {s: one_reference(case, model, d[s], up, case["frames"][s], fixture_dir)
                for s in case["outputs"]}
    return one_reference(case, model, d, up, case["frames"], fixture_dir)


def authors_expression_cost(case, fixture_dir):
    """max over baked frames and vertices of |LBS(J') - LBS(J)| with J = J(betas) (the
    exported skeleton) and J' = J_regressor (v_shaped + E psi) (the published SMPL-X math),
    pruned weights; 0 when the case bakes no expression."""
    model = load_model(fixture_dir, case["model"])
    d, _ = decoded(case, fixture_dir, model)
    if d.get("expression") is None:
        return 0.0
    worst = 0.0
    for f in range(len(d["rots"])):
        v, joints = shaped(model, d["betas"], d["expression"][f])
        fixed = lbs(model, v, joints, d["rots"][f], model["weights_pruned"])
        published = lbs(model, v, model["J_regressor"] @ v, d["rots"][f], model["weights_pruned"])
        worst = max(worst, float(np.linalg.norm(fixed - published, axis=1).max()))
    return worst


# ---- Today's equivalent -----------------------------------------------------------------------

def equivalent(case, fixture_dir, work_dir):
    """Writes the motion in today's terms (see the module comment); returns one entry per
    output: {"suffix", "motion", "model", "args"}; None for a refusal."""
    if case["refusal"] is not None:
        return None
    model = load_model(fixture_dir, case["model"])
    d, up = decoded(case, fixture_dir, model)
    tracks = {s: d[s] for s in case["outputs"]} if case["outputs"] else {"": d}
    out = []
    for suffix, tr in tracks.items():
        name, rots = case["model"], tr["rots"].copy()
        if tr.get("mirror"):   # a mirrored body: today only as the model of the hand's side
            name = "mano_small" if tr["right"] else "mano_left_small"
            rots = tr["hamer_rots"] if tr["right"] else mirror_rotations(tr["hamer_rots"])
        eq_model = load_model(fixture_dir, name)
        trans = tr["trans"].copy()
        turn = up_matrix(case, up)
        if not np.allclose(turn, np.eye(3)):     # pre-rotate the whole posed body into Y up
            j0 = shaped(eq_model, tr["betas"])[1][0]
            rots[:, 0] = turn @ rots[:, 0]
            trans = (turn @ (j0 + trans).T).T - j0
        path = os.path.join(work_dir, case["name"] + suffix + "_equivalent.npz")
        arrays = {"poses": rots, "trans": trans, "betas": tr["betas"],
                  "fps": np.float64(tr["fps"])}
        args = ["--up", "y"]
        if tr.get("expression") is not None:
            basis = os.path.join(work_dir, case["name"] + "_expression_basis.npz")
            np.savez(basis, eigvec=eq_model["exprdirs"][:, :, :tr["expression"].shape[1]])
            arrays["dmpls"] = tr["expression"]
            args += ["--dmpl", basis, "--dmpl-joints", "fixed"]
        np.savez(path, **arrays)
        out.append({"suffix": suffix, "motion": path, "model": name, "args": args})
    return out
