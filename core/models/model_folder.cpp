#include "core/models/model_folder.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <regex>
#include <tuple>

#include "core/io/printable.h"
#include "core/os/path.h"

namespace smpl {
namespace {

struct Candidate {
  std::string path;
  ModelKind kind;
  std::string gender;
  std::string ext;
  bool in_kind_folder;  // DIR/<kind>/..., as smplx.create looks
};

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool kindFromName(const std::string& name, ModelKind* kind) {
  if (name == "smpl")
    *kind = ModelKind::Smpl;
  else if (name == "smplh" || name == "smpl+h" || name == "smpl_h")
    *kind = ModelKind::SmplH;
  else if (name == "smplx" || name == "smpl-x" || name == "smpl_x")
    *kind = ModelKind::SmplX;
  else if (name == "mano")
    *kind = ModelKind::Mano;
  else
    return false;
  return true;
}

// Recognises one relative path; false if it is not a model file name we know.
bool classify(const std::string& rel, Candidate* c) {
  const std::string l = lower(rel);
  std::vector<std::string> parts;
  for (size_t start = 0;;) {
    const size_t slash = l.find('/', start);
    parts.push_back(
        l.substr(start, slash == std::string::npos ? std::string::npos : slash - start));
    if (slash == std::string::npos) break;
    start = slash + 1;
  }
  const std::string& file = parts.back();
  const size_t dot = file.rfind('.');
  if (dot == std::string::npos) return false;
  c->ext = file.substr(dot + 1);
  if (c->ext != "pkl" && c->ext != "npz") return false;
  const std::string stem = file.substr(0, dot);
  c->path = rel;
  std::smatch m;
  static const std::regex released("(smpl|smplh|smplx|mano)_(female|male|neutral|right|left)");
  static const std::regex basic("basicmodel_(f|m|neutral)_lbs_10_207_0_v1\\.[01]\\.0");
  if (std::regex_match(stem, m, released)) {
    kindFromName(m[1], &c->kind);
    c->gender = m[2];
    if ((c->kind == ModelKind::Mano) != (c->gender == "right" || c->gender == "left")) return false;
  } else if (std::regex_match(stem, m, basic)) {
    c->kind = ModelKind::Smpl;
    c->gender = normalizeGender(m[1]);
  } else if (stem == "model" && parts.size() >= 3 &&
             kindFromName(parts[parts.size() - 3], &c->kind) &&
             !normalizeGender(parts[parts.size() - 2]).empty()) {
    c->gender = normalizeGender(parts[parts.size() - 2]);  // AMASS: smplh/male/model.npz
  } else {
    return false;
  }
  c->in_kind_folder = parts.size() >= 2 && [&] {
    ModelKind k;
    return kindFromName(parts[parts.size() - 2], &k) ||
           (parts.size() >= 3 && kindFromName(parts[parts.size() - 3], &k));
  }();
  return true;
}

const char* defaultExt(ModelKind kind) { return kind == ModelKind::SmplX ? "npz" : "pkl"; }

// Best of the candidates of one kind and gender: the authors' extension, then
// a file in the kind's folder, then the shortest path, then name order.
const Candidate* best(const std::vector<Candidate>& all, ModelKind kind,
                      const std::string& gender) {
  const Candidate* pick = nullptr;
  auto rank = [&](const Candidate& c) {
    return std::make_tuple(c.ext != defaultExt(kind), !c.in_kind_folder, c.path.size(), c.path);
  };
  for (const Candidate& c : all)
    if (c.kind == kind && c.gender == gender && (!pick || rank(c) < rank(*pick))) pick = &c;
  return pick;
}

// The first 8 paths, comma-separated.
std::string firstPaths(const std::vector<std::string>& paths) {
  std::string s;
  for (size_t i = 0; i < paths.size() && i < 8; ++i) s += (i ? ", " : "") + printable(paths[i]);
  return s + (paths.size() > 8 ? ", ... (" + std::to_string(paths.size()) + " files)" : "");
}

// What the folder held: the model files recognised, else every file seen.
std::string listing(const std::vector<Candidate>& all, const std::vector<std::string>& files) {
  if (all.empty())
    return std::string(
               "no model files with the released names (e.g. SMPLX_NEUTRAL.npz, SMPL_FEMALE.pkl)") +
           (files.empty() ? "; no files in it or its subfolders"
                          : "; files seen: " + firstPaths(files));
  std::vector<std::string> paths;
  for (const Candidate& c : all) paths.push_back(c.path);
  return "found " + firstPaths(paths);
}

}  // namespace

std::string normalizeGender(const std::string& gender) {
  const std::string g = lower(gender);
  if (g == "female" || g == "f") return "female";
  if (g == "male" || g == "m") return "male";
  if (g == "neutral" || g == "n" || g.empty()) return "neutral";
  return "";
}

Result<ModelFileChoice> chooseModelFile(const std::vector<std::string>& files,
                                        std::optional<ModelKind> kind, const std::string& gender,
                                        const std::string& folder) {
  std::vector<Candidate> all;
  for (const std::string& f : files) {
    Candidate c;
    if (classify(f, &c)) all.push_back(c);
  }
  if (!kind) {
    for (ModelKind k : {ModelKind::SmplX, ModelKind::SmplH, ModelKind::Smpl, ModelKind::Mano})
      if (std::any_of(all.begin(), all.end(), [&](const Candidate& c) { return c.kind == k; })) {
        kind = k;
        break;
      }
    if (!kind) return makeError(folder + ": " + listing(all, files));
  }
  std::string want = *kind != ModelKind::Mano ? normalizeGender(gender)
                     : gender == "left"       ? "left"  // a left hand (HaMeR): MANO_LEFT
                                              : "right";
  std::string note;
  if (want.empty()) {
    note = "gender '" + gender + "' is not female, male or neutral; ";
    want = "neutral";
  }
  const Candidate* c = best(all, *kind, want);
  if (!c && want == "left") {  // the right hand model, mirrored by the export (hand_side.h)
    note = "no MANO_LEFT model in " + folder + "; ";
    c = best(all, *kind, "right");
    want = "right";
  }
  if (!c && want != "neutral" && *kind != ModelKind::Mano) {
    note = "no " + want + " " + modelKindLabel(*kind) + " model in " + folder + "; ";
    c = best(all, *kind, "neutral");
  }
  if (!c)
    return makeError(folder + ": no " + (want == "right" ? "" : want + " ") +
                     modelKindLabel(*kind) + " model (e.g. " + modelKindName(*kind) + "/" +
                     (*kind == ModelKind::SmplH   ? "SMPLH"
                      : *kind == ModelKind::SmplX ? "SMPLX"
                      : *kind == ModelKind::Mano  ? "MANO"
                                                  : "SMPL") +
                     "_" + (want == "right" ? "RIGHT" : "NEUTRAL") + "." + defaultExt(*kind) +
                     "); " + listing(all, files));
  ModelFileChoice out{c->path, c->kind, c->gender, ""};
  if (!note.empty()) out.note = note + "using " + c->path;
  return out;
}

std::vector<std::string> listModelFolder(const std::string& dir) {
  namespace fs = std::filesystem;
  std::vector<std::string> files;
  std::error_code ec;
  // Links are followed (a cluster's shared models are usually links, to files
  // or to kind folders); the depth limit bounds a link loop. Paths are the
  // links' own, relative to `dir` by name: fs::relative would resolve them.
  fs::recursive_directory_iterator it(os::fsPath(dir),
                                      fs::directory_options::skip_permission_denied |
                                          fs::directory_options::follow_directory_symlink,
                                      ec),
      end;
  for (; !ec && it != end; it.increment(ec)) {
    if (it.depth() >= 2) it.disable_recursion_pending();
    std::error_code fec;
    // A dangling link is listed too: picked, it fails to load with its reason.
    const bool dangling = it->is_symlink(fec) && !it->exists(fec);
    if (it->is_regular_file(fec) || dangling)
      files.push_back(os::genericUtf8(it->path().lexically_relative(os::fsPath(dir))));
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace smpl
