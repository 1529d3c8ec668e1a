#include "cli/settings.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/io/npy.h"
#include "core/io/npz.h"
#include "core/io/printable.h"
#include "core/load/betas_rows.h"
#include "core/load/validate_inputs.h"
#include "core/memory_budget.h"

namespace smpl {
namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

Result<double> parseNumber(const std::string& text, const std::string& option) {
  errno = 0;
  char* end = nullptr;
  double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || errno != 0 || !std::isfinite(v))
    return makeError(option + ": '" + text + "' is not a finite number");
  return v;
}

Result<int> parseInt(const std::string& text, const std::string& option) {
  Result<double> v = parseNumber(text, option);
  if (!v || *v != std::floor(*v) || std::abs(*v) > 1e6) return makeError(option + ": '" + text + "' is not an integer");
  return static_cast<int>(*v);
}

Result<std::vector<double>> parseList(const std::string& text, const std::string& option) {
  std::vector<double> values;
  size_t start = 0;
  while (start <= text.size()) {
    size_t comma = text.find(',', start);
    std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    Result<double> v = parseNumber(item, option);
    if (!v) return v.error();
    values.push_back(*v);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return values;
}

// "A:B" (B exclusive, either may be empty) -> frame range.
Status parseFrames(const std::string& value, AnimationOptions* a) {
  size_t colon = value.find(':');
  if (colon == std::string::npos) return makeError("--frames: expected A:B, got '" + value + "'");
  const std::string first = value.substr(0, colon), end = value.substr(colon + 1);
  if (!first.empty()) {
    Result<int> v = parseInt(first, "--frames");
    if (!v || *v < 0) return makeError("--frames: bad start '" + first + "'");
    a->first_frame = *v;
  }
  if (!end.empty()) {
    Result<int> v = parseInt(end, "--frames");
    if (!v || *v <= a->first_frame) return makeError("--frames: end must be after start in '" + value + "'");
    a->end_frame = *v;
  }
  return Status();
}

// "I/N", 0 <= I < N: this run's share of a batch (cli/batch_shard.h).
Status parseShard(const std::string& value, Settings* s) {
  const size_t slash = value.find('/');
  Result<int> i = parseInt(value.substr(0, slash), "--shard");
  Result<int> n = parseInt(slash == std::string::npos ? "" : value.substr(slash + 1), "--shard");
  if (!i || !n || *n < 1 || *i < 0 || *i >= *n)
    return makeError("--shard: expected I/N with 0 <= I < N (e.g. 0/8), got '" + value + "'");
  s->shard_index = *i;
  s->shard_count = *n;
  return Status();
}

// One option with its value; returns an error for unknown names.
Status applyOption(const std::string& name, const std::string& value, Settings* s) {
  ExportOptions& e = s->export_options;
  auto intInto = [&](int* target) -> Status {
    Result<int> v = parseInt(value, name);
    if (!v) return v.error();
    *target = *v;
    return Status();
  };
  if (name == "--motion") s->motions.push_back(value);
  else if (name == "--motion-dir") s->motion_dir = value;
  else if (name == "--out-dir") s->out_dir = value;
  else if (name == "--threads") return intInto(&s->threads);
  else if (name == "--format") {
    if (value != "glb" && value != "gltf" && value != "fbx") return makeError("--format: expected glb, gltf or fbx, got '" + value + "'");
    s->format = value;
  } else if (name == "--fps") {
    Result<double> v = parseNumber(value, name);
    if (!v || *v <= 0 || *v > 1000) return makeError("--fps: expected a rate in (0, 1000], got '" + value + "'");
    s->animation.fps = *v;
  } else if (name == "--source-fps") {
    Result<double> v = parseNumber(value, name);
    if (!v || *v < 1 || *v > 1000) return makeError("--source-fps: expected a rate in [1, 1000], got '" + value + "'");
    s->source_fps = *v;
  } else if (name == "--shard") {
    return parseShard(value, s);
  } else if (name == "--manifest") {
    s->manifest = value;
  } else if (name == "--frames") {
    return parseFrames(value, &s->animation);
  } else if (name == "--up") {
    if (value != "y" && value != "z") return makeError("--up: expected 'y' or 'z', got '" + value + "'");
    s->animation.up = value == "y" ? UpAxis::Y : UpAxis::Z;
  } else if (name == "--root-motion") {
    if (value != "keep" && value != "in-place") return makeError("--root-motion: expected 'keep' or 'in-place', got '" + value + "'");
    s->animation.in_place = value == "in-place";
  } else if (name == "--memory-limit") {
    Result<uint64_t> v = parseMemorySize(value);
    if (!v) return v.error();
    s->memory_limit = *v;
  } else if (name == "--model") s->model = value;
  else if (name == "--out") s->out = value;
  else if (name == "--betas-file") s->betas_file = value;
  else if (name == "--uv") e.uv_obj = value;
  else if (name == "--name") e.name = value;
  else if (name == "--max-influences") return intInto(&e.max_influences);
  else if (name == "--shape-keys") return intInto(&e.shape_keys);
  else if (name == "--expression-keys") return intInto(&e.expression_keys);
  else if (name == "--betas" || name == "--expression") {
    Result<std::vector<double>> v = parseList(value, name);
    if (!v) return v.error();
    if (Status st = checkCoefficients(*v, name, "value"); !st) return st;
    (name == "--betas" ? e.betas : e.expression) = *v;
  } else if (name == "--correctives") {
    if (value != "all" && value != "none") return makeError("--correctives: expected 'all' or 'none', got '" + value + "'");
    e.correctives = value == "all";
  } else if (name == "--corrective-epsilon") {
    Result<double> v = parseNumber(value, name);
    if (!v || *v < 0 || *v > 0.01) return makeError("--corrective-epsilon: expected metres in [0, 0.01], got '" + value + "'");
    s->writer_options.morph_epsilon = *v;
  } else if (name == "--corrective-basis") {
    return intInto(&e.corrective_basis);
  } else if (name == "--corrective-weights") {
    if (value != "signed" && value != "unit") return makeError("--corrective-weights: expected 'signed' or 'unit', got '" + value + "'");
    e.encoding = value == "unit" ? CorrectiveEncoding::Unit : CorrectiveEncoding::Signed;
  } else if (name == "--dmpl") {
    s->dmpl = value;
  } else if (name == "--dmpl-count") {
    Status st = intInto(&s->dmpl_count);
    if (st && s->dmpl_count < 1) return makeError("--dmpl-count: expected N >= 1, got '" + value + "'");
    return st;
  } else if (name == "--dmpl-joints") {
    if (value != "fixed" && value != "regressed") return makeError("--dmpl-joints: expected 'fixed' or 'regressed', got '" + value + "'");
    s->dmpl_regressed_joints = value == "regressed";
  } else if (name == "--fbx-version") {
    if (value != "7400" && value != "7500") return makeError("--fbx-version: expected 7400 or 7500, got '" + value + "'");
    s->writer_options.fbx_version = value == "7400" ? 7400 : 7500;
  } else if (name == "--fbx-units") {
    if (value != "m" && value != "cm") return makeError("--fbx-units: expected 'm' or 'cm', got '" + value + "'");
    s->writer_options.fbx_units = value;
  } else {
    return makeError("unknown option '" + name + "' (see --help)");
  }
  return Status();
}

Status checkConflicts(const Settings& s, const std::vector<std::string>& given) {
  auto has = [&](const char* o) { return std::find(given.begin(), given.end(), o) != given.end(); };
  if (s.model.empty()) return makeError("missing --model PATH (use --model builtin for the demo body)");
  if (has("--betas") && has("--betas-file")) return makeError("--betas and --betas-file conflict: give one");
  if (has("--betas-from-motion") && s.betas_given) return makeError("--betas-from-motion conflicts with --betas/--betas-file");
  if (has("--corrective-basis") && !s.export_options.correctives)
    return makeError("--corrective-basis conflicts with --correctives none");
  const bool batch = !s.motion_dir.empty() || !s.out_dir.empty();
  const bool animated = !s.motions.empty() || batch;
  for (const char* o : {"--dmpl-count", "--dmpl-joints"})
    if (has(o) && s.dmpl.empty()) return makeError(std::string(o) + " needs --dmpl");
  for (const char* o : {"--fps", "--frames", "--up", "--root-motion", "--betas-from-motion", "--source-fps",
                        "--flat-hand-mean"})
    if (has(o) && !animated) return makeError(std::string(o) + " needs --motion or --motion-dir");
  if (batch) {
    if (s.motion_dir.empty() || s.out_dir.empty()) return makeError("batch mode needs both --motion-dir and --out-dir");
    if (!s.out.empty() || !s.motions.empty()) return makeError("--motion-dir/--out-dir conflict with --out/--motion");
    if (has("--fbx-units") && s.format != "fbx") return makeError("--fbx-units applies only to --format fbx");
    return Status();
  }
  if (has("--format") || has("--threads") || has("--force") || has("--shard") || has("--manifest"))
    return makeError("--format, --threads, --force, --shard and --manifest apply only to batch mode (--motion-dir)");
  if (s.out.empty()) return makeError("missing --out FILE (.glb, .gltf or .fbx)");
  const bool fbx = endsWith(s.out, ".fbx");
  if (!fbx && !endsWith(s.out, ".glb") && !endsWith(s.out, ".gltf"))
    return makeError("--out " + s.out + ": unknown format (expected .glb, .gltf or .fbx)");
  for (const char* o : {"--fbx-units", "--fbx-version"})
    if (has(o) && !fbx) return makeError(std::string(o) + " applies only to .fbx output");
  for (const char* o : {"--corrective-epsilon", "--quantize-morphs", "--draco"})
    if (has(o) && fbx) return makeError(std::string(o) + " applies only to glTF output");
  return Status();
}

const char* const kFlags[] = {"--help", "-h", "--version", "--quiet", "-q", "--betas-from-motion", "--quantize-morphs", "--draco", "--force",
                              "--flat-hand-mean"};

}  // namespace

