"""Test cases for the video-to-motion layouts (docs/motions.md "Video-to-motion layouts"), and
the expected posed vertices of each, computed in numpy from the writing tool's conventions and the
body model's math (tests/roundtrip/model_math.py), never from our C++.

Fixtures: tests/fixtures/make_video_layouts.py (FIXTURE_DIR/layouts/video/...). Runner:
tests/cli/layouts/run_cases.py --cases video.

Each case: name, fixture (relative to FIXTURE_DIR; a folder is given to --motion-sequence), model,
args, outputs (suffixes when --track all writes several files, else None), frames (three
clip-relative frames), notes (substrings stderr must contain), absent (substrings it must not
contain), source (what the sidecar's motion_source must say, or None), refusal (None or
{"exit", "message"}), wrong (plausible wrong readings: (label, {flag: value} args replaced or
{"reading": name}); run_cases.py checks each is >= 1 mm from the right reference at every frame).

expected(case, fixture_dir) -> {"fps", "frames", "num_vertices", "vertices"} (or {suffix: that}).
equivalent(case, fixture_dir) -> [(suffix, npz arrays)] in our terms (AMASS-style poses (T,3K) in the
model's joint order, trans (T,3) with the body already turned Y-up, betas, fps), to export with
today's smpl-export and `--up y`, or a string saying why the case cannot be expressed today.

The composition every layout reduces to, per clip frame t (Y-up output, metres):
    v_out = A_t (LBS(pose_t, betas) + transl_t) + b_t
with LBS the model's math with the root joint at J_0 (docs/file-contract.md), transl_t the tool's
own translation composed as the tool's body-model call composes it, and (A_t, b_t) the frame
change: the camera frame's half turn about x (A = diag(1,-1,-1)), a world-from-camera transform
(TRAM), EasyMocap's Rh/Th followed by Z-up -> Y-up, or the identity.
"""
import base64
import glob
import io
import json
import os
import pickle
import sys

import joblib
import numpy as np
import torch
from scipy.spatial.transform import Rotation

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "roundtrip"))
import model_math  # noqa: E402

CAMERA_TO_UP = np.diag([1.0, -1.0, -1.0])  # --up -y: (x, y, z) -> (x, -y, -z)
Z_UP_TO_Y_UP = np.array([[1.0, 0, 0], [0, 0, 1], [0, -1, 0]])  # --up z: -90 degrees about x
V = "layouts/video/"
HANDS = V + "hands/"
# The closing note of an export with an animated expression (the exporter's wording,
# exporter/animation.cpp clipNotes; docs/motions.md, SMPLer-X); its number is checked against
# authors_expression_cost_mm (run_cases.py: `numbers` of the reference).
EXPRESSION_COST = (r"the expression is baked with the betas-only skeleton \(fixed joints\); against the authors' "
                   r"math, where the joints follow the expression, this costs up to ([0-9.]+) mm")


def case(name, fixture, model, frames, notes=(), args=(), outputs=None, absent=(), source=None, refusal=None,
         wrong=()):
    """`wrong`: plausible wrong readings [(label, change)] (see wrong_expected); each must be >= 1 mm away."""
    return {"name": name, "fixture": fixture, "model": model, "args": list(args), "outputs": outputs,
            "frames": list(frames), "notes": list(notes), "absent": list(absent), "source": source,
            "refusal": refusal, "wrong": list(wrong)}


def refused(name, fixture, model, message, args=()):
    return case(name, fixture, model, [], args=args, refusal={"exit": 2, "message": message})


