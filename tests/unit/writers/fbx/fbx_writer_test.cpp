// FBX writer: the written bytes are parsed back by a small reader written
// here from the format description (the same checks Blender's parser makes:
// end offsets, nested-block null records), and the content compared with
// the input asset. Also writes the inputs of the Blender import check
// (tests/roundtrip/blender_fbx_import_check.py) into the fixture directory.
#include "writers/fbx/fbx_writer.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <zlib.h>

#include <Eigen/Geometry>
#include <cstring>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>

#include "tests/unit/writers/fbx/fbx_test_asset.h"
#include "writers/fbx/fbx_scene_internal.h"

namespace smpl {
namespace {

struct Prop {
  char type = 0;
  int64_t i = 0;
  double d = 0;
  std::string s;
  std::vector<double> numbers;  // any numeric array, widened
};

struct Node {
  std::string name;
  std::vector<Prop> props;
  std::vector<Node> children;
  const Node* child(const std::string& n) const {
    for (const Node& c : children)
      if (c.name == n) return &c;
    return nullptr;
  }
  std::vector<const Node*> all(const std::string& n) const {
    std::vector<const Node*> out;
    for (const Node& c : children)
      if (c.name == n) out.push_back(&c);
    return out;
  }
};

// Minimal binary FBX reader; throws on any inconsistency.
class Reader {
 public:
  Reader(const std::string& bytes) : b_(bytes) {}

  std::vector<Node> parse() {
    if (b_.compare(0, 23, std::string("Kaydara FBX Binary  \0\x1a\0", 23)) != 0)
      throw std::runtime_error("magic");
    uint32_t version = get<uint32_t>();
    wide_ = version >= 7500;
    std::vector<Node> top;
    Node n;
    while (record(n)) top.push_back(std::move(n));
    return top;
  }

