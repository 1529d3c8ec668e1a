// Per-target scales for quantized morph targets (ExportOptions::quantize_morphs).
//
// KHR_mesh_quantization stores morph deltas as normalised SHORT, i.e. values in
// [-1, 1] with a step of 1/32767. glTF has no per-accessor dequantisation
// scale, and the spec's shared transform (folded into the skin's inverse bind
// matrices) would give every target the grid of the largest one and put a
// scale into the bind pose, which the runtime formula of docs/file-contract.md assumes is
// pure rotation/translation. Instead each corrective target n is stored as
// d_n / s_n, s_n = max |component of d_n|, and s_n is folded into its weight:
// the metadata mapping becomes weight = (s_n scale) f + (s_n offset), so
// weight * stored delta is unchanged and the runtime formula
// weight = scale * f + offset still holds with the file's own numbers. Rest
// weights and animated weights are multiplied by s_n as well. The quantisation
// error of target n is then at most s_n / 65534 per component instead of
// 1 / 65534 m. --corrective-basis targets (pose_basis_<k>) are quantized the
// same way, s_k folded into the basis' scale and offset. Targets without a
// corrective mapping (shape_<i>, expr_<i>: their weight is the coefficient
// itself) keep FLOAT deltas and weight scale 1; the CLI says so in a note.
// exportAsset (export_asset.h) folds once and marks the folded targets
// MorphTarget::quantized; the glTF writer stores exactly those as int16 and
// computes no scale itself. Folding twice is the identity (after one fold
// every scale is exactly 1).
#pragma once

#include <vector>

#include "exporter/asset.h"

namespace smpl {

// Quantized targets: correctives and basis targets with some non-zero delta.
std::vector<bool> quantizedTargets(const Asset& asset);

// s_n per morph target: max |delta component| for quantized targets, else 1.
std::vector<double> morphWeightScales(const Asset& asset);

// Multiplies the metadata mapping of every corrective (and basis target) naming target n by s[n].
void foldScalesIntoMetadata(const std::vector<double>& s, const SkinnedMesh& mesh,
                            AssetMetadata* metadata);

// The whole fold on an asset: deltas / s_n, metadata, rest and animated weights * s_n;
// every target of quantizedTargets() gets MorphTarget::quantized = true.
void foldMorphScales(Asset* asset);

}  // namespace smpl
