// An SMPL-family body model in memory, exactly as published, whatever file it
// came from. Generic in the joint count: SMPL (24), SMPL-H (52), SMPL-X (55),
// MANO (16). Arrays are reshaped for matrix products:
//   vertex-major 3N rows, row 3*i + c holds vertex i's coordinate c,
// so v_shaped = v_template + shapedirs * betas is one product.
// Built only by loadModel()/buildModel() or makeDemoBody(), which validate
// every shape; code that holds a BodyModel may rely on the invariants below.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

namespace smpl {

enum class ModelKind { Smpl, SmplH, SmplX, Mano };

const char* modelKindName(ModelKind kind);   // "smpl", "smplh", "smplx", "mano"
const char* modelKindLabel(ModelKind kind);  // for messages: "SMPL", "SMPL-H", "SMPL-X", "MANO"

struct BodyModel {
  ModelKind kind = ModelKind::Smpl;
  std::string name;                      // file name or "builtin"
  std::vector<std::string> joint_names;  // K names, model order
  std::vector<int> parents;              // K entries; parents[0] == -1, parents[k] < k
  Eigen::MatrixXd v_template;            // N x 3
  Eigen::MatrixXd shapedirs;             // 3N x B  (identity shape directions)
  Eigen::MatrixXd exprdirs;              // 3N x E  (SMPL-X expression; 0 columns otherwise)
  Eigen::MatrixXd posedirs;  // 3N x 9(K-1), column n = feature n of docs/file-contract.md
  Eigen::SparseMatrix<double, Eigen::RowMajor> j_regressor;  // K x N
  Eigen::MatrixXd weights;                                   // N x K, rows sum to 1
  Eigen::MatrixXi faces;                                     // F x 3, indices < N
  // MANO hand pose PCA carried by SMPL-H / SMPL-X / MANO files (empty if absent).
  Eigen::MatrixXd hands_components_l, hands_components_r;  // C x 45
  Eigen::VectorXd hands_mean_l, hands_mean_r;              // 45
  // Texture coordinates shipped in the model file (SMPL-X release: `vt`, `ft`);
  // empty if absent. Face i of texcoord_faces gives the UVs of faces row i.
  Eigen::MatrixXd texcoords;       // U x 2 (u, v), v up as in OBJ
  Eigen::MatrixXi texcoord_faces;  // F x 3 indices < U (0 rows if absent)

  int numVertices() const { return static_cast<int>(v_template.rows()); }
  int numJoints() const { return static_cast<int>(parents.size()); }
  int numBetas() const { return static_cast<int>(shapedirs.cols()); }
  int numExpressions() const { return static_cast<int>(exprdirs.cols()); }
  int numPoseFeatures() const { return static_cast<int>(posedirs.cols()); }
};

}  // namespace smpl