Result<Settings> parseSettings(int argc, const char* const* argv) {
  Settings s;
  std::vector<std::string> given;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    std::string value;
    if (size_t eq = arg.find('='); arg.rfind("--", 0) == 0 && eq != std::string::npos) {
      value = arg.substr(eq + 1);
      arg = arg.substr(0, eq);
    } else if (std::find(std::begin(kFlags), std::end(kFlags), arg) == std::end(kFlags)) {
      if (arg.rfind("-", 0) != 0)
        return makeError("unexpected argument '" + printable(arg) + "': options start with -- (see --help)");
      if (i + 1 >= argc) {  // an unknown option says so, rather than asking for a value
        Settings probe;
        Status known = applyOption(arg, "", &probe);
        if (!known && known.message().rfind("unknown option", 0) == 0) return known.error();
        return makeError("option " + arg + " needs a value");
      }
      value = argv[++i];
    }
    if (arg != "--motion" && std::find(given.begin(), given.end(), arg) != given.end())
      return makeError("option " + arg + " given twice");
    given.push_back(arg);
    s.given_options.emplace_back(arg, value);
    if (arg == "--help" || arg == "-h") s.help = true;
    else if (arg == "--version") s.version = true;
    else if (arg == "--quiet" || arg == "-q") s.quiet = true;
    else if (arg == "--betas-from-motion") continue;  // the default without --betas; checked below
    else if (arg == "--quantize-morphs") s.writer_options.quantize_morphs = true;
    else if (arg == "--draco") s.writer_options.draco = true;
    else if (arg == "--force") s.force = true;
    else if (arg == "--flat-hand-mean") s.flat_hand_mean = true;
    else if (Status st = applyOption(arg, value, &s); !st) return st.error();
  }
  s.betas_given = std::find(given.begin(), given.end(), "--betas") != given.end() ||
                  std::find(given.begin(), given.end(), "--betas-file") != given.end();
  s.writer_options.binary = !endsWith(s.out, ".gltf") && s.format != "gltf";
  if (s.help || s.version) return s;
  if (Status st = checkConflicts(s, given); !st) return st.error();
  return s;
}

