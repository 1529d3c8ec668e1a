// Canonical joint names per model family, in model order. These names become
// bone names and morph target names (pose_<joint>_<r><c>, docs/file-contract.md), so they
// are part of the exporter/runtime contract: do not rename.
#pragma once

#include <string>
#include <vector>

#include "core/body_model.h"

namespace smpl {

// Names for a family; empty if the family has no fixed table.
const std::vector<std::string>& canonicalJointNames(ModelKind kind);

// The name the tables use for `name`, accepting older spellings: SMPL-X's eye
// joints were "left_eye"/"right_eye" before this exporter took the authors'
// "left_eye_smplhf"/"right_eye_smplhf". Match bone names through this.
std::string canonicalJointName(const std::string& name);

// Guess the family from the joint count (24 SMPL, 52 SMPL-H, 55 SMPL-X, 16 MANO).
bool modelKindFromJointCount(int joints, ModelKind* kind);

}  // namespace smpl
