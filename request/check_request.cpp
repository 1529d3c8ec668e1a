// checkRequest / checkRequestForModel / checkDmplCount: see check_request.h.
#include "request/check_request.h"

#include <cstdio>

#include "core/models/validate_inputs.h"
#include "exporter/skeleton_names.h"
#include "writers/writer.h"

namespace smpl {
namespace {

Error usage(const std::string& message) { return makeError(message, ErrorKind::Usage); }

std::string number(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.15g", v);
  return text;
}

// A rate in [lo, hi] (or (lo, hi] when `open_low`).
Status checkRate(const std::optional<double>& v, const char* option, double lo, double hi,
                 bool open_low) {
  if (!v || (*v >= lo && *v <= hi && !(open_low && *v == lo))) return Status();
  return usage(std::string(option) + ": expected a rate in " + (open_low ? "(" : "[") + number(lo) +
               ", " + number(hi) + "], got '" + number(*v) + "'");
}

// Values that need no model: each option's own range.
Status checkRanges(const ExportRequest& r) {
  if (Status st = checkCoefficients(r.asset.betas, "--betas", "value"); !st)
    return usage(st.message());
  if (Status st = checkCoefficients(r.asset.expression, "--expression", "value"); !st)
    return usage(st.message());
  if (Status st = checkRate(r.reading.source_fps, "--source-fps", 1, 1000, false); !st) return st;
  if (Status st = checkRate(r.animation.fps, "--fps", 0, 1000, true); !st) return st;
  if (r.reading.max_held_frames < 0 || r.reading.max_held_frames > kMaxHeldFramesLimit)
    return usage("--max-held-frames: expected 0.." + std::to_string(kMaxHeldFramesLimit) +
                 " (held copies of a frame per gap; more is a lost folder, not a pause), got '" +
                 std::to_string(r.reading.max_held_frames) + "'");
  if (r.animation.first_frame < 0)
    return usage("--frames: bad start '" + std::to_string(r.animation.first_frame) + "'");
  if (r.animation.end_frame >= 0 && r.animation.end_frame <= r.animation.first_frame)
    return usage("--frames: end must be after start in '" +
                 std::to_string(r.animation.first_frame) + ":" +
                 std::to_string(r.animation.end_frame) + "'");
  if (!(r.writer.morph_epsilon >= 0 && r.writer.morph_epsilon <= 0.01))
    return usage("--corrective-epsilon: expected metres in [0, 0.01], got '" +
                 number(r.writer.morph_epsilon) + "'");
  if (r.writer.fbx_compress_level < 0 || r.writer.fbx_compress_level > 12)
    return usage("--fbx-compress-level: expected 0..12, got '" +
                 std::to_string(r.writer.fbx_compress_level) + "'");
  if (r.writer.threads && (*r.writer.threads < 1 || *r.writer.threads > 1024))
    return usage("--threads: expected 1..1024, got '" + std::to_string(*r.writer.threads) + "'");
  if (!(r.writer.density > 0 && r.writer.density <= 1e5))
    return usage("--density: expected kg/m^3 in (0, 100000], got '" + number(r.writer.density) +
                 "'");
  if (r.writer.mjcf_joints != "hinge" && r.writer.mjcf_joints != "ball")
    return usage("--mjcf-joints: expected 'hinge' or 'ball', got '" + r.writer.mjcf_joints + "'");
  if (r.writer.mjcf_motors && r.writer.mjcf_joints != "hinge")
    return usage("--mjcf-motors drives hinge joints: it conflicts with --mjcf-joints ball");
  if (r.writer.mjcf_geoms != "capsule" && r.writer.mjcf_geoms != "mesh")
    return usage("--mjcf-geoms: expected 'capsule' or 'mesh', got '" + r.writer.mjcf_geoms + "'");
  if (r.dmpl_count && *r.dmpl_count < 1)
    return usage("--dmpl-count: expected N >= 1, got '" + std::to_string(*r.dmpl_count) + "'");
  return Status();
}

// Size options that would otherwise be silently ignored together.
Status checkMorphOptions(const ExportRequest& r) {
  if (r.asset.corrective_basis > 0 && !r.asset.correctives)
    return usage("--corrective-basis conflicts with --correctives none");
  if (r.asset.encoding != CorrectiveEncoding::Auto && !r.asset.correctives)
    return usage(
        "--corrective-weights conflicts with --correctives none (no corrective targets to encode)");
  if (r.asset.quantize_morphs && !r.asset.correctives)
    return usage(
        "--quantize-morphs quantizes corrective targets; with --correctives none there are none");
  if (r.writer.morph_epsilon > 0 && !r.asset.correctives && r.asset.shape_keys == 0 &&
      r.asset.expression_keys == 0)
    return usage(
        "--corrective-epsilon thins morph targets; with --correctives none and no --shape-keys/"
        "--expression-keys there are none");
  if (r.writer.quantize_animation && r.motions.empty() && r.motion_dir.empty())
    return usage(
        "--quantize-animation quantises animation keys; without --motion or --motion-dir there are "
        "none");
  if (r.asset.corrective_basis > 0 && r.asset.encoding == CorrectiveEncoding::Split)
    return usage(
        "--corrective-basis conflicts with --corrective-weights split (basis weights are signed or "
        "unit)");
  return Status();
}

// --hands drives one body clip; --hands-wrist needs it.
Status checkHandOptions(const ExportRequest& r) {
  if (r.hands_wrist && r.hands.empty()) return usage("--hands-wrist needs --hands FILE");
  if (r.hands.empty()) return Status();
  if (r.hands.size() > 2)
    return usage("--hands: " + std::to_string(r.hands.size()) +
                 " files; give at most two (the left and the right hand)");
  if (r.motions.size() != 1)
    return usage(
        "--hands drives the fingers of one body clip: give one --motion or "
        "--motion-sequence");
  if (r.track.kind == TrackChoice::Kind::All)
    return usage("--hands drives one body: give --track ID (or longest), not --track all");
  return Status();
}

Status checkConflicts(const ExportRequest& r) {
  if (r.model.empty()) return usage("missing --model PATH (use --model builtin for the demo body)");
  if (!r.asset.betas.empty() && !r.betas_file.empty())
    return usage("--betas and --betas-file conflict: give one");
  if (r.betas_from_motion && (!r.asset.betas.empty() || !r.betas_file.empty()))
    return usage("--betas-from-motion conflicts with --betas/--betas-file");
  if (r.dmpl_count && r.dmpl.empty()) return usage("--dmpl-count needs --dmpl");
  if (r.dmpl_regressed_joints && r.dmpl.empty()) return usage("--dmpl-joints needs --dmpl");
  if (r.track.kind == TrackChoice::Kind::All && !r.motion_dir.empty())
    return usage(
        "--track all writes one output per person of one motion; in batch mode give --track "
        "longest or a track id");
  if (r.track.kind == TrackChoice::Kind::All && r.motions.size() != 1)
    return usage(
        "--track all writes one output per person: give one --motion or --motion-sequence");
  if (r.asset.root_bone && r.asset.origin == Origin::Model)
    return usage(
        "--root-bone conflicts with --origin model (the root bone stands on the floor: it implies "
        "--origin floor)");
  if (!r.motion_sequence.empty() && r.motions.size() != 1)
    return usage("--motion-sequence DIR is the run's one motion: it conflicts with --motion");
  if (Status st = checkHandOptions(r); !st) return st;
  return checkMorphOptions(r);
}

// A format without a mesh (writer.h needs_mesh false) refuses what only a mesh has.
Status checkMeshOptions(const ExportRequest& r, const WriterFormat& format) {
  const char* option = !r.dmpl.empty()                ? "--dmpl"
                       : r.asset.shape_keys > 0       ? "--shape-keys"
                       : r.asset.expression_keys > 0  ? "--expression-keys"
                       : !r.asset.uv_obj.empty()      ? "--uv"
                       : r.asset.corrective_basis > 0 ? "--corrective-basis"
                       : r.asset.quantize_morphs      ? "--quantize-morphs"
                                                      : nullptr;
  if (!option) return Status();
  return usage(std::string(option) + " needs an output format with a mesh; " + format.name +
               " output has none");
}

// A count option against what the model has: "--shape-keys 12: the model has 10 shape directions".
Status checkCount(int value, int available, const char* option, const char* what) {
  if (value >= 0 && value <= available) return Status();
  return usage(std::string(option) + " " + std::to_string(value) + ": the model has " +
               std::to_string(available) + " " + what);
}

}  // namespace

// --scene: every track of one motion file in one file, in the file's world
// and on its timeline, so nothing may pick, cut or move a body on its own.
Status checkSceneOptions(const ExportRequest& r, const WriterFormat& format) {
  if (!r.scene) return Status();
  if (!format.writer || !format.writer->writesScenes())
    return usage("--scene: " + format.name +
                 " output cannot hold several bodies on one timeline; write .glb, .gltf or .fbx");
  if (r.motions.size() != 1)
    return usage("--scene: give one --motion (or --motion-sequence) holding the tracks; got " +
                 std::to_string(r.motions.size()));
  if (r.track.kind == TrackChoice::Kind::Id)
    return usage("--scene exports every track; --track " + r.track.id +
                 " picks one: give one or the other");
  if (r.track.kind == TrackChoice::Kind::All)
    return usage(
        "--scene writes every track into one file; --track all writes one file per track: give "
        "one or the other");
  if (r.animation.first_frame != 0 || r.animation.end_frame >= 0)
    return usage("--scene exports the file's whole timeline: --frames is not supported with it");
  if (r.asset.root_bone || r.asset.origin == Origin::Floor)
    return usage(
        "--scene keeps every body in the file's world: --origin floor and --root-bone (which "
        "raise each body by its own rest height) are not supported with it");
  if (r.animation.in_place)
    return usage(
        "--scene keeps every body in the file's world: --root-motion in-place is not supported "
        "with it");
  return Status();
}

Status checkRequestOptions(const ExportRequest& r) {
  if (Status st = checkRanges(r); !st) return st;
  return checkConflicts(r);
}

Status checkRequest(const ExportRequest& r) {
  if (Status st = checkRequestOptions(r); !st) return st;
  if (r.out.empty() && r.motion_dir.empty())
    return usage("missing --out FILE (" + writerExtensionList() + ")");
  const WriterFormat* format = r.out.empty() ? batchFormat(r) : writerFormatForPath(r.out);
  if (!format && r.out.empty()) {
    std::string names;  // the writer table's rows
    for (size_t i = 0; i < writerFormats().size(); ++i)
      names += std::string(i == 0                            ? ""
                           : i + 1 == writerFormats().size() ? " or "
                                                             : ", ") +
               "'" + writerFormats()[i].name + "'";
    return usage("--format: expected " + names + ", got '" + r.format + "'");
  }
  if (!format)
    return usage("--out " + r.out + ": unknown format (expected " + writerExtensionList() + ")");
  if (r.writer.draco && !dracoAvailable())
    return usage(
        "--draco: this smpl-export was built without Draco (the Windows and WebAssembly builds: "
        "Debian ships no Draco for them); use --meshopt, or a Linux build");
  if (r.writer.meshopt && !meshoptAvailable())
    return usage(
        "--meshopt: this smpl-export was built without meshoptimizer (the static build: "
        "Debian ships no static libmeshoptimizer); use the Debian package build");
  if (format->single_clip && r.motions.size() > 1)
    return usage("--motion: " + format->name + " output holds one motion; got " +
                 std::to_string(r.motions.size()) + " (one output per motion: --motion-dir)");
  if (!format->animated && (!r.motions.empty() || !r.motion_dir.empty()))
    return usage(std::string(r.motion_dir.empty() ? "--motion" : "--motion-dir") + ": " +
                 format->name + " output holds no animation (the model only)");
  if (Status st = checkSceneOptions(r, *format); !st) return st;
  if (r.asset.rest_pose == RestPose::A && format->needs_mesh)
    return usage(
        "--rest-pose a applies only to .bvh for now: a skinned mesh bound at an A pose deforms "
        "differently under linear blend skinning, and MJCF and USD keep the model's rest "
        "(docs/retargeting.md \"A-pose rest\")");
  return format->needs_mesh ? Status() : checkMeshOptions(r, *format);
}

Status checkRequestForModel(const ExportRequest& r, const std::vector<double>& betas,
                            const BodyModel& model) {
  if (static_cast<int>(betas.size()) > model.numBetas())
    return usage("betas: " + std::to_string(betas.size()) + " values given; the model " +
                 model.name + " has " + std::to_string(model.numBetas()));
  if (static_cast<int>(r.asset.expression.size()) > model.numExpressions())
    return usage("expression: " + std::to_string(r.asset.expression.size()) +
                 " values given; the model " + model.name + " has " +
                 std::to_string(model.numExpressions()));
  if (r.asset.max_influences != kAllInfluences &&
      (r.asset.max_influences < 1 || r.asset.max_influences > model.numJoints()))
    return usage("--max-influences must be between 1 and " + std::to_string(model.numJoints()) +
                 " (the model's joints) or 'all', got " + std::to_string(r.asset.max_influences));
  if (Status st =
          checkCount(r.asset.shape_keys, model.numBetas(), "--shape-keys", "shape directions");
      !st)
    return st;
  if (Status st = checkCount(r.asset.expression_keys, model.numExpressions(), "--expression-keys",
                             "expression directions");
      !st)
    return st;
  if (r.asset.skeleton_names != SkeletonNames::Smpl && model.kind == ModelKind::Mano)
    return usage(std::string("--skeleton-names ") + skeletonNamesName(r.asset.skeleton_names) +
                 ": the model " + model.name +
                 " is a MANO hand alone; the Mixamo and UE5 names are for SMPL, SMPL-H and SMPL-X "
                 "bodies");
  if (r.asset.rest_pose == RestPose::A && model.kind == ModelKind::Mano)
    return usage("--rest-pose a: the model " + model.name +
                 " is a MANO hand alone; an A pose lowers the arms of a body");
  const int p = model.numPoseFeatures();
  if (r.asset.corrective_basis < 0 || r.asset.corrective_basis > p)
    return usage("--corrective-basis " + std::to_string(r.asset.corrective_basis) +
                 ": expected 1.." + std::to_string(p) + " (the model has " + std::to_string(p) +
                 " pose correctives)");
  return Status();
}

const WriterFormat* batchFormat(const ExportRequest& r) {
  return r.format.empty() ? &writerFormats().front() : writerFormatByName(r.format);
}

Status checkDmplCount(const ExportRequest& r, int directions) {
  if (!r.dmpl_count || *r.dmpl_count <= directions) return Status();
  return makeError("--dmpl-count " + std::to_string(*r.dmpl_count) + ": the basis has " +
                       std::to_string(directions) + " directions",
                   ErrorKind::Load);
}

}  // namespace smpl
