#include "cli/options.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <optional>
#include <sstream>
#include <type_traits>

#include "cli/presets.h"
#include "cli/settings.h"
#include "core/docs_location.h"
#include "core/memory_budget.h"
#include "core/number_text.h"
#include "writers/writer.h"

namespace smpl {
namespace {

Error usageError(const std::string& message) { return makeError(message, ErrorKind::Usage); }

// Every numeric option goes through the one grammar of core/number_text.h:
// decimal only, the whole value, no '+', blanks, hexadecimal, inf or nan.
Result<double> parseNumber(const std::string& text, const std::string& option) {
  Result<double> v = parseDecimal(text, -DBL_MAX, DBL_MAX);
  if (!v) return usageError(option + ": " + v.message());
  return *v;
}

Result<int> parseInt(const std::string& text, const std::string& option) {
  Result<int64_t> v = parseInteger(text, -1000000, 1000000);
  if (!v) return usageError(option + ": " + v.message());
  return static_cast<int>(*v);
}

Status intInto(const std::string& value, const char* option, int* target) {
  Result<int> v = parseInt(value, option);
  if (!v) return v.error();
  *target = *v;
  return Status();
}

// `value` must be one of `choices`; returns its index.
Result<int> choice(const std::string& value, const char* option, std::vector<const char*> choices) {
  std::string expected;
  for (size_t i = 0; i < choices.size(); ++i) {
    if (value == choices[i]) return static_cast<int>(i);
    expected += (i == 0                    ? ""
                 : i + 1 == choices.size() ? " or "
                                           : ", ") +
                std::string("'") + choices[i] + "'";
  }
  return usageError(std::string(option) + ": expected " + expected + ", got '" + value + "'");
}

// "v,v,...": each value a decimal number; blanks around a value are allowed
// ("0.5, -1.2" as a shell user types it), blanks inside one are not.
Result<std::vector<double>> parseList(const std::string& text, const std::string& option) {
  std::vector<double> values;
  size_t start = 0;
  while (start <= text.size()) {
    size_t comma = text.find(',', start);
    std::string item =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const size_t first = item.find_first_not_of(" \t"), last = item.find_last_not_of(" \t");
    item = first == std::string::npos ? std::string() : item.substr(first, last + 1 - first);
    Result<double> v = parseNumber(item, option);
    if (!v) return v.error();
    values.push_back(*v);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return values;
}

// "A:B" (B exclusive, either may be empty) -> frame range (the request
// checks A >= 0 and B > A).
Status parseFrames(const std::string& value, ExportRequest* r) {
  size_t colon = value.find(':');
  if (colon == std::string::npos) return usageError("--frames: expected A:B, got '" + value + "'");
  const std::string first = value.substr(0, colon), end = value.substr(colon + 1);
  if (!first.empty()) {
    Result<int> v = parseInt(first, "--frames");
    if (!v) return usageError("--frames: bad start '" + first + "'");
    r->animation.first_frame = *v;
  }
  if (!end.empty()) {
    Result<int> v = parseInt(end, "--frames");
    if (!v) return usageError("--frames: bad end '" + end + "'");
    r->animation.end_frame = *v;
  }
  return Status();
}

// A number into an optional request field.
template <class T>
Status numberInto(const std::string& value, const char* option, std::optional<T>* target) {
  if constexpr (std::is_same_v<T, int>) {
    Result<int> v = parseInt(value, option);
    if (!v) return v.error();
    *target = *v;
  } else {
    Result<double> v = parseNumber(value, option);
    if (!v) return v.error();
    *target = *v;
  }
  return Status();
}

// "I/N", 0 <= I < N: this run's share of a batch (cli/batch_shard.h).
Status parseShard(const std::string& value, Settings* s) {
  const size_t slash = value.find('/');
  Result<int> i = parseInt(value.substr(0, slash), "--shard");
  Result<int> n = parseInt(slash == std::string::npos ? "" : value.substr(slash + 1), "--shard");
  if (!i || !n || *n < 1 || *i < 0 || *i >= *n)
    return usageError("--shard: expected I/N with 0 <= I < N (e.g. 0/8), got '" + value + "'");
  s->shard_index = *i;
  s->shard_count = *n;
  return Status();
}

using S = Settings;
using V = const std::string&;
// Each apply function stores its value into the request (s->request) or, for
// what only the command line has, into the settings; syntax only.

const std::vector<OptionSpec> kOptions = {
    {"--model", nullptr, "PATH|DIR|builtin", Applies::Any, "",
     "model file (.npz or .pkl from the model's authors); a folder of released model files (picked "
     "per motion by kind and gender: SMPL_FEMALE.pkl, smplx/SMPLX_MALE.npz, AMASS "
     "smplh/male/model.npz, "
     "...); or the built-in demo body",
     [](V v, S* s) { return s->request.model = v, Status(); }, Hashed::Content},
    {"--out", nullptr, "FILE", Applies::Single, nullptr,
     "output; format from the extension ({extensions}). Also writes FILE.smpl.json (metadata)",
     [](V v, S* s) { return s->request.out = v, Status(); }, Hashed::No},
    {"--betas", nullptr, "v,v,...", Applies::Any, nullptr,
     "shape coefficients (fewer than the model has are zero-padded)",
     [](V v, S* s) {
       Result<std::vector<double>> list = parseList(v, "--betas");
       if (!list) return Status(list.error());
       return s->request.asset.betas = *list, Status();
     }},
    {"--betas-file", nullptr, "FILE", Applies::Any, nullptr,
     "betas from .npy, .npz (key 'betas') or .json; per-frame (T,B) betas: identical rows -> that "
     "row, else their mean (a note gives the deviation)",
     [](V v, S* s) { return s->request.betas_file = v, Status(); }, Hashed::Content},
    {"--expression", nullptr, "v,v,...", Applies::Any, nullptr, "SMPL-X expression coefficients",
     [](V v, S* s) {
       Result<std::vector<double>> list = parseList(v, "--expression");
       if (!list) return Status(list.error());
       return s->request.asset.expression = *list, Status();
     }},
    {"--max-influences", nullptr, "N|all", Applies::Mesh, nullptr,
     "skin influences per vertex, 1..K (the model's joints) or all (default 4); glTF writes "
     "ceil(N/4) "
     "JOINTS_n/WEIGHTS_n sets (engines that read one set: keep 4), FBX has no limit; all: as many "
     "as "
     "the model's vertices use",
     [](V v, S* s) -> Status {
       if (v == "all") return s->request.asset.max_influences = kAllInfluences, Status();
       Result<int> n = parseInt(v, "--max-influences");
       if (!n) return n.error();
       // kAllInfluences is 0: a count below 1 is refused here, never read as "all"
       if (*n < 1)
         return usageError(
             "--max-influences must be between 1 and the model's joints or 'all', got " + v);
       return s->request.asset.max_influences = *n, Status();
     }},
    {"--skin-weights", nullptr, "truncated|optimized", Applies::Mesh, nullptr,
     "truncated: the N largest weights, renormalised; optimized (default): the best-fitting N "
     "of the vertex's largest weights, with weights fitted to the unpruned model over 48 "
     "motion-like training poses (lower error on held-out poses; the summary shows both)",
     [](V v, S* s) {
       Result<int> c = choice(v, "--skin-weights", {"truncated", "optimized"});
       if (!c) return Status(c.error());
       return s->request.asset.skin_weights =
                  *c == 0 ? SkinWeightMethod::Truncated : SkinWeightMethod::Optimized,
              Status();
     }},
    {"--corrective-refit", nullptr, "on|off", Applies::Mesh, nullptr,
     "on (default): refit the corrective deltas of vertices whose influences were cut so that "
     "the exported skin + correctives reproduce the unpruned model (240 motion-like training "
     "poses; a vertex keeps the model's deltas where the refit is worse on validation poses); "
     "off: the model's posedirs as they are. The summary shows the error with and without",
     [](V v, S* s) {
       Result<int> c = choice(v, "--corrective-refit", {"on", "off"});
       if (!c) return Status(c.error());
       return s->request.asset.corrective_refit = *c == 0, Status();
     }},
    {"--correctives", nullptr, "all|none", Applies::Mesh, nullptr,
     "pose-corrective morph targets (default all)",
     [](V v, S* s) {
       Result<int> c = choice(v, "--correctives", {"all", "none"});
       if (!c) return Status(c.error());
       return s->request.asset.correctives = *c == 0, Status();
     }},
    {"--corrective-weights", nullptr, "signed|unit|split", Applies::Mesh, nullptr,
     "signed: weight = pose feature f, in [-2, 1] (default without --motion);\n"
     "unit: weight = 0.5 f + 0.5 (off-diagonal) or + 1 (diagonal), in [0, 1], relies on the file's "
     "default weights at rest;\n"
     "split (default with --motion; unit with --corrective-basis): rectified targets (diagonal -2P "
     "with "
     "weight -f/2; off-diagonal _pos/_neg with max(f,0), max(-f,0)), in [0, 1] and exact with "
     "every "
     "weight at zero; the mapping is in the metadata",
     [](V v, S* s) {
       Result<int> c = choice(v, "--corrective-weights", {"signed", "unit", "split"});
       if (!c) return Status(c.error());
       const CorrectiveEncoding e[] = {CorrectiveEncoding::Signed, CorrectiveEncoding::Unit,
                                       CorrectiveEncoding::Split};
       return s->request.asset.encoding = e[*c], Status();
     }},
    {"--corrective-basis", nullptr, "K", Applies::Mesh, nullptr,
     "replace the corrective targets by K principal components of posedirs (weights = C f; C in "
     "the "
     "metadata; runtime scripts apply it)",
     [](V v, S* s) {
       return intInto(v, "--corrective-basis", &s->request.asset.corrective_basis);
     }},
    {"--corrective-epsilon", nullptr, "M", Applies::Format, nullptr,
     "glTF: drop morph deltas up to M metres, write sparse accessors",
     [](V v, S* s) {
       Result<double> m = parseNumber(v, "--corrective-epsilon");
       if (!m) return Status(m.error());
       return s->request.writer.morph_epsilon = *m, Status();
     }},
    {"--quantize-morphs", nullptr, nullptr, Applies::Format, nullptr,
     "glTF: int16 morph deltas (KHR_mesh_quantization)",
     [](V, S* s) { return s->request.asset.quantize_morphs = true, Status(); }},
    {"--draco", nullptr, nullptr, Applies::Format, nullptr,
     "glTF: Draco-compress the base mesh (KHR_draco_mesh_compression)",
     [](V, S* s) { return s->request.writer.draco = true, Status(); }},
    {"--meshopt", nullptr, nullptr, Applies::Format, nullptr,
     "glTF: meshopt-compress vertex, index, morph-target and animation data "
     "(EXT_meshopt_compression; three.js, Babylon.js and glTFast decode it)",
     [](V, S* s) { return s->request.writer.meshopt = true, Status(); }},
    {"--quantize-animation", nullptr, nullptr, Applies::Format, nullptr,
     "glTF: rotation keys as normalised int16, morph weight keys as normalised 16-bit integers "
     "where they fit (core glTF 2.0, no extension); needs a motion",
     [](V, S* s) { return s->request.writer.quantize_animation = true, Status(); }},
    {"--preset", nullptr, "web|engine|archive", Applies::Any, nullptr,
     "a bundle of the size options; options given explicitly override it, and each applies only "
     "where it can (the glTF-only ones to glTF, --quantize-animation with a motion); their "
     "sizes and errors: performance.md:"
     "{presets}",
     [](V v, S* s) { return s->preset = v, Status(); }},
    {"--gltf-embed", nullptr, nullptr, Applies::Format, nullptr,
     ".gltf: embed the buffer in the JSON as a base64 data URI (one file, a third larger); "
     "default: the "
     "buffer is FILE.bin beside FILE.gltf (written and replaced together with it)",
     [](V, S* s) { return s->request.gltf_embed = true, Status(); }},
    {"--shape-keys", nullptr, "N", Applies::Mesh, nullptr,
     "also export the first N shape directions as morph targets shape_<i>",
     [](V v, S* s) { return intInto(v, "--shape-keys", &s->request.asset.shape_keys); }},
    {"--expression-keys", nullptr, "N", Applies::Mesh, nullptr,
     "also export the first N expression directions (SMPL-X) as expr_<i>",
     [](V v, S* s) { return intInto(v, "--expression-keys", &s->request.asset.expression_keys); }},
    {"--uv", nullptr, "OBJ|NPY|none", Applies::Mesh, nullptr,
     "UVs (seams split vertices). Default: the model file's own vt/ft if it has them (SMPL-X "
     "release). OBJ sharing the model's vertex order, or a numpy pair <stem>_uv.npy (U,2) + "
     "<stem>_ft.npy (F,3) (give either); none: no UVs",
     [](V v, S* s) { return s->request.asset.uv_obj = v, Status(); }, Hashed::Content},
    {"--name", nullptr, "NAME", Applies::Mesh, nullptr, "mesh name (default body)",
     [](V v, S* s) { return s->request.asset.name = v, Status(); }},
    {"--origin", nullptr, "model|floor", Applies::Any, nullptr,
     "model: the model's own origin (default; the pelvis near y = 0, the feet below); floor: one "
     "shift in y puts the body's lowest point at y = 0 (the rest mesh, or with --motion the lowest "
     "posed vertex over every frame); the offset is in the metadata",
     [](V v, S* s) {
       Result<int> c = choice(v, "--origin", {"model", "floor"});
       if (!c) return Status(c.error());
       return s->request.asset.origin = *c == 0 ? Origin::Model : Origin::Floor, Status();
     }},
    {"--root-bone", nullptr, nullptr, Applies::Any, nullptr,
     "add a joint `root` on the floor below the pelvis (parent of pelvis; implies --origin floor); "
     "with --motion it carries the pelvis' ground-plane motion (root motion), the pelvis keeps "
     "its height and rotation",
     [](V, S* s) { return s->request.asset.root_bone = true, Status(); }},
    {"--skeleton-names", nullptr, "smpl|mixamo|ue5", Applies::Format, nullptr,
     "bone names: smpl (default) the model's joint names; mixamo (mixamorig:Hips, ...) or ue5 "
     "(the UE5 Mannequin's pelvis, thigh_l, ...) for those rigs' retarget presets; joints the rig "
     "has no bone for keep their names, morph target names stay; the table: {retargeting-page}",
     [](V v, S* s) {
       Result<int> c = choice(v, "--skeleton-names", {"smpl", "mixamo", "ue5"});
       if (!c) return Status(c.error());
       s->request.asset.skeleton_names = *c == 0   ? SkeletonNames::Smpl
                                         : *c == 1 ? SkeletonNames::Mixamo
                                                   : SkeletonNames::Ue5;
       return Status();
     }},
    {"--rest-pose", nullptr, "t|a", Applies::Any, nullptr,
     "the skeleton's rest: t (default) the model's T-pose; a the arms 45 degrees down, every key "
     "re-expressed so the joints move as with t (.bvh only: a skinned mesh bound at an A pose "
     "deforms differently)",
     [](V v, S* s) {
       Result<int> c = choice(v, "--rest-pose", {"t", "a"});
       if (!c) return Status(c.error());
       s->request.asset.rest_pose = *c == 0 ? RestPose::T : RestPose::A;
       return Status();
     }},
    {"--dmpl", nullptr, "FILE|DIR", Applies::Mesh, nullptr,
     "DMPL soft-tissue basis (.npz, key eigvec (N,3,D)): morph targets dmpl_<i>, animated from the "
     "motion's `dmpls` (weight = scale*c + offset in [0, 1], mapping in the metadata); without "
     "--motion at weight 0. DIR: per motion gender, DIR/dmpls/<gender>/model.npz or "
     "DIR/<gender>/model.npz (AMASS layout)",
     [](V v, S* s) { return s->request.dmpl = v, Status(); }, Hashed::Content},
    {"--dmpl-count", nullptr, "N", Applies::Mesh, nullptr,
     "keep the first N DMPL directions (default all)",
     [](V v, S* s) { return numberInto(v, "--dmpl-count", &s->request.dmpl_count); }},
    {"--dmpl-joints", nullptr, "fixed|regressed", Applies::Mesh, nullptr,
     "fixed (default): keep the betas-only skeleton (the cost is printed); regressed: animate "
     "joint "
     "translations to follow the displaced template (the published math, exact)",
     [](V v, S* s) {
       Result<int> c = choice(v, "--dmpl-joints", {"fixed", "regressed"});
       if (!c) return Status(c.error());
       return s->request.dmpl_regressed_joints = *c == 1, Status();
     }},
    {"--fbx-units", nullptr, "m|cm", Applies::Format, nullptr, "FBX geometry units (default m)",
     [](V v, S* s) {
       Result<int> c = choice(v, "--fbx-units", {"m", "cm"});
       if (!c) return Status(c.error());
       return s->request.writer.fbx_units = v, Status();
     }},
    {"--fbx-version", nullptr, "7400|7500", Applies::Format, nullptr,
     "FBX binary version (default 7400)",
     [](V v, S* s) {
       Result<int> c = choice(v, "--fbx-version", {"7400", "7500"});
       if (!c) return Status(c.error());
       return s->request.writer.fbx_version = *c == 0 ? 7400 : 7500, Status();
     }},
    {"--fbx-compress-level", nullptr, "N", Applies::Format, nullptr,
     "array compression, as the FBX SDK's EXP_FBX_COMPRESS_LEVEL: 0 = stored uncompressed "
     "(fastest to write and read, largest), 1..12 = deflate level (default 1)",
     [](V v, S* s) {
       return intInto(v, "--fbx-compress-level", &s->request.writer.fbx_compress_level);
     }},
    {"--bvh-units", nullptr, "m|cm", Applies::Format, nullptr,
     "BVH offsets and positions in metres (default) or centimetres",
     [](V v, S* s) {
       Result<int> c = choice(v, "--bvh-units", {"m", "cm"});
       if (!c) return Status(c.error());
       return s->request.writer.bvh_units = v, Status();
     }},
    {"--density", nullptr, "KG_M3", Applies::Format, nullptr,
     "MJCF body masses: the closed rest mesh's volume times KG_M3 (default 1000, water)",
     [](V v, S* s) {
       Result<double> d = parseNumber(v, "--density");
       if (!d) return Status(d.error());
       return s->request.writer.density = *d, Status();
     }},
    {"--mjcf-joints", nullptr, "hinge|ball", Applies::Format, nullptr,
     "MJCF joints below the root: three hinges <joint>_x/_y/_z (default) or one ball joint",
     [](V v, S* s) {
       Result<int> c = choice(v, "--mjcf-joints", {"hinge", "ball"});
       if (!c) return Status(c.error());
       return s->request.writer.mjcf_joints = v, Status();
     }},
    {"--mjcf-geoms", nullptr, "capsule|mesh", Applies::Format, nullptr,
     "MJCF collision geoms per body: a capsule (default) or the convex hull of the vertices "
     "the joint dominates",
     [](V v, S* s) {
       Result<int> c = choice(v, "--mjcf-geoms", {"capsule", "mesh"});
       if (!c) return Status(c.error());
       return s->request.writer.mjcf_geoms = v, Status();
     }},
    {"--mjcf-motors", nullptr, nullptr, Applies::Format, nullptr,
     "MJCF: a <motor> per hinge joint (ctrlrange -100..100 N m)",
     [](V, S* s) { return s->request.writer.mjcf_motors = true, Status(); }},

    {"--motion", nullptr, "FILE", Applies::Single,
     "Animation (recognised by content, not by name: AMASS, SMPLCodec .smpl, fits, AIST++, and "
     "the outputs of video, generation and hand trackers: WHAM, 4D-Humans, GVHMR, TRAM, ROMP, "
     "EasyMocap, SMPLer-X, Motion-X, MDM, HaMeR, BEAT2; the list: {motions-page}):",
     "bake FILE as an animation (repeatable: one animation each)",
     [](V v, S* s) { return s->request.motions.push_back(v), Status(); }, Hashed::Content},
    {"--motion-sequence", nullptr, "DIR", Applies::Single, nullptr,
     "one motion from per-frame files (<frame>.<ext> or <frame>_<person>.<ext>: SMPLer-X, "
     "EasyMocap, HaMeR), joined in frame order, one track per person",
     [](V v, S* s) {
       s->request.motion_sequence = v;
       return s->request.motions.push_back(v), Status();
     },
     Hashed::Content},
    {"--skip-bad-frames", nullptr, nullptr, Applies::Motion, nullptr,
     "folders of per-frame files (--motion-sequence, --hands DIR): skip an entry named like a "
     "frame that is no readable file (a folder, FIFO, device, link loop) or whose number has "
     "more than 12 digits, with a note naming it (default: an error naming it)",
     [](V, S* s) { return s->request.reading.skip_bad_frames = true, Status(); }},
    {"--max-held-frames", nullptr, "N", Applies::Motion, nullptr,
     "folders of per-frame files: at most N copies of a frame fill a gap between two frame "
     "numbers (default 1000, at most 100000); a wider gap is an error naming its frames",
     [](V v, S* s) {
       Result<int64_t> n = parseInteger(v, 0, kMaxHeldFramesLimit);
       if (!n) return Status(usageError("--max-held-frames: " + n.message()));
       return s->request.reading.max_held_frames = *n, Status();
     }},
    {"--track", nullptr, "ID|longest|all", Applies::Motion, nullptr,
     "multi-person files: the person to bake (default longest: most detections, ties to the "
     "lower id, with a note listing the others); all: one output per person, "
     "<out stem>.track<ID>.<ext>",
     [](V v, S* s) {
       Result<TrackChoice> c = parseTrackChoice(v);
       if (!c) return Status(c.error());
       return s->request.track = *c, Status();
     }},
    {"--scene", nullptr, nullptr, Applies::Single, nullptr,
     "multi-person files: every track a skinned body of its own in one .glb/.gltf/.fbx, on "
     "the file's timeline (hidden where absent), with the file's camera when it has one",
     [](V, S* s) { return s->request.scene = true, Status(); }},
    {"--source-params", nullptr, "global|incam", Applies::Motion, nullptr,
     "tools that write world and camera parameters (WHAM, GVHMR, TRAM, PromptHMR): which to read "
     "(default global, the world one)",
     [](V v, S* s) {
       Result<int> c = choice(v, "--source-params", {"global", "incam"});
       if (!c) return Status(c.error());
       s->request.reading.source_params = *c == 0 ? SourceParams::Global : SourceParams::Incam;
       return Status();
     }},
    {"--source-fps", nullptr, "R", Applies::Motion, nullptr,
     "the motion's frame rate: overrides a stored one; without it a file that stores none is read "
     "at 30 fps (AIST++: 60) and a note says so",
     [](V v, S* s) { return numberInto(v, "--source-fps", &s->request.reading.source_fps); }},
    {"--flat-hand-mean", nullptr, nullptr, Applies::Motion, nullptr,
     "fit hand poses (PCA or 45-d axis-angle) are relative to the flat hand: the model's "
     "hands_mean "
     "is not added (the authors' default adds it)",
     [](V, S* s) { return s->request.flat_hand_mean = true, Status(); }},
    {"--hands", nullptr, "FILE", Applies::Single, nullptr,
     "MANO hand tracks (HaMeR, WiLoR; a folder: per-frame files) drive the fingers of the SMPL-X "
     "/ SMPL-H --motion, frame by frame (repeatable: left and right from one or two files; a "
     "frame without a hand keeps the body's)",
     [](V v, S* s) { return s->request.hands.push_back(v), Status(); }, Hashed::Content},
    {"--hands-wrist", nullptr, nullptr, Applies::Single, nullptr,
     "with --hands: the wrists too, from the tracks' global_orient (Mano2Smpl-X); body and hands "
     "in one camera frame (--source-params incam)",
     [](V, S* s) { return s->request.hands_wrist = true, Status(); }},
    {"--fps", nullptr, "F", Applies::Motion, nullptr,
     "resample to F frames per second (slerp/lerp; default: the motion's rate)",
     [](V v, S* s) { return numberInto(v, "--fps", &s->request.animation.fps); }},
    {"--frames", nullptr, "A:B", Applies::Motion, nullptr,
     "bake source frames A (inclusive) to B (exclusive), counted in the motion file before any "
     "resampling; either may be empty (0:300 = the first 300 frames, 100: = from frame 100 on). "
     "A motion shorter than B is baked to its end with a note",
     [](V v, S* s) { return parseFrames(v, &s->request); }},
    {"--betas-from-motion", nullptr, nullptr, Applies::Motion, nullptr,
     "take the betas from the (first) motion and fail if it has none (without --betas/--betas-file "
     "the motion's betas are used when it has them, else zeros)",
     [](V, S* s) { return s->request.betas_from_motion = true, Status(); }},
    {"--up", nullptr, "y|z|-y", Applies::Motion, nullptr,
     "up axis of the motion's world (default: what the layout says: z for AMASS files, -y for the "
     "camera frames of video methods, else y); -y: a camera frame (x right, y down, z forward), "
     "turned upright by a half turn about x; output is always Y-up",
     [](V v, S* s) {
       Result<int> c = choice(v, "--up", {"y", "z", "-y"});
       if (!c) return Status(c.error());
       const UpAxis axes[] = {UpAxis::Y, UpAxis::Z, UpAxis::NegY};
       return s->request.animation.up = axes[*c], Status();
     }},
    {"--root-motion", nullptr, "keep|in-place", Applies::Motion, nullptr,
     "keep or drop horizontal root motion (default keep)",
     [](V v, S* s) {
       Result<int> c = choice(v, "--root-motion", {"keep", "in-place"});
       if (!c) return Status(c.error());
       return s->request.animation.in_place = *c == 1, Status();
     }},

    {"--motion-dir", nullptr, "DIR", Applies::Batch, "Batch mode (--motion-dir DIR --out-dir DIR):",
     "convert every .npz/.json/.smpl/.pkl in DIR, in parallel, skipping outputs made from the same "
     "inputs and options (recorded in the sidecar); per-file errors do not stop the batch; files "
     "with no pose keys (AMASS shape.npz, *_stagei.npz) are skipped with a note",
     [](V v, S* s) { return s->request.motion_dir = v, Status(); }, Hashed::No},
    {"--out-dir", nullptr, "DIR", Applies::Batch, nullptr,
     "where batch outputs go (DIR/<motion stem>.<format>)",
     [](V v, S* s) { return s->out_dir = v, Status(); }, Hashed::No},
    {"--format", nullptr, "{formats}", Applies::Batch, nullptr,
     "batch output format (default {default-format})",
     [](V v, S* s) {  // one of the writer table's rows: checked by the request
       return s->request.format = v, Status();
     }},
    {"--force", nullptr, nullptr, Applies::Batch, nullptr,
     "rebuild every output, even when up to date",
     [](V, S* s) { return s->force = true, Status(); }, Hashed::No},
    {"--threads", nullptr, "N", Applies::Any, nullptr,
     "worker threads: batch files converted at once (each compressing on one), or, for a single "
     "file, the skin fit, the corrective refit and the FBX arrays compressed at once; with 1, no "
     "stage runs beside another (the model's load and its hash, the write and the skinning-error "
     "measurement) (default: all cores; the output does not depend on it)",
     [](V v, S* s) { return numberInto(v, "--threads", &s->request.writer.threads); }, Hashed::No},
    {"--shard", nullptr, "I/N", Applies::Batch, nullptr,
     "convert only share I of N (0 <= I < N): the motions sorted by path relative to DIR, the one "
     "at position p belongs to shard p mod N",
     [](V v, S* s) { return parseShard(v, s); }, Hashed::No},
    {"--manifest", nullptr, "FILE", Applies::Batch, nullptr,
     "write one JSON line per motion (input, output, bytes, sha256, seconds, status); shards' "
     "manifests concatenate",
     [](V v, S* s) { return s->request.manifest = v, Status(); }, Hashed::No},

    {"--memory-limit", nullptr, "SIZE", Applies::Any, "General:",
     "memory budget for everything the run reads or builds, e.g. 512M, 4G (default: the smaller of "
     "8G and 3/4 of physical memory); an input that would need more fails before allocating (exit "
     "2, "
     "3 when baking)",
     [](V v, S* s) {
       Result<uint64_t> m = parseMemorySize(v);
       if (!m) return Status(usageError(m.message()));
       return s->request.memory_limit = *m, Status();
     },
     Hashed::No},
    {"--quiet", "-q", nullptr, Applies::Any, nullptr,
     "no summary, no notes (warnings and errors still go to stderr)",
     [](V, S* s) { return s->quiet = true, Status(); }, Hashed::No},
    {"--version", nullptr, nullptr, Applies::Any, nullptr, "print the version and exit",
     [](V, S* s) { return s->version = true, Status(); }, Hashed::No},
    {"--help", "-h", nullptr, Applies::Any, nullptr, "print this text and exit",
     [](V, S* s) { return s->help = true, Status(); }, Hashed::No},
};

constexpr size_t kHelpColumn = 25, kWidth = 80;  // a terminal's 80 columns

// Paragraphs ('\n') of `text` word-wrapped to `width` columns.
std::vector<std::string> wrap(const std::string& text, size_t width) {
  std::vector<std::string> lines;
  std::istringstream paragraphs(text);
  for (std::string paragraph; std::getline(paragraphs, paragraph);) {
    std::istringstream words(paragraph);
    std::string line;
    for (std::string word; words >> word;) {
      if (!line.empty() && line.size() + 1 + word.size() > width)
        lines.push_back(line), line.clear();
      line += (line.empty() ? "" : " ") + word;
    }
    lines.push_back(line);
  }
  return lines;
}

// The writer table's words in usage text (writers/writer.h): {formats}
// "glb|gltf|fbx|bvh", {default-format} "glb", {extensions} ".glb, .gltf, .fbx, .bvh",
// {extensions|} ".glb|.gltf|.fbx|.bvh".
std::string expand(std::string text) {
  std::string names, extensions, bars;
  for (const WriterFormat& row : writerFormats()) {
    names += (names.empty() ? "" : "|") + row.name;
    for (const std::string& ext : row.extensions) {
      extensions += (extensions.empty() ? "" : ", ") + ext;
      bars += (bars.empty() ? "" : "|") + ext;
    }
  }
  const std::pair<const char*, std::string> words[] = {
      {"{formats}", names},
      {"{default-format}", writerFormats().front().name},
      {"{extensions}", extensions},
      {"{extensions|}", bars},
      {"{presets}", text.find("{presets}") == std::string::npos ? "" : presetsHelp()},
      {"{motions-page}", docsPageReference("motions.md")},
      {"{retargeting-page}", docsPageReference("retargeting.md")}};
  for (const auto& [word, value] : words)
    for (size_t at; (at = text.find(word)) != std::string::npos;)
      text.replace(at, std::string(word).size(), value);
  return text;
}

// Where the pages are: the folder found beside the executable, or the
// documentation in general when there is none.
std::string docsPlace() {
  const std::string folder = docsFolder();
  return folder.empty() ? "the smpl-export documentation (docs/ in its sources)" : folder;
}

// "  --name VALUE" then the help text in a column; a long name puts the help
// on the next line.
void appendUsage(const OptionSpec& o, std::string* out) {
  std::string left = std::string("  ") + o.name;
  if (o.alias) left += std::string(", ") + o.alias;
  if (o.value) left += " " + expand(o.value);
  bool first = true;
  for (const std::string& line : wrap(expand(o.help), kWidth - kHelpColumn)) {
    if (first && left.size() + 1 <= kHelpColumn) {
      *out += left + std::string(kHelpColumn - left.size(), ' ') + line + "\n";
    } else {
      if (first) *out += left + "\n";
      *out += std::string(kHelpColumn, ' ') + line + "\n";
    }
    first = false;
  }
}

}  // namespace

const std::vector<OptionSpec>& optionTable() { return kOptions; }

const OptionSpec* findOption(const std::string& name) {
  for (const OptionSpec& o : kOptions)
    if (name == o.name || (o.alias && name == o.alias)) return &o;
  return nullptr;
}

std::string appliesRule(const OptionSpec& option) {
  switch (option.applies) {
    case Applies::Single:
      return "conflicts with batch mode (--motion-dir)";
    case Applies::Motion:
      return "needs --motion or --motion-dir";
    case Applies::Batch:
      return "applies only to batch mode (--motion-dir)";
    case Applies::Format: {
      std::string extensions;
      for (const WriterFormat& row : writerFormats())
        if (std::find(row.options.begin(), row.options.end(), option.name) != row.options.end())
          for (const std::string& ext : row.extensions)
            extensions += (extensions.empty() ? "" : ", ") + ext;
      return "applies only to " + extensions + " output";
    }
    case Applies::Mesh:
      return "needs an output format with a mesh";
    default:
      return "";
  }
}

std::string usageText() {
  std::string out =
      "smpl-export: SMPL-family body model -> rigged glTF/GLB or FBX with pose\n"
      "correctives, a BVH skeleton and motion, a MuJoCo (MJCF) model or a USD\n"
      "(UsdSkel) body\n\n"
      "Usage: smpl-export --model PATH|builtin\n"
      "         --out FILE" +
      expand("{extensions|}") + " [options]\n" +
      "       smpl-export --model PATH|DIR --motion-dir DIR --out-dir DIR [options]\n\n";
  for (const OptionSpec& o : kOptions) {
    if (o.heading && *o.heading)
      for (const std::string& line : wrap("\n" + expand(o.heading), kWidth)) out += line + "\n";
    appendUsage(o, &out);
  }
  for (const std::string& line :
       wrap("\nExit codes: 0 ok, 1 usage, 2 cannot load input, 3 cannot export, 4 cannot write "
            "output.\nReference: man smpl-export; the pages (cli.md, motions.md, ...): " +
                docsPlace(),
            kWidth))
    out += line + "\n";
  return out;
}

}  // namespace smpl
