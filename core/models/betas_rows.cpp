#include "core/models/betas_rows.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace smpl {

Result<BetasRows> collapseBetasRows(const Array& a, const std::string& context) {
  if (a.isString() || a.isObject() || a.shape.empty() || a.shape.size() > 2 || a.size() == 0)
    return makeError(context + ": 'betas' has shape " + shapeString(a.shape) +
                     (a.isString() ? " of text" : "") + "; expected (B,) or (T,B) numbers");
  // Finite values and ranges are checked by the callers' input validation
  // (checkCoefficients), which names the offending index; NaN/Inf pass through the mean.
  BetasRows out;
  if (a.shape.size() == 1) {
    out.betas = a.data;
    return out;
  }
  const int64_t t = a.shape[0], b = a.shape[1];
  out.rows = static_cast<int>(t);
  out.betas.assign(a.data.begin(), a.data.begin() + b);
  bool identical = true;
  for (int64_t r = 1; r < t && identical; ++r)
    identical = std::equal(a.data.begin() + r * b, a.data.begin() + (r + 1) * b, a.data.begin());
  if (identical) return out;
  out.averaged = true;
  std::vector<double> mean(b, 0.0);
  for (int64_t r = 0; r < t; ++r)
    for (int64_t c = 0; c < b; ++c) mean[c] += a.data[r * b + c] / static_cast<double>(t);
  for (int64_t r = 0; r < t; ++r)
    for (int64_t c = 0; c < b; ++c)
      out.max_deviation = std::max(out.max_deviation, std::abs(a.data[r * b + c] - mean[c]));
  out.betas = std::move(mean);
  return out;
}

std::string betasRowsNote(const BetasRows& rows) {
  char buf[160];
  std::snprintf(
      buf, sizeof buf,
      "betas: %d per-frame rows differ (largest deviation from their mean %.6g); using their mean",
      rows.rows, rows.max_deviation);
  return buf;
}

}  // namespace smpl
