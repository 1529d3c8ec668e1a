#include "core/joint_names.h"

namespace smpl {
namespace {

const char* const kBody[] = {
    "pelvis",     "left_hip",    "right_hip",    "spine1",     "left_knee",     "right_knee",
    "spine2",     "left_ankle",  "right_ankle",  "spine3",     "left_foot",     "right_foot",
    "neck",       "left_collar", "right_collar", "head",       "left_shoulder", "right_shoulder",
    "left_elbow", "right_elbow", "left_wrist",   "right_wrist"};
const char* const kFingers[] = {"index1",  "index2", "index3", "middle1", "middle2",
                                "middle3", "pinky1", "pinky2", "pinky3",  "ring1",
                                "ring2",   "ring3",  "thumb1", "thumb2",  "thumb3"};

std::vector<std::string> body() {
  return std::vector<std::string>(std::begin(kBody), std::end(kBody));
}

void appendHand(std::vector<std::string>* names, const std::string& side) {
  for (const char* finger : kFingers) names->push_back(side + finger);
}

// Orders follow the model files (and the smplx Python package's JOINT_NAMES).
std::vector<std::string> makeNames(ModelKind kind) {
  std::vector<std::string> names;
  switch (kind) {
    case ModelKind::Smpl:
      names = body();
      names.push_back("left_hand");
      names.push_back("right_hand");
      break;
    case ModelKind::SmplH:
      names = body();
      appendHand(&names, "left_");
      appendHand(&names, "right_");
      break;
    case ModelKind::SmplX:
      names = body();
      names.push_back("jaw");
      names.push_back("left_eye_smplhf");   // the authors' names (smplx joint_names.py,
      names.push_back("right_eye_smplhf");  // their Blender add-on)
      appendHand(&names, "left_");
      appendHand(&names, "right_");
      break;
    case ModelKind::Mano:
      names.push_back("wrist");
      appendHand(&names, "");
      break;
  }
  return names;
}

}  // namespace

const std::vector<std::string>& canonicalJointNames(ModelKind kind) {
  static const std::vector<std::string> tables[] = {
      makeNames(ModelKind::Smpl), makeNames(ModelKind::SmplH), makeNames(ModelKind::SmplX),
      makeNames(ModelKind::Mano)};
  return tables[static_cast<int>(kind)];
}

std::string canonicalJointName(const std::string& name) {
  if (name == "left_eye") return "left_eye_smplhf";
  if (name == "right_eye") return "right_eye_smplhf";
  return name;
}

bool modelKindFromJointCount(int joints, ModelKind* kind) {
  switch (joints) {
    case 24:
      *kind = ModelKind::Smpl;
      return true;
    case 52:
      *kind = ModelKind::SmplH;
      return true;
    case 55:
      *kind = ModelKind::SmplX;
      return true;
    case 16:
      *kind = ModelKind::Mano;
      return true;
    default:
      return false;
  }
}

const char* modelKindName(ModelKind kind) {
  switch (kind) {
    case ModelKind::Smpl:
      return "smpl";
    case ModelKind::SmplH:
      return "smplh";
    case ModelKind::SmplX:
      return "smplx";
    case ModelKind::Mano:
      return "mano";
  }
  return "unknown";
}

const char* modelKindLabel(ModelKind kind) {
  switch (kind) {
    case ModelKind::Smpl:
      return "SMPL";
    case ModelKind::SmplH:
      return "SMPL-H";
    case ModelKind::SmplX:
      return "SMPL-X";
    case ModelKind::Mano:
      return "MANO";
  }
  return "?";
}

}  // namespace smpl
