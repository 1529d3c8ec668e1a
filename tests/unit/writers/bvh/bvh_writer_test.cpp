// The BVH writer (writers/bvh/bvh_writer.h): the exact text of a small file,
// the structure of a bigger one (nesting, channel counts, frame count and
// time, values per line), centimetres, the rest-pose file without a clip,
// position channels for a joint with a translation track, refusals, and the
// text read back here with forward kinematics written from the BVH
// definition (R = Rz Rx Ry, the position channels replacing the offset)
// giving the asset's joint world positions.
#include "writers/bvh/bvh_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "tests/unit/test_asset.h"
#include "writers/writer.h"

namespace smpl {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A skeleton-only asset: pelvis(0) <- left_hip(1) <- left_knee(3), pelvis <- spine1(2) <-
// spine2(4) (the file nests left_knee under left_hip before spine1, so its frame lines are
// not in joint order), `frames` random frames at `fps`.
Asset smallAsset(int frames, double fps = 120.0) {
  Eigen::MatrixXd world(5, 3);
  world << 0.0, 0.9, 0.0, 0.1, 0.8, 0.0, 0.0, 1.0, -0.02, 0.12, 0.45, 0.01, 0.01, 1.2, 0.0;
  Asset a;
  a.name = "body";
  a.skeleton = test::skeletonFromWorld({"pelvis", "left_hip", "spine1", "left_knee", "spine2"},
                                       {-1, 0, 0, 1, 2}, world);
  a.skeleton_only = true;
  a.metadata.model_kind = "smpl";
  if (frames == 0) return a;
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0.0, 1.0);
  AnimationClip clip;
  clip.name = "walk";
  clip.fps = fps;
  clip.rotations.resize(5);
  for (int t = 0; t < frames; ++t) {
    clip.times.push_back(t / fps);
    for (auto& track : clip.rotations)
      track.push_back(
          Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().cast<float>());
    clip.root_translation.emplace_back(0.1 * t, 0.9 + 0.01 * t, -0.05 * t);
  }
  a.animations.push_back(clip);
  return a;
}

std::string write(const Asset& a, const std::string& units = "m") {
  WriterOptions o;
  o.bvh_units = units;
  Result<std::string> text = bvhWriter().serialize(a, o);
  EXPECT_TRUE(text.ok()) << text.message();
  return text.ok() ? *text : "";
}

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(BvhWriter, ExactTextOfARestFile) {
  // Two joints, no clip: the rest pose, one frame at 30 fps.
  Eigen::MatrixXd world(2, 3);
  world << 0.0, 0.9, 0.0, 0.0, 1.15, -0.125;
  Asset a;
  a.skeleton = test::skeletonFromWorld({"pelvis", "spine1"}, {-1, 0}, world);
  a.skeleton_only = true;
  EXPECT_EQ(write(a),
            "HIERARCHY\n"
            "ROOT pelvis\n"
            "{\n"
            "\tOFFSET 0.00000000 0.90000000 0.00000000\n"
            "\tCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
            "\tJOINT spine1\n"
            "\t{\n"
            "\t\tOFFSET 0.00000000 0.25000000 -0.12500000\n"
            "\t\tCHANNELS 3 Zrotation Xrotation Yrotation\n"
            "\t\tEnd Site\n"
            "\t\t{\n"
            "\t\t\tOFFSET 0.00000000 0.12500000 -0.06250000\n"
            "\t\t}\n"
            "\t}\n"
            "}\n"
            "MOTION\n"
            "Frames: 1\n"
            "Frame Time: 0.0333333333\n"
            "0.00000000 0.90000000 0.00000000 0.000000 0.000000 0.000000 0.000000 0.000000 "
            "0.000000\n");
  EXPECT_EQ(
      write(a, "cm").rfind("HIERARCHY\nROOT pelvis\n{\n\tOFFSET 0.000000 90.000000 0.000000\n", 0),
      0u);
}