TRACKS_ALL = [".track0.glb", ".track1.glb", ".track2.glb"]
CASES = [
    # WHAM: tracks 0 (frames 0-17), 1 (5-29), 2 (2-26); 1 and 2 tie on length -> 1.
    case("wham_world", V + "wham/wham_output.pkl", "smpl_small", [0, 12, 24],
         ["read as WHAM output", "track 1 of 3 (source frames 5-29, the longest)",
          "other tracks: 0 (0-17), 2 (2-26)", "world frame", "assumed 30 fps", "their mean"],
         absent=["camera frame"], source={"layout": "wham", "track": "1", "frames": [5, 29]}),
    case("wham_track0_fps25", V + "wham/wham_output.pkl", "smpl_small", [0, 9, 17],
         ["track 0 of 3 (source frames 0-17)", "world frame"], args=["--track", "0", "--source-fps", "25"],
         absent=["assumed"], source={"layout": "wham", "track": "0", "frames": [0, 17]}),
    case("wham_incam", V + "wham/wham_output.pkl", "smpl_small", [0, 12, 24],
         ["camera frame", "track 1 of 3"], args=["--source-params", "incam"], absent=["world frame"]),
    case("wham_incam_up_y", V + "wham/wham_output.pkl", "smpl_small", [0, 12, 24], ["track 1 of 3"],
         args=["--source-params", "incam", "--up", "y"], absent=["camera frame"]),
    case("wham_all", V + "wham/wham_output.pkl", "smpl_small", [0, 8, 17],
         ["track 0 of 3", "track 1 of 3", "track 2 of 3"], args=["--track", "all"], outputs=TRACKS_ALL),
    # VIBE: persons 1 (frames 0-15), 2 (3-24); no 3-D translation; camera frame.
    case("vibe", V + "vibe/vibe_output.pkl", "smpl_small", [0, 10, 21],
         ["read as VIBE output", "track 2 of 2 (source frames 3-24, the longest)", "other tracks: 1 (0-15)",
          "no 3-D translation", "camera frame", "assumed 30 fps"],
         source={"layout": "vibe", "track": "2", "frames": [3, 24]}),
    case("vibe_track1", V + "vibe/vibe_output.pkl", "smpl_small", [0, 7, 15], ["track 1 of 2 (source frames 0-15)"],
         args=["--track", "1"]),
    # PHALP / 4D-Humans: tracks 1 (0-19), 2 (3-16, no detection at 8-9), 3 (10-19).
    case("phalp", V + "phalp/demo_video.pkl", "smpl_small", [0, 10, 19],
         ["read as PHALP output", "track 1 of 3 (source frames 0-19, the longest)", "other tracks: 2 (3-16), 3 (10-19)",
          "camera translation", "camera frame", "assumed 30 fps"],
         source={"layout": "phalp", "track": "1", "frames": [0, 19]}),
    case("phalp_gap", V + "phalp/demo_video.pkl", "smpl_small", [0, 6, 13],
         ["track 2 of 3 (source frames 3-16)", "source frames without a detection: 2"], args=["--track", "2"]),
    case("phalp_all", V + "phalp/demo_video.pkl", "smpl_small", [0, 5, 9], ["track 3 of 3"], args=["--track", "all"],
         outputs=[".track1.glb", ".track2.glb", ".track3.glb"]),
    # GVHMR: SMPL-X, hands at hands_mean; global (Y up) preferred, incam on request.
    case("gvhmr_global", V + "gvhmr/hmr4d_results.pt", "smplx_small", [0, 11, 23],
         ["read as GVHMR output", "world frame", "hands_mean", "assumed 30 fps", "their mean"], absent=["camera frame"],
         source={"layout": "gvhmr", "track": None, "frames": [0, 23]}),
    case("gvhmr_incam", V + "gvhmr/hmr4d_results.pt", "smplx_small", [0, 11, 23], ["camera frame", "hands_mean"],
         args=["--source-params", "incam"]),
    case("gvhmr_pkl", V + "gvhmr/hmr4d_results.pkl", "smplx_small", [0, 11, 23],
         ["read as GVHMR output", "world frame"]),
    # GVHMR with fingers merged in as Mano2Smpl-X does: absolute finger rotations, not hands_mean.
    case("gvhmr_hands", V + "gvhmr_hands/hmr4d_results.pt", "smplx_small", [0, 11, 23],
         ["read as GVHMR output", "hands from 'left_hand_pose' and 'right_hand_pose'", "flat_hand_mean=True"],
         absent=["hands at the model's hands_mean"], wrong=[("hands ignored", {"reading": "no_hands"})]),
    case("gvhmr_hands_incam", V + "gvhmr_hands/hmr4d_results.pt", "smplx_small", [0, 11, 23],
         ["camera frame", "hands from 'left_hand_pose'"], args=["--source-params", "incam"]),
    # MHR's converter output for SAM 3D Body (docs/motions.md "SAM 3D Body"): SMPL-X parameters of a
    # flat_hand_mean=True model, identical float32 betas rows, exported with --flat-hand-mean.
    case("mhr_smplx_npz", V + "mhr_smplx/smplx_params.npz", "smplx_small", [0, 2, 5], ["assumed 30 fps"],
         args=["--flat-hand-mean"], absent=["different rows", "their mean"], wrong=[("hands_mean added", {"reading": "other_hands_mean"})]),
    case("mhr_smplx_pt", V + "mhr_smplx/smplx_params.pt", "smplx_small", [0, 2, 5], ["assumed 30 fps"],
         args=["--flat-hand-mean"], absent=["different rows", "their mean"], wrong=[("hands_mean added", {"reading": "other_hands_mean"})]),
    # Without the flag the hands are read as smplx's default model does: hands_mean added.
    case("mhr_smplx_default_mean", V + "mhr_smplx/smplx_params.npz", "smplx_small", [0, 2, 5],
         wrong=[("flat hands", {"reading": "other_hands_mean"})]),
    # --hands: HaMeR tracks drive GVHMR's fingers (docs/motions.md "Combining hand tracks"); a folder of
    # per-image outputs holds both hands (tracks 0 left, 1 right); "{fixtures}" is the fixture folder.
    case("hands_fingers", V + "gvhmr/hmr4d_results.pt", "smplx_small", [0, 11, 23],
         [HANDS + "hamer: track 0: the left hand's fingers (absolute MANO rotations",
          HANDS + "hamer: track 1: the right hand's fingers", "its translation, betas and rate are not used",
          HANDS + "hamer: read as HaMeR output"],
         args=["--hands", "{fixtures}/" + HANDS + "hamer"], absent=["keep the body clip's hand", "assumed 30 fps;"]),
    case("hands_two_files", V + "gvhmr/hmr4d_results.pt", "smplx_small", [0, 11, 23],
         [HANDS + "left.npz: the left hand's fingers", HANDS + "right.npz: the right hand's fingers"],
         args=["--source-params", "incam", "--hands", "{fixtures}/" + HANDS + "right.npz",
               "--hands", "{fixtures}/" + HANDS + "left.npz"]),
    case("hands_wrist", V + "gvhmr/hmr4d_results.pt", "smplx_small", [0, 11, 23],
         ["the left hand's wrist and fingers", "the right hand's wrist and fingers", "Mano2Smpl-X"],
         args=["--source-params", "incam", "--hands", "{fixtures}/" + HANDS + "hamer", "--hands-wrist"]),
    # An SMPL-H body (AMASS, Z up, its own fingers bent) takes both hands from the HaMeR folder.
    case("hands_smplh", HANDS + "amass_smplh.npz", "smplh_small", [0, 11, 23],
         [HANDS + "hamer: track 0: the left hand's fingers", HANDS + "hamer: track 1: the right hand's fingers"],
         args=["--hands", "{fixtures}/" + HANDS + "hamer"],
         absent=["keep the body clip's hand"]),
    case("hands_smplh_left", HANDS + "amass_smplh.npz", "smplh_small", [0, 11, 23],
         [HANDS + "left.npz: the left hand's fingers"], args=["--hands", "{fixtures}/" + HANDS + "left.npz"]),
    # No left hand at frames 7, 21-23, no file at frame 10: those frames keep GVHMR's hands (hands_mean).
    case("hands_gap", V + "gvhmr/hmr4d_results.pt", "smplx_small", [7, 10, 15],
         ["left hand's fingers", "5 of 24 frames have no frame of this track and keep the body clip's hand",
          "1 of 24 frames have no frame of this track"],
         args=["--hands", "{fixtures}/" + HANDS + "hamer_gap"], absent=["each holds the previous one"]),
    case("hands_gap_wrist", V + "gvhmr/hmr4d_results.pt", "smplx_small", [6, 10, 21],
         ["the left hand's wrist and fingers", "5 of 24 frames"],
         args=["--source-params", "incam", "--hands", "{fixtures}/" + HANDS + "hamer_gap", "--hands-wrist"]),
    # Today's reading of GVHMR's global parameters flattened into an npz (an SMPL-X fit: hands at rest).
    case("gvhmr_flat_today", V + "gvhmr/gvhmr_flat.npz", "smplx_small", [0, 11, 23],
         ["assumed 30 fps", "their mean"]),
    # TRAM: hps_track_0 (frames 2-29) with camera.npy (world, Y up); without it, camera frame.
    case("tram_world", V + "tram/seq/hps/hps_track_0.npy", "smpl_small", [0, 14, 27],
         ["read as TRAM output", "world frame", "camera.npy", "assumed 30 fps", "their mean"], absent=["camera frame"],
         source={"layout": "tram", "track": None, "frames": [2, 29]}),
    case("tram_incam", V + "tram/seq/hps/hps_track_0.npy", "smpl_small", [0, 14, 27], ["camera frame"],
         args=["--source-params", "incam"]),
    case("tram_no_camera", V + "tram_cam/hps_track_0.npy", "smpl_small", [0, 8, 15], ["camera frame", "camera.npy"]),
    # ROMP / BEV video_results.npz.
    case("romp", V + "romp/video_results.npz", "smpl_small", [0, 11, 21],
         ["read as ROMP output", "track 1 of 2 (source frames 0-21, the longest)", "other tracks: 2 (6-17)",
          "camera frame", "assumed 24 fps"], source={"layout": "romp", "track": "1", "frames": [0, 21]}),
    case("romp_track2", V + "romp/video_results.npz", "smpl_small", [0, 6, 11], ["track 2 of 2 (source frames 6-17)"],
         args=["--track", "2"]),
    case("romp_notrack", V + "romp_notrack/video_results.npz", "smpl_small", [0, 5, 9], ["person 0 of each frame"]),
    case("bev", V + "bev/video_results.npz", "smpl_small", [0, 6, 11],
         ["read as BEV output", "mid-hip", "age", "camera frame", "assumed 24 fps"]),
    # EasyMocap: persons 0 (frames 0-19), 1 (4-13); Z-up world; a folder is a sequence.
    case("easymocap_seq", V + "easymocap/smpl", "smpl_small", [0, 10, 19],
         ["read as EasyMocap output", "20 files joined (frames 0-19)", "track 0 of 2 (source frames 0-19, the longest)",
          "other tracks: 1 (4-13)", "Z up", "assumed 30 fps", "their mean"],
         source={"layout": "easymocap", "track": "0", "frames": [0, 19]}),
    case("easymocap_seq_track1", V + "easymocap/smpl", "smpl_small", [0, 5, 9], ["track 1 of 2 (source frames 4-13)"],
         args=["--track", "1"]),
    case("easymocap_one_file", V + "easymocap/smpl/000007.json", "smpl_small", [0, 0, 0],
         ["track 0 of 2 (source frames 7-7, the longest)", "other tracks: 1 (7-7)", "Z up"], absent=["assumed"]),
    # SMPLer-X: one npz per frame and detection; person 0 frames 3-24 (none at 11), person 1 frames 6-14.
    case("smplerx_seq", V + "smplerx/smplx", "smplx_small", [0, 8, 21],
         ["read as SMPLer-X output", "30 files joined (frames 3-24)", "track 0 of 2 (source frames 3-24, the longest)",
          "source frames without a detection: 1", "detection index", "camera frame", "not baked", "their mean"],
         source={"layout": "smplerx", "track": "0", "frames": [3, 24]}),
    case("smplerx_track1", V + "smplerx/smplx", "smplx_small", [0, 4, 8], ["track 1 of 2 (source frames 6-14)"],
         args=["--track", "1"]),
    case("smplerx_expression", V + "smplerx/smplx", "smplx_small", [0, 8, 21], ["track 0 of 2"],
         args=["--expression-keys", "10"], absent=["not baked"]),
    # A format that works today keeps its conventions.
    case("amass_smplh_today", "motions/amass_smplh.npz", "smplh_small", [0, 100, 239], []),
    # Refusals: exit 2, one line on stderr, no output.
    refused("bev_infant", V + "bev_infant/video_results.npz", "smpl_small", "SMIL"),
    refused("wham_no_such_track", V + "wham/wham_output.pkl", "smpl_small", "no track 7 (tracks: 0, 1, 2)",
            args=["--track", "7"]),
    refused("hostile_pickle", V + "hostile/wham_output.pkl", "smpl_small", "refusing pickle global"),
    refused("easymocap_smplx", V + "easymocap_smplx/000000.json", "smplx_small", "'handl'"),
    refused("phalp_no_track", V + "phalp_empty/demo_video.pkl", "smpl_small", "no tracked person"),
    refused("gvhmr_bad_shape", V + "gvhmr_bad/hmr4d_results.pt", "smplx_small",
            "'smpl_params_global/body_pose' has shape (24,60)"),
    refused("gvhmr_hands_bad_shape", V + "gvhmr_hands_bad/hmr4d_results.pt", "smplx_small",
            "'smpl_params_global/left_hand_pose' is of shape (24,44)"),
    refused("sam3d_npz", V + "sam3d/person0.npz", "smplx_small", "MHR parameters (SAM 3D Body), not SMPL"),
    refused("sam3d_list_pkl", V + "sam3d/outputs.pkl", "smplx_small", "tools/mhr_smpl_conversion"),
    # Models that are not SMPL-family, named (the model given as a fixture path).
    refused("star_model", V + "wham/wham_output.pkl", V + "not_smpl/STAR_NEUTRAL.npz", "a STAR model file"),
    refused("supr_model_npy", V + "wham/wham_output.pkl", V + "not_smpl/supr_male.npy", "a SUPR model file"),
    refused("supr_model_npz", V + "wham/wham_output.pkl", V + "not_smpl/supr_unconstrained.npz",
            "a SUPR model file"),
    refused("skel_model", V + "wham/wham_output.pkl", V + "not_smpl/skel_male.pkl", "a SKEL model file"),
    refused("hsmr_poses", V + "not_smpl/HSMR-walk.npz", "smpl_small", "SKEL pose parameters"),
    refused("vibe_no_world", V + "vibe/vibe_output.pkl", "smpl_small", "no world-frame parameters",
            args=["--source-params", "global"]),
    # PromptHMR results.pkl: people 1 (frames 0-19), 2 (6-29); SMPL-X with absolute hands; world Y up.
    case("prompthmr_world", V + "prompthmr/results.pkl", "smplx_small", [0, 9, 19],
         ["read as PromptHMR output", "track 2 of 2 (source frames 6-29, the longest)", "other tracks: 1 (0-19)",
          "world frame ('smplx_world'", "absolute finger rotations", "scene camera from 'camera_world'",
          "ignored: camera,", "smplx_cam/rotmat", "assumed 30 fps"],
         absent=["camera frame"], source={"layout": "prompthmr", "track": "2", "frames": [6, 29]},
         wrong=[("the other track", {"--track": "1"}), ("smplx_cam instead of smplx_world",
                                                        {"--source-params": "incam"}),
                ("hands ignored", {"reading": "no_hands"})]),
    case("prompthmr_track1", V + "prompthmr/results.pkl", "smplx_small", [0, 7, 19],
         ["track 1 of 2 (source frames 0-19)"], args=["--track", "1", "--source-fps", "25"],
         source={"layout": "prompthmr", "track": "1", "frames": [0, 19]},
         wrong=[("hands ignored", {"reading": "no_hands"})]),
    case("prompthmr_incam", V + "prompthmr/results.pkl", "smplx_small", [0, 11, 23],
         ["camera frame", "no finger joints", "hands stay flat"], args=["--source-params", "incam"],
         absent=["world frame"], wrong=[("smplx_world", {"--source-params": "global"})]),
    case("prompthmr_all", V + "prompthmr/results.pkl", "smplx_small", [0, 10, 19], ["track 1 of 2", "track 2 of 2"],
         args=["--track", "all"], outputs=[".track1.glb", ".track2.glb"]),
    # PromptHMR world4d.mcs (and the same JSON as world4d.glb): bodies 0 (frames 0-19), 1 (6-29), 25 fps.
    case("mcs", V + "prompthmr/world4d.mcs", "smplx_small", [0, 12, 19],
         ["read as a Meshcapade scene", "track 1 of 2 (source frames 6-29, the longest)", "other tracks: 0 (0-19)",
          "scene camera from node 1 (animated, frames 0-29)"], absent=["assumed"],
         source={"layout": "mcs", "track": "1", "frames": [6, 29]},
         wrong=[("the other track", {"--track": "0"})]),
    case("mcs_glb_copy", V + "prompthmr/world4d.glb", "smplx_small", [0, 9, 19], ["read as a Meshcapade scene"],
         args=["--track", "0"], source={"layout": "mcs", "track": "0", "frames": [0, 19]}),
    # Multi-HMR: one npz per image, two persons each (rows 0, 1); camera frame; a folder is a sequence.
    case("multihmr_seq", V + "multihmr", "smplx_small", [0, 5, 11],
         ["read as Multi-HMR output", "track 0 of 2 (source frames 0-11, the longest)",
          "transl_pelvis", "ignored: transl, scores, loc, dist", "camera frame", "assumed 30 fps", "their mean",
          "13 files joined (frames 0-12)", "images without a person contribute no frame"],
         source={"layout": "multihmr", "track": "0", "frames": [0, 11]},
         wrong=[("the other person", {"--track": "1"}), ("transl instead of transl_pelvis", {"reading": "transl"}),
                ("transl_pelvis as the SMPL-X transl", {"reading": "pelvis_as_transl"}),
                ("hands ignored", {"reading": "no_hands"})]),
    case("multihmr_one", V + "multihmr/000004.npz", "smplx_small", [0, 0, 0],
         ["read as Multi-HMR output (2 persons", "track 1 of 2"], args=["--track", "1"],
         wrong=[("the other person", {"--track": "0"})]),
    # Hostile PromptHMR / .mcs / Multi-HMR files: one line, exit 2, nothing written.
    refused("prompthmr_bad_shape", V + "prompthmr_bad/results_shape.pkl", "smplx_small",
            "people 2: 'smplx_world/pose' has shape (24,160)"),
    refused("prompthmr_nan", V + "prompthmr_bad/results_nan.pkl", "smplx_small", "NaN"),
    refused("prompthmr_no_track", V + "prompthmr/results.pkl", "smplx_small", "no track 3 (tracks: 1, 2)",
            args=["--track", "3"]),
    refused("mcs_truncated", V + "prompthmr_bad/truncated.mcs", "smplx_small", "base64 data is truncated"),
    refused("mcs_huge_length", V + "prompthmr_bad/huge_length.mcs", "smplx_small",
            "buffer 0 declares 1099511627776 bytes"),
    refused("mcs_nested", V + "prompthmr_bad/nested.mcs", "smplx_small", "nested deeper"),
    refused("mcs_presence", V + "prompthmr_bad/presence.mcs", "smplx_small",
            "'frame_presence' [6, 12) spans 6 frames; its body has 24"),
    refused("mcs_nan_body", V + "prompthmr_bad/nan_body.mcs", "smplx_small", "'bodyPose' contains NaN"),
    refused("mcs_binary_glb", V + "prompthmr_bad/binary.glb", "smplx_small", "a binary glTF (GLB)"),
    refused("multihmr_bad_shape", V + "multihmr_bad/rotvec_shape.npz", "smplx_small",
            "'rotvec' has shape (2,52,3)"),
    refused("multihmr_inf", V + "multihmr_bad/pelvis_inf.npz", "smplx_small", "'transl_pelvis' contains NaN"),
    refused("multihmr_persons", V + "multihmr_bad/persons.npz", "smplx_small", "'shape' has shape (1,10)"),
    refused("multihmr_empty", V + "multihmr_bad/empty.npz", "smplx_small", "no person in this image"),
    refused("prompthmr_empty", V + "prompthmr_bad/results_empty.pkl", "smplx_small", "no tracked person"),
    # --hands refusals: exit 2, one line naming the file, nothing written.
    refused("hands_length_mismatch", V + "gvhmr/hmr4d_results.pt", "smplx_small",
            "right_short.npz: 20 hand frames for the body clip's 24",
            args=["--hands", "{fixtures}/" + HANDS + "right_short.npz"]),
    refused("hands_frames_beyond", V + "gvhmr/hmr4d_results.pt", "smplx_small",
            "hamer_long: track 1: source frames 0-25 are not all in the body clip's 0-23",
            args=["--hands", "{fixtures}/" + HANDS + "hamer_long"]),
    refused("hands_nan", V + "gvhmr/hmr4d_results.pt", "smplx_small",
            "right_nan.npz: 'hand_pose' contains NaN or infinite values",
            args=["--hands", "{fixtures}/" + HANDS + "right_nan.npz"]),
    refused("hands_hostile_pickle", V + "gvhmr/hmr4d_results.pt", "smplx_small", "refusing pickle global",
            args=["--hands", "{fixtures}/" + V + "hostile/wham_output.pkl"]),
    refused("hands_body_file", V + "gvhmr/hmr4d_results.pt", "smplx_small",
            "hmr4d_results.pt: not a hand track (a smplx motion)",
            args=["--hands", "{fixtures}/" + V + "gvhmr/hmr4d_results.pt"]),
    refused("hands_two_left", V + "gvhmr/hmr4d_results.pt", "smplx_small", "a second left hand",
            args=["--hands", "{fixtures}/" + HANDS + "left.npz", "--hands", "{fixtures}/" + HANDS + "hamer"]),
    refused("hands_smpl_body", V + "wham/wham_output.pkl", "smplx_small",
            "wham_output.pkl: --hands drives the fingers of an SMPL-X or SMPL-H body clip; this clip is smpl",
            args=["--hands", "{fixtures}/" + HANDS + "right.npz"]),
    refused("hands_smpl_model", V + "gvhmr/hmr4d_results.pt", "smpl_small", "has no finger joints",
            args=["--hands", "{fixtures}/" + HANDS + "right.npz"]),
    refused("hands_wrist_world", V + "gvhmr/hmr4d_results.pt", "smplx_small",
            "--hands-wrist needs the body clip in the camera frame of the hand track",
            args=["--hands", "{fixtures}/" + HANDS + "right.npz", "--hands-wrist"]),
]


