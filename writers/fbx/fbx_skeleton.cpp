// Joint Models (LimbNode), their NodeAttributes, the Skin deformer with one
// Cluster per joint, and the BindPose (fbx_scene_internal.h).
#include "writers/fbx/fbx_scene_internal.h"

namespace smpl {
namespace fbx {
namespace {

void addJointModel(SceneContext& ctx, int k) {
  const Skeleton& s = ctx.asset.skeleton;
  const std::string name = ctx.ns + s.names[k];
  int64_t model = ctx.ids.id("model/joint/" + std::to_string(k));
  ctx.joint_models.push_back(model);
  FbxNode& node = ctx.addObject("Model", model, name, "Model", "LimbNode");
  // Rest rotation is identity by contract, so a joint's animated local
  // rotation is the model's own R_k (docs/file-contract.md).
  addModelBody(node, s.rest_local(k, 0) * ctx.scale, s.rest_local(k, 1) * ctx.scale,
               s.rest_local(k, 2) * ctx.scale);

  int64_t attr = ctx.ids.id("attribute/joint/" + std::to_string(k));
  FbxNode& a = ctx.addObject("NodeAttribute", attr, name, "NodeAttribute", "LimbNode");
  pDouble(a.add("Properties70"), "Size", 10.0);
  a.add("TypeFlags").addString("Skeleton");

  int parent = s.parents[k];
  ctx.connectOO(model, parent < 0 ? ctx.skeleton_parent : ctx.joint_models[parent]);
  ctx.connectOO(attr, model);
}

// Per joint: the vertices it influences (ascending) and their weights.
struct JointInfluences {
  std::vector<int32_t> indexes;
  std::vector<double> weights;
};

std::vector<JointInfluences> influencesByJoint(const SkinnedMesh& m, size_t joints) {
  std::vector<JointInfluences> out(joints);
  for (Eigen::Index v = 0; v < m.joints.rows(); ++v) {
    for (Eigen::Index slot = 0; slot < m.joints.cols(); ++slot) {
      float w = m.weights(v, slot);
      if (w == 0.0f) continue;
      JointInfluences& j = out[m.joints(v, slot)];
      if (!j.indexes.empty() && j.indexes.back() == v) {
        j.weights.back() += w;  // the same joint twice in one row: one influence
      } else {
        j.indexes.push_back(static_cast<int32_t>(v));
        j.weights.push_back(w);
      }
    }
  }
  return out;
}

void addCluster(SceneContext& ctx, int k, int64_t skin, const JointInfluences& inf) {
  const Skeleton& s = ctx.asset.skeleton;
  int64_t id = ctx.ids.id("cluster/" + std::to_string(k));
  FbxNode& c = ctx.addObject("Deformer", id, ctx.ns + s.names[k], "SubDeformer", "Cluster");
  c.add("Version").addInt32(100);
  c.add("UserData").addString("").addString("");
  if (!inf.indexes.empty()) {
    c.add("Indexes").addInt32Array(inf.indexes);
    c.add("Weights").addDoubleArray(inf.weights);
  }
  double x = s.rest_world(k, 0) * ctx.scale, y = s.rest_world(k, 1) * ctx.scale,
         z = s.rest_world(k, 2) * ctx.scale;
  // Transform is stored in bone space: inverse(TransformLink) * mesh world,
  // with the mesh at the origin; TransformLink is the joint's bind world.
  c.add("Transform").addDoubleArray(translationMatrix(-x, -y, -z));
  c.add("TransformLink").addDoubleArray(translationMatrix(x, y, z));
  ctx.connectOO(id, skin);
  ctx.connectOO(ctx.joint_models[k], id);
}

void addBindPose(SceneContext& ctx) {
  const Skeleton& s = ctx.asset.skeleton;
  const std::string& name = ctx.bodyName();
  FbxNode& pose = ctx.addObject("Pose", ctx.ids.id("pose/bind"), name, "Pose", "BindPose");
  pose.add("Type").addString("BindPose");
  pose.add("Version").addInt32(100);
  pose.add("NbPoseNodes").addInt32(static_cast<int32_t>(s.names.size() + 1));
  FbxNode& mesh_node = pose.add("PoseNode");
  mesh_node.add("Node").addInt64(ctx.mesh_model);
  mesh_node.add("Matrix").addDoubleArray(translationMatrix(0, 0, 0));
  for (size_t k = 0; k < s.names.size(); ++k) {
    FbxNode& n = pose.add("PoseNode");
    n.add("Node").addInt64(ctx.joint_models[k]);
    n.add("Matrix").addDoubleArray(translationMatrix(s.rest_world(k, 0) * ctx.scale,
                                                     s.rest_world(k, 1) * ctx.scale,
                                                     s.rest_world(k, 2) * ctx.scale));
  }
}

}  // namespace

void buildSkeletonObjects(SceneContext& ctx) {
  for (size_t k = 0; k < ctx.asset.skeleton.names.size(); ++k)
    addJointModel(ctx, static_cast<int>(k));
}

void buildSkinObjects(SceneContext& ctx) {
  const std::string& name = ctx.bodyName();
  int64_t skin = ctx.ids.id("skin");
  FbxNode& d = ctx.addObject("Deformer", skin, name + "_skin", "Deformer", "Skin");
  d.add("Version").addInt32(101);
  d.add("Link_DeformAcuracy").addDouble(50.0);
  d.add("SkinningType").addString("Linear");
  ctx.connectOO(skin, ctx.mesh_geometry);
  std::vector<JointInfluences> inf =
      influencesByJoint(ctx.asset.mesh, ctx.asset.skeleton.names.size());
  for (size_t k = 0; k < inf.size(); ++k) addCluster(ctx, static_cast<int>(k), skin, inf[k]);
  addBindPose(ctx);
}

}  // namespace fbx
}  // namespace smpl
