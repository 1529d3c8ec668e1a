// The MJCF writer (mjcf_writer.h): the skeleton as nested bodies, masses and
// capsules from mjcf_parts.h, Z up.
#include "writers/mjcf/mjcf_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

#include "exporter/validate_asset.h"
#include "writers/mjcf/mjcf_npz.h"
#include "writers/mjcf/mjcf_parts.h"
#include "writers/mjcf/mjcf_qpos.h"

namespace smpl {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr size_t kMaxKeyframes = 100;  // <keyframe> holds the first min(T, 100) frames

// The shortest %g text that reads back as `v`; "-0" is written "0".
std::string num(double v) {
  if (v == 0) return "0";
  char text[40];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    if (std::strtod(text, nullptr) == v) break;
  }
  return text;
}

// `v` for a reader (%g: "120", not the shortest round-trip "1.2e+02").
std::string plain(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// Y up -> Z up: +90 degrees about X, (x, y, z) -> (x, -z, y).
Eigen::Vector3d zUp(const Eigen::Vector3d& p) { return {p.x(), -p.z(), p.y()}; }

Eigen::Matrix3d zUpRotation() {
  Eigen::Matrix3d r;
  r << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  return r;
}

std::string vec(const Eigen::Vector3d& v) {
  return num(v.x()) + " " + num(v.y()) + " " + num(v.z());
}

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

struct Tree {
  std::vector<std::vector<int>> children;  // per joint, in index order
  int root = 0;
};

Tree treeOf(const Skeleton& s) {
  Tree t;
  t.children.resize(s.names.size());
  for (size_t k = 0; k < s.names.size(); ++k) {
    if (s.parents[k] < 0)
      t.root = int(k);
    else
      t.children[size_t(s.parents[k])].push_back(int(k));
  }
  return t;
}

struct Context {
  const Asset& asset;
  const WriterOptions& options;
  const MjcfParts& parts;
  Tree tree;
};

std::string inertial(const Context& c, int k, const Eigen::Vector3d& origin) {
  const MjcfPart& p = c.parts.parts[size_t(k)];
  const double mass = p.volume * c.options.density;
  const Eigen::Matrix3d r = zUpRotation();
  const Eigen::Matrix3d i = r * (mass * p.inertia_per_kg) * r.transpose();
  return "<inertial pos=\"" + vec(zUp(p.center - origin)) + "\" mass=\"" + num(mass) +
         "\" fullinertia=\"" + num(i(0, 0)) + " " + num(i(1, 1)) + " " + num(i(2, 2)) + " " +
         num(i(0, 1)) + " " + num(i(0, 2)) + " " + num(i(1, 2)) + "\"/>";
}

bool meshGeom(const Context& c, int k) {
  return c.options.mjcf_geoms == "mesh" && !c.parts.parts[size_t(k)].geom.hull.empty();
}

std::string geom(const Context& c, int k, const Eigen::Vector3d& origin) {
  const MjcfGeom& g = c.parts.parts[size_t(k)].geom;
  const std::string name = escaped(c.asset.skeleton.names[size_t(k)]);
  if (meshGeom(c, k))  // the <asset> mesh of the same name, in this body's frame
    return "<geom name=\"" + name + "\" type=\"mesh\" mesh=\"" + name + "\"/>";
  if (g.kind == MjcfGeom::Kind::Capsule)
    return "<geom name=\"" + name + "\" type=\"capsule\" fromto=\"" + vec(zUp(g.from - origin)) +
           " " + vec(zUp(g.to - origin)) + "\" size=\"" + num(g.radius) + "\"/>";
  if (g.kind == MjcfGeom::Kind::Sphere)
    return "<geom name=\"" + name + "\" type=\"sphere\" pos=\"" + vec(zUp(g.from - origin)) +
           "\" size=\"" + num(g.radius) + "\"/>";
  return "";
}

// <asset>: with --mjcf-geoms mesh, per part with hull points a <mesh> of
// those points in its body's frame (Z up); MuJoCo takes their convex hull.
std::string meshAssets(const Context& c) {
  if (c.options.mjcf_geoms != "mesh") return "";
  std::string out;
  const Skeleton& s = c.asset.skeleton;
  for (size_t k = 0; k < s.names.size(); ++k) {
    if (!meshGeom(c, int(k))) continue;
    const Eigen::Vector3d origin = s.rest_world.row(Eigen::Index(k)).transpose();
    out += "    <mesh name=\"" + escaped(s.names[k]) + "\" vertex=\"";
    const std::vector<Eigen::Vector3d>& points = c.parts.parts[k].geom.hull;
    for (size_t i = 0; i < points.size(); ++i) out += (i ? " " : "") + vec(zUp(points[i] - origin));
    out += "\"/>\n";
  }
  return out.empty() ? "" : "  <asset>\n" + out + "  </asset>\n";
}

std::string joints(const Context& c, int k) {
  const std::string name = escaped(c.asset.skeleton.names[size_t(k)]);
  if (k == c.tree.root) return "<freejoint name=\"" + name + "\"/>";
  if (c.options.mjcf_joints == "ball") return "<joint name=\"" + name + "\" type=\"ball\"/>";
  std::string out;
  const char* axes[3][2] = {{"_x", "1 0 0"}, {"_y", "0 1 0"}, {"_z", "0 0 1"}};
  for (const auto& a : axes)
    out += std::string(out.empty() ? "" : "\n") + "<joint name=\"" + name + a[0] +
           "\" type=\"hinge\" axis=\"" + a[1] + "\" limited=\"true\" range=\"" + num(-kPi) + " " +
           num(kPi) + "\"/>";
  return out;
}

void indentLines(const std::string& text, const std::string& tab, std::string* out) {
  size_t start = 0;
  while (start < text.size()) {
    const size_t end = text.find('\n', start);
    *out += tab + text.substr(start, end - start) + "\n";
    if (end == std::string::npos) break;
    start = end + 1;
  }
}

void writeBody(const Context& c, int k, int depth, std::string* out) {
  const Skeleton& s = c.asset.skeleton;
  const std::string tab(size_t(2 * depth), ' ');
  const Eigen::Vector3d origin = s.rest_world.row(k).transpose();
  *out += tab + "<body name=\"" + escaped(s.names[size_t(k)]) + "\" pos=\"" +
          vec(zUp(s.rest_local.row(k).transpose())) + "\">\n";
  indentLines(joints(c, k), tab + "  ", out);
  indentLines(inertial(c, k, origin), tab + "  ", out);
  indentLines(geom(c, k, origin), tab + "  ", out);
  for (int child : c.tree.children[size_t(k)]) writeBody(c, child, depth + 1, out);
  *out += tab + "</body>\n";
}

std::string actuators(const Context& c) {
  if (!c.options.mjcf_motors || c.options.mjcf_joints != "hinge") return "";
  std::string out = "  <actuator>\n";
  const Skeleton& s = c.asset.skeleton;
  for (size_t k = 0; k < s.names.size(); ++k) {
    if (int(k) == c.tree.root) continue;
    for (const char* axis : {"_x", "_y", "_z"}) {
      const std::string joint = escaped(s.names[k]) + axis;
      out += "    <motor name=\"" + joint + "\" joint=\"" + joint +
             "\" gear=\"1\" ctrllimited=\"true\" ctrlrange=\"-100 100\"/>\n";
    }
  }
  return out + "  </actuator>\n";
}

Status checkInput(const Asset& asset, const WriterOptions& options) {
  if (!(options.density > 0 && options.density <= 1e5))
    return makeError("MJCF writer: density " + num(options.density) +
                     " kg/m^3; expected (0, 100000]");
  if (options.mjcf_joints != "hinge" && options.mjcf_joints != "ball")
    return makeError("MJCF writer: joints '" + options.mjcf_joints + "'; expected hinge or ball");
  if (options.mjcf_motors && options.mjcf_joints != "hinge")
    return makeError("MJCF writer: motors drive hinge joints; ball joints have none");
  if (options.mjcf_geoms != "capsule" && options.mjcf_geoms != "mesh")
    return makeError("MJCF writer: geoms '" + options.mjcf_geoms + "'; expected capsule or mesh");
  if (asset.animations.size() > 1)
    return makeError("MJCF writer: the asset has " + std::to_string(asset.animations.size()) +
                     " animations; an MJCF file holds one");
  if (Status st = validateAsset(asset); !st) return st;  // the same rules for every writer
  if (asset.skeleton.names.empty()) return makeError("MJCF writer: the skeleton has no joints");
  std::set<std::string> seen;
  for (size_t k = 0; k < asset.skeleton.names.size(); ++k)
    if (asset.skeleton.names[k].empty() || !seen.insert(asset.skeleton.names[k]).second)
      return makeError("MJCF writer: joint " + std::to_string(k) + " name '" +
                       asset.skeleton.names[k] + "' is empty or not unique");
  return Status();
}

double lowestY(const SkinnedMesh& m) { return double(m.positions.col(1).minCoeff()); }

// <keyframe>: the first min(T, kMaxKeyframes) rows as <key name="frame_<i>">.
std::string keyframes(const MjcfMotion& m) {
  const size_t frames = std::min(m.times.size(), kMaxKeyframes);
  if (frames == 0) return "";
  std::string out = "  <keyframe>\n";
  for (size_t f = 0; f < frames; ++f) {
    out += "    <key name=\"frame_" + std::to_string(f) + "\" time=\"" + num(m.times[f]) +
           "\" qpos=\"";
    for (int i = 0; i < m.nq; ++i)
      out += (i ? " " : "") + num(m.qpos[f * size_t(m.nq) + size_t(i)]);
    out += "\"/>\n";
  }
  return out + "  </keyframe>\n";
}

// The <stem>.qpos.npz bytes: qpos (T, nq), fps (), joint_names (J,).
Result<std::string> qposNpz(const MjcfMotion& m) {
  Result<NpyMember> names = npyStrings("joint_names", m.joint_names);
  if (!names) return names.error();
  return npzBytes({npyDoubles("qpos", {m.times.size(), size_t(m.nq)}, m.qpos),
                   npyDoubles("fps", {}, {m.fps}), std::move(*names)});
}

struct MjcfWriter : Writer {
  const char* name() const override { return "mjcf"; }

  Result<std::string> serialize(const Asset& asset, const WriterOptions& options) const override {
    Result<Files> files = serializeFiles(asset, options);
    if (!files) return files.error();
    return std::move(files->bytes);
  }

  // The XML, and with a clip the qpos .npz as the buffer (mjcf_writer.h).
  Result<Files> serializeFiles(const Asset& asset, const WriterOptions& options) const override {
    if (Status st = checkInput(asset, options); !st) return st.error();
    Result<MjcfParts> parts = mjcfParts(asset);
    if (!parts) return parts.error();
    const Context c{asset, options, *parts, treeOf(asset.skeleton)};
    MjcfMotion motion;
    std::string npz;
    if (!asset.animations.empty()) {
      Result<MjcfMotion> m = mjcfMotion(asset, asset.animations.front(), options.mjcf_joints);
      if (!m) return m.error();
      motion = std::move(*m);
      Result<std::string> bytes = qposNpz(motion);
      if (!bytes) return bytes.error();
      npz = std::move(*bytes);
    }
    std::string out = "<mujoco model=\"" + escaped(asset.name) + "\">\n";
    out += "  <!-- smpl-export: " + escaped(asset.metadata.model_kind) + " " +
           escaped(asset.metadata.model_name) +
           "; Z up (the model's Y up turned +90 degrees about X), metres, kilograms; density " +
           num(options.density) + " kg/m^3, mesh volume " + num(parts->mesh_volume) + " m^3 -->\n";
    if (!asset.animations.empty())
      out += "  <!-- reference motion: " + std::to_string(motion.times.size()) + " frames at " +
             plain(motion.fps) + " fps, nq " + std::to_string(motion.nq) +
             "; qpos of every frame in " +
             escaped(options.buffer_uri.empty() ? "the .qpos.npz beside this file"
                                                : options.buffer_uri) +
             ", the first " + std::to_string(std::min(motion.times.size(), kMaxKeyframes)) +
             " as keyframes -->\n";
    out += "  <compiler angle=\"radian\" inertiafromgeom=\"false\"/>\n";
    out += "  <option gravity=\"0 0 -9.81\" timestep=\"0.002\"/>\n";
    out += "  <default>\n    <joint damping=\"0.5\" armature=\"0.01\"/>\n";
    out += "    <geom contype=\"1\" conaffinity=\"0\" condim=\"3\" friction=\"1 0.005 0.0001\"/>\n";
    out += "  </default>\n" + meshAssets(c) + "  <worldbody>\n";
    out += "    <geom name=\"floor\" type=\"plane\" pos=\"0 0 " + num(lowestY(asset.mesh)) +
           "\" size=\"10 10 0.1\" contype=\"1\" conaffinity=\"1\"/>\n";
    writeBody(c, c.tree.root, 2, &out);
    out += "  </worldbody>\n" + actuators(c) + keyframes(motion) + "</mujoco>\n";
    return Files{std::move(out), std::move(npz)};
  }
};

}  // namespace

const Writer& mjcfWriter() {
  static const MjcfWriter writer;
  return writer;
}

}  // namespace smpl