# ----------------------------------------------------------------------------------------------
# Small math helpers (written here, not shared with the C++).


def mats(axis_angle):
    a = np.asarray(axis_angle, np.float64)
    return model_math.rodrigues(a)


def axis_angle(matrices):
    m = np.asarray(matrices, np.float64)
    return Rotation.from_matrix(m.reshape(-1, 3, 3)).as_rotvec().reshape(m.shape[:-2] + (3,))


def f64(x):
    """float32 (or any) file values as float64, the way the readers widen them."""
    if isinstance(x, torch.Tensor):
        x = x.numpy()
    return np.asarray(x).astype(np.float64)


def arg(case, flag, default=None):
    a = case["args"]
    return a[a.index(flag) + 1] if flag in a else default


def load_model(fixture_dir, name):
    path = os.path.join(fixture_dir, "models", name + ".npz")
    m = model_math.load_model_npz(path)
    raw = np.load(path)
    for key in ("hands_meanl", "hands_meanr", "hands_componentsl", "hands_componentsr"):
        if key in raw.files:
            m[key] = np.asarray(raw[key], np.float64)
    m["num_betas"] = {24: 10, 52: 16, 55: 300, 16: 10}[len(m["parents"])]
    return m


# ----------------------------------------------------------------------------------------------
# Tracks: the rules every multi-person layout shares (docs/motions.md "Tracks and frames").