Result<std::vector<double>> readBetasFile(const std::string& path, std::string* note) {
  if (endsWith(path, ".npy") || endsWith(path, ".npz")) {
    Array a;
    if (endsWith(path, ".npy")) {
      Result<Array> r = readNpyFile(path);
      if (!r) return r.error();
      a = std::move(*r);
    } else {
      Result<ArrayDict> d = readNpzFile(path, {"betas"});  // lazy: other members are not read
      if (!d) return d.error();
      auto it = d->find("betas");
      if (it == d->end()) return makeError(path + ": missing key 'betas'");
      a = it->second;
    }
    Result<BetasRows> rows = collapseBetasRows(a, path);  // (B,), (1,B) or per frame (T,B)
    if (!rows) return rows.error();
    if (rows->averaged && note) *note = betasRowsNote(*rows);
    return rows->betas;
  }
  std::ifstream in(path);
  if (!in) return makeError(path + ": cannot open");
  nlohmann::json j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) return makeError(path + ": not valid JSON");
  if (j.is_object() && j.contains("betas")) j = j["betas"];
  if (!j.is_array()) return makeError(path + ": expected a JSON array of numbers or {\"betas\": [...]}");
  std::vector<double> betas;
  for (const auto& v : j) {
    if (!v.is_number() || !std::isfinite(v.get<double>())) return makeError(path + ": 'betas' holds a non-number");
    betas.push_back(v.get<double>());
  }
  return betas;
}

