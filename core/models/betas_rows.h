// Betas as files store them: (B,), (1,B), or per frame (T,B) as video-based
// fitters write them. Per-frame rows are never flattened (which would mix
// rows 0 and 1): identical rows give that row; rows that differ give their
// mean, and the caller reports the largest deviation in a note. One rule for
// motions (`betas` key) and for --betas-file.
#pragma once

#include <string>
#include <vector>

#include "core/array.h"
#include "core/result.h"

namespace smpl {

struct BetasRows {
  std::vector<double> betas;   // B values
  int rows = 1;                // T (1 for (B,) and (1,B))
  bool averaged = false;       // rows differed: `betas` is their mean
  double max_deviation = 0.0;  // max over rows and columns of |row - mean| (0 if identical)
};

// `context` names file and key in errors: "walk.npz: 'betas' has shape (2,3,4); expected (B,) or
// (T,B)".
Result<BetasRows> collapseBetasRows(const Array& betas, const std::string& context);

// "betas: 120 per-frame rows differ (largest deviation from their mean 0.0123); using their mean".
std::string betasRowsNote(const BetasRows& rows);

}  // namespace smpl