class Track:
    """One person: rows[frame] = that frame's stored values (a dict), source frame numbers."""

    def __init__(self, tid):
        self.id = tid
        self.rows = {}

    def frames(self):
        return sorted(self.rows)

    def clip(self):
        """Source frames first..last; a frame without a row repeats the previous row."""
        first, last = self.frames()[0], self.frames()[-1]
        out, held = [], None
        for f in range(first, last + 1):
            held = self.rows.get(f, held)
            out.append(held)
        return out


def pick_tracks(case, tracks):
    """--track ID | all | longest (default): the most rows, ties to the lower id."""
    want = arg(case, "--track", "longest")
    ids = sorted(tracks, key=lambda t: int(t))
    if want == "all":
        return [(".track%s.glb" % t, tracks[t]) for t in ids]
    if want == "longest":
        best = max(ids, key=lambda t: (len(tracks[t].rows), -int(t)))
        return [(None, tracks[best])]
    return [(None, tracks[want])]


# ----------------------------------------------------------------------------------------------
# Per-layout decoding into clips: per clip frame the model-order pose (K,3) axis-angle, the tool's
# translation, and the frame change (A, b); plus betas (the mean of the track's rows), fps.


def clip_dict(kind, poses, transl, betas_rows, fps, a, b=None, expression=None, anchor=None):
    t = len(poses)
    return {"kind": kind, "pose": np.asarray(poses, np.float64), "transl": np.asarray(transl, np.float64),
            "betas": np.mean(np.asarray(betas_rows, np.float64), axis=0), "fps": fps,
            "A": np.broadcast_to(np.asarray(a, np.float64), (t, 3, 3)).copy(),
            "b": np.zeros((t, 3)) if b is None else np.asarray(b, np.float64),
            "expression": expression, "anchor": anchor}


def fps_of(case, default):
    return float(arg(case, "--source-fps", default))


def frame_change(case, layout_is_camera):
    """A for a layout's own frame: camera frames get --up -y unless --up says otherwise."""
    up = arg(case, "--up")
    if up == "y":
        return np.eye(3)
    if up == "z":
        return Z_UP_TO_Y_UP
    if up == "-y" or layout_is_camera:
        return CAMERA_TO_UP
    return np.eye(3)


def wham_clips(case, path):
    # yohanshin/WHAM demo.py run(): pose = [root_cam | body] (T,72) axis-angle, trans = trans_cam - offset
    # (an SMPL transl: verts = SMPL(pose, betas) + trans); pose_world / trans_world from
    # Network.rollout(return_y_up=True): Y-up world; trans_world is used as the SMPL transl, as
    # lib/eval/evaluate_emdb.py does (smplx SMPL(..., transl=pred_trans)).
    data = joblib.load(path)
    incam = arg(case, "--source-params", "global") == "incam"
    tracks = {}
    for key, person in data.items():
        t = Track(str(int(key)))
        for i, f in enumerate(np.asarray(person["frame_ids"]).astype(int)):
            t.rows[f] = {"pose": f64(person["pose" if incam else "pose_world"][i]).reshape(24, 3),
                         "transl": f64(person["trans" if incam else "trans_world"][i]),
                         "betas": f64(person["betas"][i])}
        tracks[t.id] = t
    a = frame_change(case, incam)
    return [(sfx, clip_dict("smpl", [r["pose"] for r in tr.clip()], [r["transl"] for r in tr.clip()],
                            [r["betas"] for r in tr.rows.values()], fps_of(case, 30), a))
            for sfx, tr in pick_tracks(case, tracks)]