std::string usageText() {
  return R"(smpl-export: SMPL-family body model -> rigged glTF/GLB or FBX with pose correctives

Usage: smpl-export --model PATH|builtin --out FILE.glb|.gltf|.fbx [options]

  --model PATH|DIR|builtin  model file (.npz or .pkl from the model's authors); a folder of released model
                         files (picked per motion by kind and gender: SMPL_FEMALE.pkl, smplx/SMPLX_MALE.npz,
                         AMASS smplh/male/model.npz, ...); or the built-in demo body
  --out FILE             output; format from the extension. Also writes FILE.smpl.json (metadata)
  --betas v,v,...        shape coefficients (fewer than the model has are zero-padded)
  --betas-file FILE      betas from .npy, .npz (key 'betas') or .json; per-frame (T,B) betas:
                         identical rows -> that row, else their mean (a note gives the deviation)
  --expression v,v,...   SMPL-X expression coefficients
  --max-influences N     skin influences per vertex, 1..8 (default 4; >4 writes JOINTS_1/WEIGHTS_1)
  --correctives all|none pose-corrective morph targets (default all)
  --corrective-weights signed|unit
                         signed: weight = pose feature f, in [-2, 1] (default without --motion);
                         unit: weight = 0.5 f + 0.5 (off-diagonal) or + 1 (diagonal), in [0, 1],
                         for engines/importers that clamp weights (default with --motion: Blender
                         clamps animated weights); the mapping is in the metadata
  --corrective-basis K   replace the corrective targets by K principal components of posedirs
                         (weights = C f; C in the metadata; runtime scripts apply it)
  --corrective-epsilon M glTF: drop morph deltas up to M metres, write sparse accessors
  --quantize-morphs      glTF: int16 morph deltas (KHR_mesh_quantization)
  --draco                glTF: Draco-compress the base mesh (KHR_draco_mesh_compression)
  --shape-keys N         also export the first N shape directions as morph targets shape_<i>
  --expression-keys N    also export the first N expression directions (SMPL-X) as expr_<i>
  --uv OBJ|NPY|none      UVs (seams split vertices). Default: the model file's own vt/ft if it has
                         them (SMPL-X release). OBJ sharing the model's vertex order, or a numpy pair
                         <stem>_uv.npy (U,2) + <stem>_ft.npy (F,3) (give either); none: no UVs
  --name NAME            mesh name (default body)
  --dmpl FILE|DIR        DMPL soft-tissue basis (.npz, key eigvec (N,3,D)): morph targets dmpl_<i>,
                         animated from the motion's `dmpls` (weight = scale*c + offset in [0, 1], mapping
                         in the metadata); without --motion at weight 0. DIR: per motion gender,
                         DIR/dmpls/<gender>/model.npz or DIR/<gender>/model.npz (AMASS layout)
  --dmpl-count N         keep the first N DMPL directions (default all)
  --dmpl-joints fixed|regressed  fixed (default): keep the betas-only skeleton (the cost is printed);
                         regressed: animate joint translations to follow the displaced template (exact)
  --fbx-units m|cm       FBX geometry units (default m)
  --fbx-version 7400|7500  FBX binary version (default 7400)

Animation (recognised by content: AMASS .npz, SMPL (T,72), .npz/.json with `poses` axis-angle or
rotation matrices, SMPLCodec .smpl, SMPL-X/SMPL fits .pkl/.npz (SMPLify-X, PIXIE, ExPose), AIST++ .pkl):
  --motion FILE          bake FILE as an animation (repeatable: one animation each)
  --source-fps R         the motion's frame rate: overrides a stored one; without it a file that stores
                         none is read at 30 fps (AIST++: 60) and a note says so
  --flat-hand-mean       fit hand poses (PCA or 45-d axis-angle) are relative to the flat hand: the
                         model's hands_mean is not added (the authors' default adds it)
  --fps F                resample to F frames per second (slerp/lerp; default: the motion's rate)
  --frames A:B           source frames A (inclusive) to B (exclusive); either may be empty
  --betas-from-motion    use the motion's betas (the default when no --betas/--betas-file)
  --up y|z               up axis of the motion's world (default: z for AMASS files, else y);
                         output is always Y-up
  --root-motion keep|in-place   keep or drop horizontal root motion (default keep)
  --motion-dir DIR --out-dir DIR  batch: convert every .npz/.json/.smpl/.pkl in DIR, in parallel,
                         skipping outputs made from the same inputs and options (recorded in the
                         sidecar); per-file errors do not stop the batch; files with no pose keys
                         (AMASS shape.npz, *_stagei.npz) are skipped with a note
  --force                batch: rebuild every output, even when up to date
  --shard I/N            batch: convert only share I of N (0 <= I < N): the motions sorted by path
                         relative to DIR, the one at position p belongs to shard p mod N
  --manifest FILE        batch: write one JSON line per motion (input, output, bytes, sha256,
                         seconds, status); shards' manifests concatenate
  --format glb|gltf|fbx  batch output format (default glb)
  --threads N            batch workers (default: all cores)
  --memory-limit SIZE    memory budget for everything the run reads or builds, e.g. 512M, 4G
                         (default: the smaller of 8G and 3/4 of physical memory); an input
                         that would need more fails before allocating (exit 2, 3 when baking)
  --quiet, -q            no summary
  --version, --help

Exit codes: 0 ok, 1 usage, 2 cannot load input, 3 cannot export, 4 cannot write output.
)";
}

}  // namespace smpl