TEST(BvhWriter, StructureFollowsTheSkeletonAndClip) {
  const Asset a = smallAsset(5);
  const std::string text = write(a);
  const std::vector<std::string> lines = linesOf(text);
  // Depth first, children in index order: left_knee before spine1.
  std::vector<std::string> joints;
  int depth = 0, deepest = 0, channels = 0, sites = 0;
  size_t motion = 0;
  for (size_t i = 0; i < lines.size() && !motion; ++i) {
    std::istringstream words(lines[i]);
    std::string word;
    words >> word;
    if (word == "ROOT" || word == "JOINT")
      joints.push_back(lines[i].substr(lines[i].find(' ') + 1));
    if (word == "{") deepest = std::max(deepest, ++depth);
    if (word == "}") --depth;
    if (word == "End") ++sites;
    if (word == "CHANNELS") {
      int count = 0;
      words >> count;
      channels += count;
      int listed = 0;
      for (std::string c; words >> c;) ++listed;
      EXPECT_EQ(listed, count) << lines[i];
      EXPECT_EQ(count, joints.size() == 1 ? 6 : 3) << lines[i];
    }
    if (word == "MOTION") motion = i;
  }
  EXPECT_EQ(joints,
            (std::vector<std::string>{"pelvis", "left_hip", "left_knee", "spine1", "spine2"}));
  EXPECT_EQ(depth, 0);
  EXPECT_EQ(deepest, 4);  // pelvis { left_hip { left_knee { End Site { } } } }
  EXPECT_EQ(sites, 2);    // the leaves left_knee and spine2
  EXPECT_EQ(channels, 6 + 4 * 3);
  ASSERT_GT(motion, 0u);
  EXPECT_EQ(lines[motion + 1], "Frames: 5");
  EXPECT_EQ(lines[motion + 2], "Frame Time: 0.0083333333");  // 120 fps
  ASSERT_EQ(lines.size(), motion + 3 + 5);
  for (size_t f = 0; f < 5; ++f) {
    std::istringstream values(lines[motion + 3 + f]);
    int count = 0;
    for (double v; values >> v;) ++count;
    EXPECT_EQ(count, channels) << f;
  }
  EXPECT_EQ(write(a), text);  // deterministic
  EXPECT_EQ(text.find("-0.000000 "), std::string::npos);
  EXPECT_EQ(text.back(), '\n');
}

// --- forward kinematics of the file, from the BVH definition ---------------------

struct Node {
  std::string name;
  int parent = -1;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  std::vector<std::string> channels;
};

struct Parsed {
  std::vector<Node> nodes;  // file order
  std::vector<std::vector<double>> frames;
  double frame_time = 0.0;
};

Parsed parse(const std::string& text) {
  Parsed p;
  std::istringstream in(text);
  std::vector<int> stack;
  bool site = false;
  for (std::string word; in >> word;) {
    if (word == "ROOT" || word == "JOINT") {
      Node n;
      in >> n.name;
      n.parent = stack.empty() ? -1 : stack.back();
      p.nodes.push_back(n);
    } else if (word == "End") {
      in >> word;  // Site
      site = true;
    } else if (word == "{") {
      stack.push_back(site ? -2 : int(p.nodes.size()) - 1);
      site = false;
    } else if (word == "}") {
      stack.pop_back();
    } else if (word == "OFFSET") {
      Eigen::Vector3d v;
      in >> v.x() >> v.y() >> v.z();
      if (stack.back() >= 0) p.nodes[size_t(stack.back())].offset = v;
    } else if (word == "CHANNELS") {
      int count = 0;
      in >> count;
      p.nodes.back().channels.resize(size_t(count));
      for (std::string& c : p.nodes.back().channels) in >> c;
    } else if (word == "MOTION") {
      int frames = 0;
      in >> word >> frames >> word >> word >> p.frame_time;
      size_t values = 0;
      for (const Node& n : p.nodes) values += n.channels.size();
      p.frames.assign(size_t(frames), std::vector<double>(values));
      for (auto& f : p.frames)
        for (double& v : f) in >> v;
    }
  }
  return p;
}

Eigen::Matrix3d axisRotation(char axis, double degrees) {
  const double a = degrees * kPi / 180.0, c = std::cos(a), s = std::sin(a);
  Eigen::Matrix3d m;
  if (axis == 'X') m << 1, 0, 0, 0, c, -s, 0, s, c;
  if (axis == 'Y') m << c, 0, s, 0, 1, 0, -s, 0, c;
  if (axis == 'Z') m << c, -s, 0, s, c, 0, 0, 0, 1;
  return m;
}

// World position of every node at `frame`: rotations multiplied in channel order.
std::map<std::string, Eigen::Vector3d> fileWorld(const Parsed& p, size_t frame, double scale) {
  std::vector<Eigen::Matrix3d> rot(p.nodes.size());
  std::vector<Eigen::Vector3d> pos(p.nodes.size());
  std::map<std::string, Eigen::Vector3d> out;
  size_t at = 0;
  for (size_t i = 0; i < p.nodes.size(); ++i) {
    const Node& n = p.nodes[i];
    Eigen::Vector3d local = n.offset;
    Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
    for (const std::string& c : n.channels) {
      const double v = p.frames[frame][at++];
      if (c.find("position") != std::string::npos)
        local[c[0] - 'X'] = v;
      else
        r = r * axisRotation(c[0], v);
    }
    local /= scale;
    pos[i] = n.parent < 0 ? local
                          : Eigen::Vector3d(pos[size_t(n.parent)] + rot[size_t(n.parent)] * local);
    rot[i] = n.parent < 0 ? r : Eigen::Matrix3d(rot[size_t(n.parent)] * r);
    out[n.name] = pos[i];
  }
  return out;
}