def vibe_clips(case, path):
    # mkocabas/VIBE demo.py: vibe_results[person_id] = {pose (T,72) axis-angle (theta[:, 3:75]), betas,
    # pred_cam/orig_cam (weak-perspective), frame_ids}; no 3-D translation: lib/utils/fbx_output.py
    # process_poses keeps trans = zeros and turns the pelvis upright (camera frame, y down).
    data = joblib.load(path)
    tracks = {}
    for pid, person in data.items():
        t = Track(str(int(pid)))
        for i, f in enumerate(np.asarray(person["frame_ids"]).astype(int)):
            t.rows[f] = {"pose": f64(person["pose"][i]).reshape(24, 3), "betas": f64(person["betas"][i])}
        tracks[t.id] = t
    return [(sfx, clip_dict("smpl", [r["pose"] for r in tr.clip()], np.zeros((len(tr.clip()), 3)),
                            [r["betas"] for r in tr.rows.values()], fps_of(case, 30), frame_change(case, True)))
            for sfx, tr in pick_tracks(case, tracks)]


def phalp_clips(case, path):
    # brjathu/PHALP phalp/trackers/PHALP.py track(): per frame 'tid' lists confirmed tracks, their
    # history[-1] in the per-person lists ('smpl', 'camera', ...), 'tracked_time' their
    # time_since_update; a detection is tracked_time == 0 (phalp/utils/utils_tracks.py get_tracks).
    # 'smpl' = HMR2 pred_smpl_params: global_orient (1,3,3), body_pose (23,3,3), betas (10,);
    # 'camera' = pred_cam_t of HMAR.get_3d_parameters, added to the SMPL vertices (an SMPL transl).
    data = joblib.load(path)
    tracks = {}
    for frame in data.values():
        for i, tid in enumerate(frame["tid"]):
            if frame["tracked_time"][i] != 0:
                continue
            t = tracks.setdefault(str(tid), Track(str(tid)))
            smpl = frame["smpl"][i]
            rot = np.concatenate([f64(smpl["global_orient"]).reshape(1, 3, 3), f64(smpl["body_pose"])], 0)
            t.rows[int(frame["time"])] = {"pose": axis_angle(rot), "transl": f64(frame["camera"][i]),
                                          "betas": f64(smpl["betas"])}
    return [(sfx, clip_dict("smpl", [r["pose"] for r in tr.clip()], [r["transl"] for r in tr.clip()],
                            [r["betas"] for r in tr.rows.values()], fps_of(case, 30), frame_change(case, True)))
            for sfx, tr in pick_tracks(case, tracks)]


def gvhmr_load(path):
    if path.endswith(".pt"):
        return torch.load(path)
    with open(path, "rb") as fh:
        return pickle.load(fh)


def smplx_pose(m, root, body, jaw, leye, reye, left, right):
    """(55,3) SMPL-X joint order: root, 21 body, jaw, eyes, 15 left, 15 right fingers."""
    return np.concatenate([np.reshape(root, (1, 3)), np.reshape(body, (21, 3)), np.reshape(jaw, (1, 3)),
                           np.reshape(leye, (1, 3)), np.reshape(reye, (1, 3)), np.reshape(left, (15, 3)),
                           np.reshape(right, (15, 3))])


def gvhmr_clips(case, path, m):
    # zju3dv/GVHMR tools/demo/demo.py: pred["smpl_params_global"|"smpl_params_incam"] = {body_pose (L,63),
    # betas (L,10), global_orient (L,3), transl (L,3)}, evaluated by hmr4d/utils/smplx_utils.py
    # make_smplx("supermotion"): SMPL-X neutral, num_pca_comps=12, flat_hand_mean=False, hands not
    # passed (BodyModelSMPLX.forward: zero PCA coefficients) -> each hand at the model's hands_mean
    # (smplx SMPLX.forward: full_pose += pose_mean); jaw, eyes, expression zero; transl added.
    # Global: "ay" (gravity-aligned, Y up); incam: the camera frame.
    pred = gvhmr_load(path)
    incam = arg(case, "--source-params", "global") == "incam"
    p = {k: f64(v) for k, v in pred["smpl_params_incam" if incam else "smpl_params_global"].items()}
    z = np.zeros(3)
    # Hands merged by Mano2Smpl-X (VincentHu19/Mano2Smpl-X mano2smplx.py; README: "set flat_hand_mean=True
    # in SMPLX"): left_hand_pose / right_hand_pose are the finger rotations themselves, no mean added.
    n = len(p["body_pose"])
    hands = "left_hand_pose" in p and arg(case, "reading") != "no_hands"
    left = p["left_hand_pose"] if hands else np.tile(m["hands_meanl"], (n, 1))
    right = p["right_hand_pose"] if hands else np.tile(m["hands_meanr"], (n, 1))
    poses = [smplx_pose(m, p["global_orient"][i], p["body_pose"][i], z, z, z, left[i], right[i])
             for i in range(n)]
    return [(None, clip_dict("smplx", poses, p["transl"], p["betas"], fps_of(case, 30), frame_change(case, incam)))]


def mhr_smplx_clips(case, path, m):
    # facebookresearch/MHR tools/mhr_smpl_conversion: result_parameters of an smplx.SMPLX model; its
    # example.py builds it with flat_hand_mean=True, so the hands are the finger rotations themselves
    # (--flat-hand-mean); smplx's default model (flat_hand_mean=False) adds hands_mean
    # (SMPLX.forward: full_pose += self.pose_mean). transl added; identical betas rows; Y up.
    d = gvhmr_load(path) if path.endswith(".pt") else dict(np.load(path))
    p = {k: f64(v) for k, v in d.items()}
    flat = "--flat-hand-mean" in case["args"]
    if arg(case, "reading") == "other_hands_mean":
        flat = not flat
    ml, mr = (np.zeros(45), np.zeros(45)) if flat else (m["hands_meanl"], m["hands_meanr"])
    poses = [smplx_pose(m, p["global_orient"][i], p["body_pose"][i], p["jaw_pose"][i], p["leye_pose"][i],
                        p["reye_pose"][i], p["left_hand_pose"][i] + ml, p["right_hand_pose"][i] + mr)
             for i in range(len(p["body_pose"]))]
    return [(None, clip_dict("smplx", poses, p["transl"], p["betas"], fps_of(case, 30), np.eye(3)))]
# --hands (docs/motions.md "Combining hand tracks"): Mano2Smpl-X (VincentHu19/Mano2Smpl-X mano2smplx.py)
# as written there: the fingers are HaMeR's hand_pose as they are for a right hand and M R M
# (M = diag(-1,1,1)) for a left one; with the wrist, its local rotation is
# inv(global rotation of the elbow from the SMPL-X pose's parent chain) @ global_orient (M G M on the
# left). The chain is each side's own elbow (the script's right-hand line reuses joint 18, the left
# elbow: a slip that would give the right wrist the left arm's frame).
MIRROR = np.diag([-1.0, 1.0, 1.0])
SMPLX_PARENTS = [-1, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 9, 9, 12, 13, 14, 16, 17, 18, 19]


def hand_paths(case, fixture_dir):
    a = case["args"]
    return [a[i + 1].replace("{fixtures}", fixture_dir) for i in range(len(a)) if a[i] == "--hands"]


