// The conformance kit's malformed sidecars (kit_bad_sidecars.h).
#include "tools/reference/kit_bad_sidecars.h"

namespace smpl {
namespace {

const char* kSkeleton = R"("joint_names": ["a", "b", "c"], "parents": [-1, 0, 1], "up_axis": "+Y")";

std::string withSkeleton(const std::string& rest) {
  return std::string("{") + kSkeleton + (rest.empty() ? "" : ", " + rest) + "}\n";
}

}  // namespace

std::vector<BadSidecar> badSidecars() {
  std::string zeros = "0";
  for (int i = 1; i < 36; ++i) zeros += ", 0";  // a 2 x 18 matrix
  return {
      {"truncated", "json", "the text ends inside an array", "{\"joint_names\": [\"a\", \"b\"\n"},
      {"not_an_object", "json", "the top level is an array", "[1, 2, 3]\n"},
      {"lengths_differ", "parents", "3 joint names, 2 parents",
       R"({"joint_names": ["a", "b", "c"], "parents": [-1, 0], "correctives": []})"
       "\n",
       false},
      {"parent_after_child", "parents", "parents[1] = 2: a parent after its child",
       R"({"joint_names": ["a", "b", "c"], "parents": [-1, 2, 0], "correctives": []})"
       "\n",
       false},
      {"root_has_parent", "parents", "parents[0] = 1: the root has a parent",
       R"({"joint_names": ["a", "b", "c"], "parents": [1, 0, 1], "correctives": []})"
       "\n",
       false},
      {"names_not_strings", "joint_names", "joint_names holds numbers",
       R"({"joint_names": [1, 2, 3], "parents": [-1, 0, 1], "correctives": []})"
       "\n"},
      {"feature_out_of_range", "correctives", "feature 18 of P = 18",
       withSkeleton(
           R"("correctives": [{"feature": 18, "target": "pose_c_22", "scale": 1, "offset": 0}])"),
       false},
      {"negative_feature", "correctives", "feature -1",
       withSkeleton(
           R"("correctives": [{"feature": -1, "target": "pose_b_00", "scale": 1, "offset": 0}])")},
      {"scale_not_a_number", "correctives", "scale is a string",
       withSkeleton(
           R"("correctives": [{"feature": 0, "target": "pose_b_00", "scale": "x", "offset": 0}])")},
      {"correctives_not_a_list", "correctives", "correctives is an object",
       withSkeleton(R"("correctives": {"feature": 0})")},
      {"basis_matrix_size", "corrective_basis",
       "2 basis targets, 5 matrix values (expected 2 x 18)",
       withSkeleton(
           R"("correctives": [], "corrective_basis": {"targets": ["pose_basis_0", "pose_basis_1"], "features": 18, "matrix": [1, 2, 3, 4, 5], "scale": [1, 1], "offset": [0, 0]})"),
       false},
      {"basis_scale_count", "corrective_basis", "2 basis targets, 1 scale",
       withSkeleton(
           R"("correctives": [], "corrective_basis": {"targets": ["pose_basis_0", "pose_basis_1"], "features": 18, "matrix": [)" +
           zeros + R"(], "scale": [1], "offset": [0, 0]})"),
       false},
  };
}

}  // namespace smpl
