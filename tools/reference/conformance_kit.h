// The runtime conformance kit (docs/conformance.md): fixed cases every
// corrective runtime (Python core, Maya glue, Unity C#, three.js, the Unreal
// core, the exporter's own C++) runs through its one loader and compares with
// the kit's single tolerance table.
#pragma once

#include <cstdint>
#include <string>

#include "core/body_model.h"

namespace smpl {

/// What `smpl-reference --conformance-kit DIR` writes and how.
struct KitRequest {
  std::string dir;      ///< output folder (created if missing; files replaced atomically)
  std::string perturb;  ///< "" or "CASE:features" / "CASE:weights": one wrong expected value
  uint64_t seed = 7;    ///< poses and bind orientations (pose_sampler.h)
};

/// Empty when `perturb` is "" or CASE:features / CASE:weights of a kit case,
/// else the error line (a usage error: checked before anything is written).
std::string checkPerturb(const std::string& perturb);

/// Writes DIR/manifest.json, DIR/<case>.smpl.json (the exporter's metadata of
/// the case's encoding, exporter/metadata_json.h), DIR/<case>.json (axes,
/// rest and posed bone rotations in the importer's frame, expected features
/// and weights) and DIR/bad/*.smpl.json (malformed sidecars with the error
/// kind each runtime must report). Expected values come from core/math
/// (poseFeatures of the model's local rotations) and the asset's metadata
/// (weight = scale f + offset, rectified, basis), never from a runtime.
/// Returns an error line naming the file, or empty.
std::string writeConformanceKit(const BodyModel& model, const KitRequest& request);

}  // namespace smpl