def hamer_frames_of(path):
    """{is_right: {frame: (16,3,3) right-MANO rotations as HaMeR stores them}}: a folder of per-image
    pickles (frame = file stem, one hand per side), or one npz of one hand through time (frame = row)."""
    out = {False: {}, True: {}}
    if os.path.isdir(path):
        for p in sorted(glob.glob(os.path.join(path, "*.pkl"))):
            with open(p, "rb") as fh:
                d = pickle.load(fh)
            params = d["pred_mano_params"]
            rots = np.concatenate([f64(params["global_orient"]), f64(params["hand_pose"])], 1)
            for i, right in enumerate(np.asarray(d["right"]) > 0.5):
                out[bool(right)][int(os.path.basename(p).split(".")[0])] = rots[i]
        return out
    d = np.load(path)
    rots = np.concatenate([f64(d["global_orient"]), f64(d["hand_pose"])], 1)
    for i, right in enumerate(np.asarray(d["is_right"]) > 0.5):
        out[bool(right)][i] = rots[i]
    return out


def elbow_global(pose, joint):
    """Mano2Smpl-X compute_global_rotation: the product of the local rotations from the root down."""
    g = np.eye(3)
    while joint != -1:
        g = mats(pose[joint]) @ g
        joint = SMPLX_PARENTS[joint]
    return g


def hands_clips(case, fixture_dir, m):
    """GVHMR's clip (gvhmr_clips) with the --hands tracks put in; the case's "reading" names a plausible
    misreading (HANDS_WRONG, for the sensitivity check): "hands_ignored", "hands_swapped" (each track on
    the other side), "hands_mirrored" (the left hand's rotations as stored, not M R M), "no_wrist"
    (--hands-wrist not applied)."""
    wrong = arg(case, "reading")
    path = os.path.join(fixture_dir, case["fixture"])
    smplh = case["model"].startswith("smplh")  # SMPL-H: fingers from joint 22 (left) and 37 (right)
    c = (amass_clips(case, path) if smplh else gvhmr_clips(case, path, m))[0][1]
    wrist = "--hands-wrist" in case["args"] and wrong != "no_wrist"
    if wrong == "hands_ignored":
        return [(None, c)]
    body = c["pose"].copy()  # the elbows' chains come from the body's own pose
    for hand_path in hand_paths(case, fixture_dir):
        for right, frames in hamer_frames_of(hand_path).items():
            side = (not right) if wrong == "hands_swapped" else right
            for f, rots in frames.items():
                own = rots if right or wrong == "hands_mirrored" else MIRROR @ rots @ MIRROR
                first = (37 if side else 22) if smplh else (40 if side else 25)
                c["pose"][f][first:first + 15] = axis_angle(own[1:])
                if wrist:
                    c["pose"][f][21 if side else 20] = axis_angle(elbow_global(body[f], 19 if side else 18).T @ own[0])
    return [(None, c)]


def hands_wrong(case):
    """The --hands cases' plausible misreadings as (label, change) pairs (see wrong_expected)."""
    names = ["hands_ignored", "hands_swapped", "hands_mirrored"]
    names += ["no_wrist"] if "--hands-wrist" in case["args"] else []
    return [(n.replace("_", " "), {"reading": n}) for n in names]


def gvhmr_flat_clips(case, path, m):
    # Today's Fit reader (core/motions/motion_fit.h) on a flattened npz: body_pose (T,63) = SMPL-X body,
    # global_orient, transl, betas rows averaged; no hand keys -> hands at rest (zero); Y up; 30 fps.
    d = np.load(path)
    z = np.zeros(3)
    poses = [smplx_pose(m, f64(d["global_orient"][i]), f64(d["body_pose"][i]), z, z, z, np.zeros(45), np.zeros(45))
             for i in range(len(d["body_pose"]))]
    return [(None, clip_dict("smplx", poses, f64(d["transl"]), f64(d["betas"]), fps_of(case, 30), np.eye(3)))]


def tram_clips(case, path):
    # yufu-wang/tram: hps_track_k.npy = HMR_VIMO.inference results (torch tensors): pred_rotmat (T,24,3,3),
    # pred_shape (T,10), pred_trans (T,1,3), frame (T,); lib/pipeline/visualization.py visualize_tram:
    # betas = the mean over the track, verts = SMPL(rotmat, betas, transl=pred_trans.squeeze()) in the
    # camera frame, world = world_cam_R[frame] @ v + world_cam_T[frame] with camera.npy from
    # scripts/estimate_camera.py (lib/camera/est_gravity.py: Y-up world).
    track = np.load(path, allow_pickle=True).item()
    rot, trans = f64(track["pred_rotmat"]), f64(track["pred_trans"]).reshape(-1, 3)
    frames = f64(track["frame"]).astype(int)
    camera_path = os.path.join(os.path.dirname(os.path.dirname(path)), "camera.npy")
    incam = arg(case, "--source-params", "global") == "incam" or not os.path.exists(camera_path)
    poses = [axis_angle(r) for r in rot]
    if incam:
        return [(None, clip_dict("smpl", poses, trans, f64(track["pred_shape"]), fps_of(case, 30),
                                 frame_change(case, True)))]
    cam = np.load(camera_path, allow_pickle=True).item()
    a, b = f64(cam["world_cam_R"])[frames], f64(cam["world_cam_T"])[frames]
    return [(None, clip_dict("smpl", poses, trans, f64(track["pred_shape"]), fps_of(case, 30), a, b))]


def romp_clips(case, path, m):
    # Arthur151/ROMP simple_romp/romp/utils.py save_video_results: sequence_results[track_id] =
    # {frame_id: [...], smpl_thetas: [(72,)], smpl_betas: [(10,) | (11,)], cam_trans: [(3,)]}; without
    # tracks, simple_romp/tools/convert2fbx.py takes person 0 of each frame in sorted frame-name order.
    # Vertices as vis_human/main.py renders them: outputs['verts'] + cam_trans; ROMP's verts are plain
    # SMPL (root_align False); BEV's (11 betas, SMPL+A) are root-aligned by bev/post_parser.py
    # SMPLA_parser: minus the mid-hip, approximated here (and in the spec) by the mid-point of the
    # model's posed hip joints 1 and 2. The age coefficient betas[10] is dropped.
    d = np.load(path, allow_pickle=True)
    seq = d["sequence_results"][()]
    tracks = {}
    if seq:
        for tid, rows in seq.items():
            t = Track(str(int(tid)))
            for i, f in enumerate(rows["frame_id"]):
                t.rows[int(f)] = {"pose": f64(rows["smpl_thetas"][i]).reshape(24, 3),
                                  "transl": f64(rows["cam_trans"][i]), "betas": f64(rows["smpl_betas"][i])}
            tracks[t.id] = t
    else:
        t = Track("0")
        results = d["results"][()]
        for f, name in enumerate(sorted(results)):
            r = results[name]
            t.rows[f] = {"pose": f64(r["smpl_thetas"][0]).reshape(24, 3), "transl": f64(r["cam_trans"][0]),
                         "betas": f64(r["smpl_betas"][0])}
        tracks["0"] = t
    out = []
    for sfx, tr in pick_tracks(case, tracks):
        rows = tr.clip()
        bev = len(rows[0]["betas"]) == 11
        c = clip_dict("smpl", [r["pose"] for r in rows], [r["transl"] for r in rows],
                      [r["betas"][:10] for r in tr.rows.values()], fps_of(case, 24), frame_change(case, True),
                      anchor="mid-hip" if bev else None)
        out.append((sfx, c))
    return out


def easymocap_persons(path):
    with open(path, encoding="utf-8") as fh:
        return json.load(fh)


