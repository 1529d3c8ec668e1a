// The metadata object of DESIGN.md as JSON text: written into glTF
// (asset.extras.smpl) and as the sidecar <out>.smpl.json. One serialiser so
// the two cannot drift.
#pragma once

#include <string>

#include "exporter/asset.h"

namespace smpl {

// Deterministic JSON (fixed key order, shortest round-trip doubles).
std::string metadataJson(const Asset& asset);

}  // namespace smpl
