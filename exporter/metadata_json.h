// The metadata object of docs/file-contract.md as JSON text: written into glTF
// (asset.extras.smpl) and as the sidecar <out>.smpl.json. One serialiser so
// the two cannot drift.
#pragma once

#include <string>

#include "exporter/asset.h"

namespace smpl {

// Deterministic JSON (fixed key order, shortest round-trip doubles).
std::string metadataJson(const Asset& asset);

// The sidecar <out>.smpl.json: metadataJson plus, last,
// "producer": {"hash": producer_hash} (what made the output; exporter/request/producer.h).
std::string sidecarJson(const Asset& asset, const std::string& producer_hash);

// The producer hash recorded in a sidecar's text; "" when absent or when the
// text is not a JSON object (an old or damaged sidecar: rebuild).
std::string producerHashOf(const std::string& sidecar);

}  // namespace smpl