def easymocap_clips(case, path):
    # zju3dv/EasyMocap easymocap/smplmodel/body_model.py SMPLlayer.forward (and bodymodel/smpl.py):
    # vertices = LBS(poses, shapes) @ Rodrigues(Rh)^T + Th: Rh turns the posed body about the model's
    # origin, not about the pelvis; poses[:3] (zero as written) is the root's own rotation about J_0.
    # The world is the calibration board's, Z up (apps/calibration/detect_chessboard.py getChessboard3d).
    files = sorted(glob.glob(os.path.join(path, "*.json"))) if os.path.isdir(path) else [path]
    tracks = {}
    for p in files:
        frame = int(os.path.splitext(os.path.basename(p))[0])
        for person in easymocap_persons(p):
            t = tracks.setdefault(str(person["id"]), Track(str(person["id"])))
            t.rows[frame] = {"pose": np.asarray(person["poses"], np.float64).reshape(24, 3),
                             "rh": mats(np.asarray(person["Rh"], np.float64).reshape(3)),
                             "th": np.asarray(person["Th"], np.float64).reshape(3),
                             "betas": np.asarray(person["shapes"], np.float64).reshape(10)}
    up = {None: Z_UP_TO_Y_UP, "z": Z_UP_TO_Y_UP, "y": np.eye(3), "-y": CAMERA_TO_UP}[arg(case, "--up")]
    out = []
    for sfx, tr in pick_tracks(case, tracks):
        rows = tr.clip()
        a = [up @ r["rh"] for r in rows]
        b = [up @ r["th"] for r in rows]
        out.append((sfx, clip_dict("smpl", [r["pose"] for r in rows], np.zeros((len(rows), 3)),
                                   [r["betas"] for r in tr.rows.values()], fps_of(case, 30), a, b)))
    return out


def smplerx_clips(case, path, m):
    # caizhongang/SMPLer-X main/inference.py: {frame:05}_{bbox_id}.npz per frame and detection, smplx
    # names; evaluated by common/utils/human_models.py smplx.create(..., use_pca=False) with
    # flat_hand_mean False (smplx's default): hands_mean is added to the 45-d hands; main/SMPLer_X.py
    # get_coord: mesh_cam = vertices + cam_trans (the saved transl); leye/reye zero; expression (1,10).
    tracks = {}
    for p in sorted(glob.glob(os.path.join(path, "*.npz"))):
        frame, person = os.path.splitext(os.path.basename(p))[0].split("_")
        d = np.load(p)
        t = tracks.setdefault(str(int(person)), Track(str(int(person))))
        t.rows[int(frame)] = {
            "pose": smplx_pose(m, f64(d["global_orient"]), f64(d["body_pose"]), f64(d["jaw_pose"]),
                               f64(d["leye_pose"]), f64(d["reye_pose"]),
                               f64(d["left_hand_pose"]).reshape(45) + m["hands_meanl"],
                               f64(d["right_hand_pose"]).reshape(45) + m["hands_meanr"]),
            "transl": f64(d["transl"]).reshape(3), "betas": f64(d["betas"]).reshape(10),
            "expression": f64(d["expression"]).reshape(10)}
    keys = int(arg(case, "--expression-keys", 0))
    out = []
    for sfx, tr in pick_tracks(case, tracks):
        rows = tr.clip()
        expr = np.array([r["expression"][:keys] for r in rows]) if keys else None
        out.append((sfx, clip_dict("smplx", [r["pose"] for r in rows], [r["transl"] for r in rows],
                                   [r["betas"] for r in tr.rows.values()], fps_of(case, 30),
                                   frame_change(case, True), expression=expr)))
    return out


def amass_clips(case, path):
    # AMASS SMPL-H release (tests/web/anim_reference.py): poses (T,156), trans, betas, Z up, stored rate.
    d = np.load(path)
    t = len(d["poses"])
    return [(None, clip_dict("smplh", f64(d["poses"]).reshape(t, 52, 3), f64(d["trans"]),
                             [f64(d["betas"])[:16]], float(d["mocap_framerate"]), Z_UP_TO_Y_UP))]


def no_hands(case, pose):
    """The "hands ignored" wrong reading: the 30 finger joints at rest."""
    if arg(case, "reading") == "no_hands":
        pose = np.array(pose)
        pose[25:] = 0
    return pose


def prompthmr_clips(case, path, m):
    # yufu-wang/PromptHMR pipeline/world.py world_hps_estimation: people[k]['smplx_world'] = {pose (T,165)
    # axis-angle in smplx's full_pose order (root, body, jaw, eyes, left, right fingers), shape (T,10),
    # trans (T,3) SMPL-X transl} in the gravity-aligned Y-up world; 'smplx_cam' (pipeline/phmr_vid.py) =
    # {pose (T,75) root, body, jaw, eyes; ...} in the camera frame; the SMPL-X is flat_hand_mean=True
    # (pipeline.py): the finger rotations are absolute (no hands_mean); 'frames' the source frames.
    data = joblib.load(path)
    incam = arg(case, "--source-params", "global") == "incam"
    tracks = {}
    for pid, person in data["people"].items():
        t = Track(str(int(pid)))
        params = person["smplx_cam" if incam else "smplx_world"]
        for i, f in enumerate(np.asarray(person["frames"]).astype(int)):
            pose = np.zeros((55, 3))
            stored = f64(params["pose"][i]).reshape(-1, 3)
            pose[:len(stored)] = stored
            t.rows[f] = {"pose": no_hands(case, pose), "transl": f64(params["trans"][i]),
                         "betas": f64(params["shape"][i])}
        tracks[t.id] = t
    return [(sfx, clip_dict("smplx", [r["pose"] for r in tr.clip()], [r["transl"] for r in tr.clip()],
                            [r["betas"] for r in tr.rows.values()], fps_of(case, 30), frame_change(case, incam)))
            for sfx, tr in pick_tracks(case, tracks)]


def mcs_clips(case, path, m):
    # yufu-wang/PromptHMR pipeline/mcs_export_cam.py add_smpl_buffers_to_gltf: buffers[i].uri = base64 of
    # body i's .smpl (Meshcapade/smplcodec codec.py: np.savez_compressed of bodyPose (T,22,3), bodyTranslation,
    # shapeParameters, frameRate, ...), scenes[0].extensions.MC_scene_description.smpl_bodies[i] =
    # {frame_presence: [first, end), bufferView: i}; the .smpl has no hands, jaw or eyes (rest).
    with open(path, encoding="utf-8") as fh:
        gltf = json.load(fh)
    desc = gltf["scenes"][gltf.get("scene", 0)]["extensions"]["MC_scene_description"]
    tracks, fps = {}, None
    for k, body in enumerate(desc["smpl_bodies"]):
        buf = gltf["buffers"][gltf["bufferViews"][body["bufferView"]]["buffer"]]
        smpl = np.load(io.BytesIO(base64.b64decode(buf["uri"].split(",", 1)[1])))
        t = Track(str(k))
        fps = fps or float(smpl["frameRate"])
        for i in range(int(smpl["frameCount"])):
            pose = np.zeros((55, 3))
            pose[:22] = f64(smpl["bodyPose"][i])
            t.rows[body["frame_presence"][0] + i] = {"pose": pose, "transl": f64(smpl["bodyTranslation"][i]),
                                                      "betas": f64(smpl["shapeParameters"])}
        tracks[t.id] = t
    return [(sfx, clip_dict("smplx", [r["pose"] for r in tr.clip()], [r["transl"] for r in tr.clip()],
                            [r["betas"] for r in tr.rows.values()], fps_of(case, fps), np.eye(3)))
            for sfx, tr in pick_tracks(case, tracks)]