// The asset's joint world positions at `frame` (quaternions, translations as stored).
std::vector<Eigen::Vector3d> assetWorld(const Asset& a, size_t frame) {
  const Skeleton& s = a.skeleton;
  const AnimationClip& c = a.animations.front();
  std::vector<Eigen::Matrix3d> rot(s.names.size());
  std::vector<Eigen::Vector3d> pos(s.names.size());
  for (size_t k = 0; k < s.names.size(); ++k) {
    const int p = s.parents[k];
    const Eigen::Vector3d local =
        p < 0 ? c.root_translation[frame]
              : (c.joint_translations.empty() ? Eigen::Vector3d(s.rest_local.row(Eigen::Index(k)))
                                              : c.joint_translations[k][frame]);
    const Eigen::Matrix3d r = c.rotations[k][frame].cast<double>().toRotationMatrix();
    pos[k] = p < 0 ? local : Eigen::Vector3d(pos[size_t(p)] + rot[size_t(p)] * local);
    rot[k] = p < 0 ? r : Eigen::Matrix3d(rot[size_t(p)] * r);
  }
  return pos;
}

double worstJointError(const Asset& a, const std::string& text, double scale) {
  const Parsed p = parse(text);
  EXPECT_EQ(p.frames.size(), a.animations.front().times.size());
  double worst = 0.0;
  for (size_t f = 0; f < p.frames.size(); ++f) {
    const std::map<std::string, Eigen::Vector3d> got = fileWorld(p, f, scale);
    const std::vector<Eigen::Vector3d> want = assetWorld(a, f);
    for (size_t k = 0; k < want.size(); ++k)
      worst = std::max(worst, (got.at(a.skeleton.names[k]) - want[k]).cwiseAbs().maxCoeff());
  }
  return worst;
}

TEST(BvhWriter, ReadBackGivesTheJointPositions) {
  const Asset a = smallAsset(40, 60.0);
  EXPECT_LT(worstJointError(a, write(a), 1.0), 1e-7);
  EXPECT_LT(worstJointError(a, write(a, "cm"), 100.0), 1e-7);
  const Parsed cm = parse(write(a, "cm"));
  EXPECT_EQ(cm.nodes[3].name, "spine1");
  EXPECT_NEAR(cm.nodes[3].offset.y(), 10.0, 1e-12);  // J_spine1 - J_pelvis, in centimetres
  EXPECT_NEAR(cm.frame_time, 1.0 / 60.0, 1e-10);
}

TEST(BvhWriter, AJointWithATranslationTrackGetsPositionChannels) {
  Asset a = smallAsset(6);
  AnimationClip& c = a.animations.front();
  c.joint_translations.resize(5);
  for (size_t k = 0; k < 5; ++k)
    c.joint_translations[k].assign(6, Eigen::Vector3d(a.skeleton.rest_local.row(Eigen::Index(k))));
  c.joint_translations[0] = c.root_translation;
  c.joint_translations[1][3] += Eigen::Vector3d(0.0, 0.02, 0.0);  // left_hip moves at frame 3
  const std::string text = write(a);
  const Parsed p = parse(text);
  ASSERT_EQ(p.nodes.size(), 5u);
  EXPECT_EQ(p.nodes[1].name, "left_hip");
  EXPECT_EQ(p.nodes[1].channels.size(), 6u);
  EXPECT_EQ(p.nodes[1].channels[1], "Yposition");
  EXPECT_EQ(p.nodes[2].channels.size(), 3u);  // left_knee: its track stays at rest
  EXPECT_EQ(p.nodes[3].channels.size(), 3u);
  EXPECT_EQ(p.nodes[4].channels.size(), 3u);
  EXPECT_LT(worstJointError(a, text, 1.0), 1e-7);
}

TEST(BvhWriter, RefusesWhatItCannotWrite) {
  Asset two = smallAsset(3);
  two.animations.push_back(two.animations.front());
  Result<std::string> r = bvhWriter().serialize(two, WriterOptions());
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.message(), "BVH writer: the asset has 2 animations; a BVH file holds one");
  WriterOptions inches;
  inches.bvh_units = "in";
  EXPECT_EQ(bvhWriter().serialize(smallAsset(3), inches).message(),
            "BVH writer: units 'in'; expected m or cm");
  Asset blank = smallAsset(3);
  blank.skeleton.names[2] = "spine 1";
  EXPECT_EQ(bvhWriter().serialize(blank, WriterOptions()).message(),
            "BVH writer: joint 2 name 'spine 1' is not one word (no blanks or braces)");
}

TEST(BvhWriter, IsTheTableRowForBvh) {
  const WriterFormat* row = writerFormatForPath("walk.BVH");
  ASSERT_NE(row, nullptr);
  EXPECT_EQ(row->name, "bvh");
  EXPECT_EQ(row->writer, &bvhWriter());
  EXPECT_FALSE(row->needs_mesh);
  EXPECT_TRUE(row->single_clip);
  EXPECT_EQ(row->options, (std::vector<std::string>{"--bvh-units", "--skeleton-names"}));
}

}  // namespace
}  // namespace smpl