 private:
  template <class T>
  T get() {
    if (pos_ + sizeof(T) > b_.size()) throw std::runtime_error("truncated");
    T v;
    std::memcpy(&v, b_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  uint64_t field() { return wide_ ? get<uint64_t>() : get<uint32_t>(); }
  size_t nullSize() const { return wide_ ? 25 : 13; }

  template <class T>
  std::vector<double> array() {
    uint32_t count = get<uint32_t>(), encoding = get<uint32_t>(), length = get<uint32_t>();
    if (pos_ + length > b_.size()) throw std::runtime_error("array truncated");
    std::vector<T> raw(count);
    if (encoding == 0) {
      if (length != count * sizeof(T)) throw std::runtime_error("array length");
      std::memcpy(raw.data(), b_.data() + pos_, length);
    } else {
      uLongf size = count * sizeof(T);
      if (uncompress(reinterpret_cast<Bytef*>(raw.data()), &size,
                     reinterpret_cast<const Bytef*>(b_.data() + pos_), length) != Z_OK ||
          size != count * sizeof(T))
        throw std::runtime_error("array inflate");
    }
    pos_ += length;
    return std::vector<double>(raw.begin(), raw.end());
  }

  Prop prop() {
    Prop p;
    p.type = get<char>();
    switch (p.type) {
      case 'C':
        p.i = get<uint8_t>();
        break;
      case 'Y':
        p.i = get<int16_t>();
        break;
      case 'I':
        p.i = get<int32_t>();
        break;
      case 'L':
        p.i = get<int64_t>();
        break;
      case 'F':
        p.d = get<float>();
        break;
      case 'D':
        p.d = get<double>();
        break;
      case 'S':
      case 'R': {
        uint32_t n = get<uint32_t>();
        if (pos_ + n > b_.size()) throw std::runtime_error("string truncated");
        p.s = b_.substr(pos_, n);
        pos_ += n;
        break;
      }
      case 'f':
        p.numbers = array<float>();
        break;
      case 'd':
        p.numbers = array<double>();
        break;
      case 'i':
        p.numbers = array<int32_t>();
        break;
      case 'l':
        p.numbers = array<int64_t>();
        break;
      default:
        throw std::runtime_error(std::string("property type ") + p.type);
    }
    return p;
  }

  bool record(Node& n) {
    uint64_t end = field(), count = field(), prop_len = field();
    uint8_t name_len = get<uint8_t>();
    if (end == 0) {
      if (count || prop_len || name_len) throw std::runtime_error("bad null record");
      return false;
    }
    n = Node{};
    n.name = b_.substr(pos_, name_len);
    pos_ += name_len;
    size_t props_start = pos_;
    for (uint64_t i = 0; i < count; ++i) n.props.push_back(prop());
    if (pos_ - props_start != prop_len) throw std::runtime_error(n.name + ": property length");
    if (pos_ < end) {
      Node c;
      while (pos_ + nullSize() < end) {
        if (!record(c)) throw std::runtime_error(n.name + ": early null record");
        n.children.push_back(std::move(c));
      }
      if (b_.compare(pos_, nullSize(), std::string(nullSize(), '\0')) != 0)
        throw std::runtime_error(n.name + ": nested block sentinel");
      pos_ += nullSize();
    }
    if (pos_ != end) throw std::runtime_error(n.name + ": end offset");
    return true;
  }

  const std::string& b_;
  size_t pos_ = 23;
  bool wide_ = false;
};

struct Parsed {
  std::vector<Node> top;
  const Node& get(const std::string& name) const {
    for (const Node& n : top)
      if (n.name == name) return n;
    throw std::runtime_error("missing " + name);
  }
  std::vector<const Node*> objects(const std::string& type, const std::string& subclass) const {
    std::vector<const Node*> out;
    for (const Node* o : get("Objects").all(type))
      if (o->props.size() == 3 && o->props[2].s == subclass) out.push_back(o);
    return out;
  }
};

Parsed writeAndParse(const Asset& asset, const WriterOptions& options) {
  Result<std::string> bytes = fbxWriter().serialize(asset, options);
  if (!bytes.ok()) throw std::runtime_error(bytes.message());
  return Parsed{Reader(*bytes).parse()};
}

std::string objectName(const Node& n) { return n.props[1].s.substr(0, n.props[1].s.find('\0')); }

const Prop* p70(const Node& owner, const std::string& name) {
  const Node* p = owner.child("Properties70");
  if (!p) return nullptr;
  for (const Node& c : p->children)
    if (c.props[0].s == name) return &c.props[4];
  return nullptr;
}

TEST(FbxWriter, IsDeterministic) {
  Asset a = fbx_test::testAsset();
  Result<std::string> first = fbxWriter().serialize(a, {});
  Result<std::string> second = fbxWriter().serialize(fbx_test::testAsset(), {});
  ASSERT_TRUE(first.ok()) << first.message();
  ASSERT_TRUE(second.ok());
  EXPECT_EQ(*first, *second);
  EXPECT_STREQ(fbxWriter().name(), "fbx");
}

TEST(FbxWriter, SectionsAndGlobalSettings) {
  Parsed f = writeAndParse(fbx_test::testAsset(), {});
  std::vector<std::string> names;
  for (const Node& n : f.top) names.push_back(n.name);
  EXPECT_EQ(names, (std::vector<std::string>{"FBXHeaderExtension", "FileId", "CreationTime",
                                             "Creator", "GlobalSettings", "Documents", "References",
                                             "Definitions", "Objects", "Connections", "Takes"}));
  const Node& g = f.get("GlobalSettings");
  EXPECT_EQ(p70(g, "UpAxis")->i, 1);
  EXPECT_EQ(p70(g, "FrontAxis")->i, 2);
  EXPECT_EQ(p70(g, "CoordAxis")->i, 0);
  EXPECT_EQ(p70(g, "UnitScaleFactor")->d, 100.0);
  EXPECT_EQ(p70(g, "TimeMode")->i, 6);  // 30 fps
  EXPECT_EQ(f.get("CreationTime").props[0].s, "1970-01-01 10:00:00:000");
  // Definitions count every object.
  int objects = int(f.get("Objects").children.size()) + 1;
  EXPECT_EQ(f.get("Definitions").child("Count")->props[0].i, objects);
}

TEST(FbxWriter, MeshGeometryRoundTrips) {
  Asset a = fbx_test::testAsset();
  Parsed f = writeAndParse(a, {});
  auto meshes = f.objects("Geometry", "Mesh");
  ASSERT_EQ(meshes.size(), 1u);
  const Node& g = *meshes[0];
  const auto& v = g.child("Vertices")->props[0].numbers;
  ASSERT_EQ(v.size(), size_t(a.mesh.positions.size()));
  for (Eigen::Index i = 0; i < a.mesh.positions.rows(); ++i)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(v[3 * i + c], double(a.mesh.positions(i, c)));
  const auto& pvi = g.child("PolygonVertexIndex")->props[0].numbers;
  ASSERT_EQ(pvi.size(), size_t(a.mesh.triangles.size()));
  for (Eigen::Index t = 0; t < a.mesh.triangles.rows(); ++t) {
    EXPECT_EQ(pvi[3 * t], a.mesh.triangles(t, 0));
    EXPECT_EQ(pvi[3 * t + 1], a.mesh.triangles(t, 1));
    EXPECT_EQ(-pvi[3 * t + 2] - 1, a.mesh.triangles(t, 2));  // polygon end marker
  }
  const Node* uv = g.child("LayerElementUV");
  ASSERT_NE(uv, nullptr);
  const auto& uv_index = uv->child("UVIndex")->props[0].numbers;
  const auto& uvs = uv->child("UV")->props[0].numbers;
  int corner = 7, vertex = a.mesh.triangles(corner / 3, corner % 3);
  EXPECT_EQ(uvs[2 * size_t(uv_index[corner]) + 1], double(a.mesh.uvs(vertex, 1)));  // v kept as is
  const auto& normals = g.child("LayerElementNormal")->child("Normals")->props[0].numbers;
  EXPECT_EQ(normals.size(), size_t(a.mesh.triangles.size() * 3));
  EXPECT_EQ(normals[3 * corner], double(a.mesh.normals(vertex, 0)));
}

TEST(FbxWriter, CentimetresScaleGeometryAndSkeleton) {
  Asset a = fbx_test::testAsset();
  WriterOptions o;
  o.fbx_units = "cm";
  Parsed f = writeAndParse(a, o);
  EXPECT_EQ(p70(f.get("GlobalSettings"), "UnitScaleFactor")->d, 1.0);
  const auto& v = f.objects("Geometry", "Mesh")[0]->child("Vertices")->props[0].numbers;
  EXPECT_NEAR(v[3 * 9 + 1], 100.0 * a.mesh.positions(9, 1), 1e-4);
  const Node* spine = f.objects("Model", "LimbNode")[1];
  const Node* t = nullptr;
  for (const Node& p : spine->child("Properties70")->children)
    if (p.props[0].s == "Lcl Translation") t = &p;
  ASSERT_NE(t, nullptr);
  EXPECT_NEAR(t->props[5].d, 100.0 * a.skeleton.rest_local(1, 1), 1e-9);
}

// Maps id -> object node, and checks every connection names known objects.
std::map<int64_t, const Node*> objectsById(const Parsed& f) {
  std::map<int64_t, const Node*> ids;
  for (const Node& o : f.get("Objects").children) {
    EXPECT_EQ(ids.count(o.props[0].i), 0u) << "duplicate id";
    ids[o.props[0].i] = &o;
  }
  return ids;
}

TEST(FbxWriter, ConnectionsReferenceObjects) {
  Parsed f = writeAndParse(fbx_test::testAsset(), {});
  auto ids = objectsById(f);
  std::set<int64_t> children;
  for (const Node& c : f.get("Connections").children) {
    EXPECT_TRUE(ids.count(c.props[1].i)) << c.props[1].i;
    EXPECT_TRUE(c.props[2].i == 0 || ids.count(c.props[2].i));
    children.insert(c.props[1].i);
  }
  for (const auto& entry : ids) {
    // Poses and animation stacks are roots of their own, never connected.
    if (entry.second->name == "Pose" || entry.second->name == "AnimationStack") continue;
    EXPECT_TRUE(children.count(entry.first)) << objectName(*entry.second);
  }
}

TEST(FbxWriter, SkinClustersCarryTheWeights) {
  Asset a = fbx_test::testAsset();
  Parsed f = writeAndParse(a, {});
  auto clusters = f.objects("Deformer", "Cluster");
  ASSERT_EQ(clusters.size(), a.skeleton.names.size());
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(a.mesh.positions.rows(), a.skeleton.names.size());
  for (Eigen::Index v = 0; v < a.mesh.joints.rows(); ++v)
    for (Eigen::Index s = 0; s < a.mesh.joints.cols(); ++s)
      dense(v, a.mesh.joints(v, s)) += a.mesh.weights(v, s);
  for (size_t k = 0; k < clusters.size(); ++k) {
    const Node& c = *clusters[k];
    EXPECT_EQ(objectName(c), a.skeleton.names[k]);
    Eigen::VectorXd column = Eigen::VectorXd::Zero(dense.rows());
    if (const Node* idx = c.child("Indexes")) {
      const auto& w = c.child("Weights")->props[0].numbers;
      for (size_t i = 0; i < idx->props[0].numbers.size(); ++i)
        column(int(idx->props[0].numbers[i])) = w[i];
    }
    EXPECT_LT((column - dense.col(k)).cwiseAbs().maxCoeff(), 1e-7) << a.skeleton.names[k];
    const auto& link = c.child("TransformLink")->props[0].numbers;
    const auto& tx = c.child("Transform")->props[0].numbers;
    for (int i = 0; i < 3; ++i) {
      EXPECT_DOUBLE_EQ(link[12 + i], a.skeleton.rest_world(k, i));
      EXPECT_DOUBLE_EQ(tx[12 + i], -a.skeleton.rest_world(k, i));
    }
  }
  EXPECT_EQ(f.objects("Pose", "BindPose")[0]->all("PoseNode").size(), a.skeleton.names.size() + 1);
}

TEST(FbxWriter, ShapesAreSparseAndNeverEmpty) {
  Asset a = fbx_test::testAsset();
  Parsed f = writeAndParse(a, {});
  auto shapes = f.objects("Geometry", "Shape");
  auto channels = f.objects("Deformer", "BlendShapeChannel");
  ASSERT_EQ(shapes.size(), 3u);
  ASSERT_EQ(channels.size(), 3u);
  for (size_t t = 0; t < 3; ++t) {
    const MorphTarget& target = a.mesh.morph_targets[t];
    EXPECT_EQ(objectName(*shapes[t]), target.name);
    EXPECT_EQ(objectName(*channels[t]), target.name);
    const auto& idx = shapes[t]->child("Indexes")->props[0].numbers;
    const auto& d = shapes[t]->child("Vertices")->props[0].numbers;
    ASSERT_EQ(d.size(), idx.size() * 3);
    ASSERT_FALSE(idx.empty());
    Eigen::MatrixXf rebuilt = Eigen::MatrixXf::Zero(target.deltas.rows(), 3);
    for (size_t i = 0; i < idx.size(); ++i)
      for (int c = 0; c < 3; ++c) rebuilt(int(idx[i]), c) = float(d[3 * i + c]);
    EXPECT_EQ(rebuilt, target.deltas) << target.name;
  }
  int moving = 0;
  for (Eigen::Index v = 0; v < a.mesh.positions.rows(); ++v)
    moving += a.mesh.positions(v, 1) > 1.3f;
  EXPECT_EQ(shapes[1]->child("Indexes")->props[0].numbers.size(), size_t(moving));
  EXPECT_EQ(shapes[2]->child("Indexes")->props[0].numbers.size(), 1u);  // all-zero target
}

// The channel's own DeformPercent is the rest weight as a percentage (FBX
// SDK: FbxBlendShapeChannel::DeformPercent, 0..100): a unit-encoded target
// rests at 50 (weight 0.5), not at 0.5 %. Importers read it before any curve.
TEST(FbxWriter, RestDeformPercentIsAPercentage) {
  Asset a = fbx_test::testAsset();
  a.mesh.morph_targets[0].rest_weight = 0.5f;
  a.mesh.morph_targets[1].rest_weight = 1.0f;
  Parsed f = writeAndParse(a, {});
  auto channels = f.objects("Deformer", "BlendShapeChannel");
  ASSERT_EQ(channels.size(), 3u);
  const double expected[3] = {50.0, 100.0, 0.0};
  for (size_t t = 0; t < 3; ++t) {
    ASSERT_NE(channels[t]->child("DeformPercent"), nullptr) << t;
    EXPECT_DOUBLE_EQ(channels[t]->child("DeformPercent")->props[0].d, expected[t]) << t;
  }
}

// Curves of one curve node, by channel ("d|X"...), via the connections.
std::map<std::string, const Node*> curvesOf(const Parsed& f, int64_t curve_node) {
  auto ids = objectsById(f);
  std::map<std::string, const Node*> out;
  for (const Node& c : f.get("Connections").children)
    if (c.props[0].s == "OP" && c.props[2].i == curve_node)
      out[c.props[3].s] = ids.at(c.props[1].i);
  return out;
}

TEST(FbxWriter, RotationCurvesReproduceTheClip) {
  Asset a = fbx_test::testAsset();
  const AnimationClip& clip = a.animations[0];
  Parsed f = writeAndParse(a, {});
  auto ids = objectsById(f);
  int rotation_nodes = 0;
  for (const Node& c : f.get("Connections").children) {
    if (c.props[0].s != "OP" || c.props[3].s != "Lcl Rotation") continue;
    const Node& model = *ids.at(c.props[2].i);
    size_t k = std::find(a.skeleton.names.begin(), a.skeleton.names.end(), objectName(model)) -
               a.skeleton.names.begin();
    ASSERT_LT(k, a.skeleton.names.size());
    auto curves = curvesOf(f, c.props[1].i);
    ASSERT_EQ(curves.size(), 3u);
    const auto& x = curves["d|X"]->child("KeyValueFloat")->props[0].numbers;
    const auto& y = curves["d|Y"]->child("KeyValueFloat")->props[0].numbers;
    const auto& z = curves["d|Z"]->child("KeyValueFloat")->props[0].numbers;
    const auto& times = curves["d|X"]->child("KeyTime")->props[0].numbers;
    ASSERT_EQ(x.size(), clip.times.size());
    for (size_t i = 0; i < x.size(); ++i) {
      EXPECT_NEAR(times[i], clip.times[i] * 46186158000.0, 1.0);
      const double r = 3.14159265358979323846 / 180;
      Eigen::Matrix3d m = (Eigen::AngleAxisd(z[i] * r, Eigen::Vector3d::UnitZ()) *
                           Eigen::AngleAxisd(y[i] * r, Eigen::Vector3d::UnitY()) *
                           Eigen::AngleAxisd(x[i] * r, Eigen::Vector3d::UnitX()))
                              .toRotationMatrix();
      EXPECT_LT((m - clip.rotations[k][i].cast<double>().toRotationMatrix()).cwiseAbs().maxCoeff(),
                1e-5)
          << k << " " << i;
      if (i > 0) {  // 270 degrees in 9 steps of 30: continuous curves step < 60 degrees
        EXPECT_LT(std::abs(x[i] - x[i - 1]) + std::abs(y[i] - y[i - 1]) + std::abs(z[i] - z[i - 1]),
                  60.0)
            << k << " " << i;
      }
    }
    ++rotation_nodes;
  }
  EXPECT_EQ(rotation_nodes, int(a.skeleton.names.size()));
}

Eigen::Matrix3d fromEulerDegrees(const Eigen::Vector3d& e) {
  const double r = 3.14159265358979323846 / 180;
  return (Eigen::AngleAxisd(e.z() * r, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(e.y() * r, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(e.x() * r, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

TEST(FbxWriter, EulerConversionSurvivesGimbalLockAndFlips) {
  std::vector<Eigen::Quaterniond> q;
  for (int i = 0; i <= 40; ++i) {  // pitch sweeps through +90 degrees and back while yawing
    double t = i / 40.0;
    q.emplace_back(Eigen::AngleAxisd(2.0 * t, Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(3.14159265358979323846 * t, Eigen::Vector3d::UnitY()) *
                   Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()));
  }
  q.emplace_back(
      Eigen::AngleAxisd(3.14159265358979323846 / 2, Eigen::Vector3d::UnitY()));  // exact lock
  RotationTrack keys;  // as the bake stores them: float
  for (const Eigen::Quaterniond& r : q) keys.push_back(r.cast<float>());
  std::vector<Eigen::Vector3d> e = fbx::continuousEulerXYZDegrees(keys);
  ASSERT_EQ(e.size(), q.size());
  for (size_t i = 0; i < q.size(); ++i) {
    const Eigen::Matrix3d want = keys[i].cast<double>().normalized().toRotationMatrix();
    // 1e-9 away from the lock; at it (the last key) asin keeps half the digits
    EXPECT_LT((fromEulerDegrees(e[i]) - want).cwiseAbs().maxCoeff(), i == 41 ? 5e-8 : 1e-9) << i;
    if (i > 0 && i < 41) {  // input steps are 4.5 degrees; no 360 jumps or flips
      EXPECT_LT((e[i] - e[i - 1]).cwiseAbs().maxCoeff(), 30.0) << i;
    }
  }
}

TEST(FbxWriter, MorphWeightCurvesArePercent) {
  Asset a = fbx_test::testAsset();
  Parsed f = writeAndParse(a, {});
  auto ids = objectsById(f);
  int found = 0;
  for (const Node& c : f.get("Connections").children) {
    if (c.props[0].s != "OP" || c.props[3].s != "DeformPercent") continue;
    const Node& channel = *ids.at(c.props[2].i);
    size_t t = 0;
    while (t < a.mesh.morph_targets.size() && a.mesh.morph_targets[t].name != objectName(channel))
      ++t;
    ASSERT_LT(t, a.mesh.morph_targets.size());
    auto curves = curvesOf(f, c.props[1].i);
    const auto& v = curves.at("d|DeformPercent")->child("KeyValueFloat")->props[0].numbers;
    for (size_t i = 0; i < v.size(); ++i)
      EXPECT_NEAR(v[i], 100.0 * a.animations[0].morph_weights(int(i), int(t)), 1e-4);
    ++found;
  }
  EXPECT_EQ(found, 3);
}

TEST(FbxWriter, Version7500ParsesWithWideHeaders) {
  WriterOptions o;
  o.fbx_version = 7500;
  Parsed f = writeAndParse(fbx_test::testAsset(), o);
  EXPECT_EQ(f.objects("Geometry", "Shape").size(), 3u);
  EXPECT_EQ(f.get("FBXHeaderExtension").child("FBXVersion")->props[0].i, 7500);
}

TEST(FbxWriter, RejectsInconsistentAssets) {
  WriterOptions o;
  Asset a = fbx_test::testAsset();
  o.fbx_units = "mm";
  EXPECT_NE(fbxWriter().serialize(a, o).message().find("units"), std::string::npos);
  o = WriterOptions{};
  o.fbx_version = 7300;
  EXPECT_FALSE(fbxWriter().serialize(a, o).ok());
  Asset bad = a;
  bad.mesh.triangles(3, 1) = 5000;
  EXPECT_NE(fbxWriter().serialize(bad, {}).message().find("triangle"), std::string::npos);
  bad = a;
  bad.mesh.morph_targets[1].deltas.resize(3, 3);
  EXPECT_NE(fbxWriter().serialize(bad, {}).message().find("pose_head_12"), std::string::npos);
  bad = a;
  bad.skeleton.parents[2] = 3;
  EXPECT_FALSE(fbxWriter().serialize(bad, {}).ok());
  bad = a;
  bad.animations[0].rotations[1].pop_back();
  EXPECT_FALSE(fbxWriter().serialize(bad, {}).ok());
  bad = a;
  bad.animations[0].rotations[3][2] = Eigen::Quaternionf(0, 0, 0, 0);
  EXPECT_NE(fbxWriter().serialize(bad, {}).message().find("zero or non-finite rotation"),
            std::string::npos);
  bad = a;
  bad.mesh.joints(0, 0) = 9;
  EXPECT_FALSE(fbxWriter().serialize(bad, {}).ok());
}

// Expectations for blender_fbx_import_check.py, in model axes and metres.
nlohmann::json blenderExpectations(const Asset& a) {
  nlohmann::json j;
  j["joint_names"] = a.skeleton.names;
  j["parents"] = a.skeleton.parents;
  j["vertex_count"] = a.mesh.positions.rows();
  Eigen::Vector3f lo = a.mesh.positions.colwise().minCoeff(),
                  hi = a.mesh.positions.colwise().maxCoeff();
  j["bbox_min"] = {lo.x(), lo.y(), lo.z()};
  j["bbox_max"] = {hi.x(), hi.y(), hi.z()};
  for (const MorphTarget& t : a.mesh.morph_targets) {
    nlohmann::json target = {{"name", t.name}, {"deltas", nlohmann::json::array()}};
    for (Eigen::Index v = 0; v < t.deltas.rows(); ++v)
      target["deltas"].push_back({t.deltas(v, 0), t.deltas(v, 1), t.deltas(v, 2)});
    j["morph_targets"].push_back(target);
  }
  for (Eigen::Index v = 0; v < a.mesh.joints.rows(); ++v) {
    nlohmann::json row = nlohmann::json::object();
    for (Eigen::Index s = 0; s < a.mesh.joints.cols(); ++s) {
      const std::string& name = a.skeleton.names[a.mesh.joints(v, s)];
      row[name] = row.value(name, 0.0) + a.mesh.weights(v, s);
    }
    j["weights"].push_back(row);
  }
  const AnimationClip& c = a.animations[0];
  j["animation"]["fps"] = c.fps;
  for (int f = 0; f < int(c.times.size()); ++f) {
    nlohmann::json frame = {{"index", f}};
    for (const Eigen::Vector3d& p : fbx_test::worldJoints(a, c, f))
      frame["joint_world"].push_back({p.x(), p.y(), p.z()});
    for (size_t t = 0; t < a.mesh.morph_targets.size(); ++t)
      frame["morph_weights"][a.mesh.morph_targets[t].name] = c.morph_weights(f, int(t));
    j["animation"]["frames"].push_back(frame);
  }
  return j;
}

// <fixtures>/fbx/synthetic.fbx (metres), synthetic_cm.fbx (centimetres) and
// synthetic.expect.json: both files must import to the same metres scene.
TEST(FbxWriter, WritesBlenderRoundTripInputs) {
  Asset a = fbx_test::testAsset();
  const std::string dir = std::string(SMPL_FIXTURE_DIR) + "/fbx";
  mkdir(SMPL_FIXTURE_DIR, 0755);
  mkdir(dir.c_str(), 0755);
  for (const char* units : {"m", "cm"}) {
    WriterOptions o;
    o.fbx_units = units;
    Result<std::string> bytes = fbxWriter().serialize(a, o);
    ASSERT_TRUE(bytes.ok());
    const std::string path = dir + (o.fbx_units == "m" ? "/synthetic.fbx" : "/synthetic_cm.fbx");
    std::ofstream(path, std::ios::binary) << *bytes;
    std::ifstream check(path, std::ios::binary | std::ios::ate);
    EXPECT_EQ(size_t(check.tellg()), bytes->size());
  }
  WriterOptions stored;  // --fbx-compress-level 0: arrays uncompressed, same expectations as "m"
  stored.fbx_compress_level = 0;
  Result<std::string> raw = fbxWriter().serialize(a, stored);
  ASSERT_TRUE(raw.ok());
  std::ofstream(dir + "/synthetic_stored.fbx", std::ios::binary) << *raw;
  std::ofstream(dir + "/synthetic.expect.json") << blenderExpectations(a).dump(1);
}

}  // namespace
}  // namespace smpl