def multihmr_clips(case, path, m):
    # naver/multi-hmr blocks/smpl_layer.py SMPL_Layer.forward: rotvec (53,3) = global orient, pose[:,1:22]
    # body, [22:37] left hand, [37:52] right hand, [52:53] jaw; eyes at rest; smplx.create(...,
    # flat_hand_mean=True): absolute fingers. The body is posed with a zero global orient, turned by R about
    # its pelvis J_0 and moved so that the pelvis is at transl_pelvis (j3d_cam[:,0]): v = R (v0 - J_0) +
    # transl_pelvis, i.e. an SMPL-X transl of transl_pelvis - J_0(betas) ("anchor": "pelvis" below).
    # Camera frame. Persons by row; a folder is one file per image (frame = file stem).
    files = sorted(glob.glob(os.path.join(path, "*.npz"))) if os.path.isdir(path) else [path]
    tracks = {}
    reading = arg(case, "reading")
    for p in files:
        frame = int(os.path.splitext(os.path.basename(p))[0]) if os.path.isdir(path) else 0
        d = np.load(p)
        for row in range(len(d["rotvec"])):
            rv = f64(d["rotvec"][row]).reshape(53, 3)
            pose = smplx_pose(m, rv[0], rv[1:22], rv[52], np.zeros(3), np.zeros(3), rv[22:37], rv[37:52])
            key = "transl" if reading == "transl" else "transl_pelvis"
            t = tracks.setdefault(str(row), Track(str(row)))
            t.rows[frame] = {"pose": no_hands(case, pose), "transl": f64(d[key][row]).reshape(3),
                             "betas": f64(d["shape"][row])}
    anchor = None if reading in ("transl", "pelvis_as_transl") else "pelvis"
    return [(sfx, clip_dict("smplx", [r["pose"] for r in tr.clip()], [r["transl"] for r in tr.clip()],
                            [r["betas"] for r in tr.rows.values()], fps_of(case, 30), frame_change(case, True),
                            anchor=anchor))
            for sfx, tr in pick_tracks(case, tracks)]


def clips(case, fixture_dir, m):
    path = os.path.join(fixture_dir, case["fixture"])
    name = case["name"]
    if name.startswith("wham"):
        return wham_clips(case, path)
    if name.startswith("vibe"):
        return vibe_clips(case, path)
    if name.startswith("phalp"):
        return phalp_clips(case, path)
    if name.startswith("mhr_smplx"):
        return mhr_smplx_clips(case, path, m)
    if name.startswith("hands"):
        return hands_clips(case, fixture_dir, m)
    if name.startswith("gvhmr_flat"):
        return gvhmr_flat_clips(case, path, m)
    if name.startswith("gvhmr"):
        return gvhmr_clips(case, path, m)
    if name.startswith("tram"):
        return tram_clips(case, path)
    if name.startswith(("romp", "bev")):
        return romp_clips(case, path, m)
    if name.startswith("easymocap"):
        return easymocap_clips(case, path)
    if name.startswith("smplerx"):
        return smplerx_clips(case, path, m)
    if name.startswith("amass"):
        return amass_clips(case, path)
    if name.startswith("prompthmr"):
        return prompthmr_clips(case, path, m)
    if name.startswith("mcs"):
        return mcs_clips(case, path, m)
    if name.startswith("multihmr"):
        return multihmr_clips(case, path, m)
    raise ValueError("no reference for case " + name)


# ----------------------------------------------------------------------------------------------
# The body model: what the exporter must reproduce, in numpy.


def shaped(m, betas, expression=None):
    b = np.zeros(m["num_betas"])
    n = min(len(betas), m["num_betas"])
    b[:n] = betas[:n]
    v = m["v_template"] + m["shapedirs"][:, :, :m["num_betas"]] @ b
    joints = m["J_regressor"] @ v
    if expression is not None and len(expression):
        v = v + m["shapedirs"][:, :, 300:300 + len(expression)] @ np.asarray(expression)
    return v, joints


def anchored_transl(c, m, joints, t):
    """The tool's translation as an SMPL transl (BEV: minus the posed mid-hip of joints 1 and 2;
    Multi-HMR: minus the rest pelvis)."""
    if c["anchor"] == "pelvis":  # the posed pelvis (Multi-HMR transl_pelvis): minus the rest pelvis J_0
        return c["transl"][t] - joints[0]
    if c["anchor"] != "mid-hip":
        return c["transl"][t]
    r0 = mats(c["pose"][t][0])
    mid = joints[0] + r0 @ ((joints[1] + joints[2]) / 2 - joints[0])
    return c["transl"][t] - mid


def vertices(c, m, t, weights):
    expr = None if c["expression"] is None else c["expression"][t]
    v_shaped, joints = shaped(m, c["betas"], expr)
    verts, _, _ = model_math.forward(m, v_shaped, joints, c["pose"][t], weights)
    return (verts + anchored_transl(c, m, joints, t)) @ c["A"][t].T + c["b"][t]


def authors_expression_cost_mm(c, m, weights):
    """The closing note's number: max over every clip frame of the vertex distance between our
    baked expression (joints from the betas alone) and the authors' math (smplx lbs regresses the
    joints from the template with betas and expression), weights pruned as exported; mm."""
    worst = 0.0
    for t in range(len(c["pose"])):
        v_shaped, joints = shaped(m, c["betas"], c["expression"][t])
        ours, _, _ = model_math.forward(m, v_shaped, joints, c["pose"][t], weights)
        theirs, _, _ = model_math.forward(m, v_shaped, m["J_regressor"] @ v_shaped, c["pose"][t], weights)
        worst = max(worst, float(np.linalg.norm(ours - theirs, axis=1).max()))
    return 1000 * worst


def expected(case, fixture_dir):
    m = load_model(fixture_dir, case["model"])
    weights = model_math.prune(m["weights"], 4)
    out = {}
    for sfx, c in clips(case, fixture_dir, m):
        for f in case["frames"]:
            assert 0 <= f < len(c["pose"]), "%s: frame %d outside the clip (%d frames)" % (
                case["name"], f, len(c["pose"]))
        ref = {"fps": c["fps"], "frames": case["frames"], "num_vertices": len(m["v_template"]),
               "vertices": [vertices(c, m, t, weights).tolist() for t in case["frames"]]}
        if c["expression"] is not None:
            ref["numbers"] = {EXPRESSION_COST: authors_expression_cost_mm(c, m, weights)}
        out[sfx] = ref
    return out[None] if list(out) == [None] else out


def equivalent(case, fixture_dir):
    """AMASS-style npz arrays per output (root and trans pre-turned Y up: export with --up y)."""
    m = load_model(fixture_dir, case["model"])
    result = []
    for sfx, c in clips(case, fixture_dir, m):
        if c["expression"] is not None:
            return "an animated expression cannot be given to today's exporter (no per-frame expression input)"
        _, joints = shaped(m, c["betas"])
        j0 = joints[0]
        poses = c["pose"].copy()
        trans = np.zeros((len(poses), 3))
        for t in range(len(poses)):
            a = c["A"][t]
            poses[t][0] = axis_angle(a @ mats(poses[t][0]))
            trans[t] = a @ (j0 + anchored_transl(c, m, joints, t)) + c["b"][t] - j0
        result.append((sfx, {"poses": poses.reshape(len(poses), -1), "trans": trans, "betas": c["betas"],
                             "fps": np.array(c["fps"])}))
    return result


def wrong_expected(case, fixture_dir, change):
    """The reference of a plausible wrong reading of the case's file: `change` replaces the case's
    args ({"--track": "1"}) or names a reading the clip functions know ({"reading": "no_hands"})."""
    c = dict(case)
    args = list(case["args"])
    for flag, value in change.items():
        if flag in args:
            args[args.index(flag) + 1] = value
        else:
            args += [flag, value]
    c["args"] = args
    c["outputs"] = None
    if "--track" in change and arg(case, "--track") == "all":
        c["args"][c["args"].index("--track") + 1] = change["--track"]
    return expected(c, fixture_dir)


for _c in CASES:
    if _c["name"].startswith("hands") and not _c["refusal"]:
        _c["wrong"] = hands_wrong(_c)
