// Input range checks (see the header for the bounds and why).
#include "core/models/validate_inputs.h"

#include <cfloat>
#include <cmath>
#include <cstdio>

namespace smpl {

std::string boundText(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

Status checkCoefficients(const std::vector<double>& values, const std::string& context,
                         const std::string& what) {
  for (size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]) || std::abs(values[i]) > kMaxCoefficient)
      return makeError(context + ": " + what + "[" + std::to_string(i) + "] is " +
                       boundText(values[i]) + "; expected a finite value with magnitude at most " +
                       boundText(kMaxCoefficient));
  return Status();
}

Status checkFloatRange(const Array& a, const std::string& context, const std::string& key) {
  bool bad = false;  // one branch-free (vectorised) pass; the loop below names the element
  for (double v : a.data) bad |= !(std::abs(v) <= FLT_MAX);
  if (!bad) return Status();
  for (size_t i = 0; i < a.data.size(); ++i) {
    const double v = a.data[i];
    if (!std::isfinite(v))
      return makeError(context + ": '" + key + "' contains NaN or infinite values");
    if (std::abs(v) > FLT_MAX)
      return makeError(context + ": '" + key + "' element " + std::to_string(i) + " is " +
                       boundText(v) + ", beyond the float32 range the output is written in");
  }
  return Status();
}

Status checkIndices(const Array& a, const std::string& context, const std::string& key) {
  for (size_t i = 0; i < a.data.size(); ++i) {
    const double v = a.data[i];
    if (!(v >= 0 && v < 2147483648.0) || v != std::floor(v))
      return makeError(context + ": '" + key + "' element " + std::to_string(i) + " is " +
                       boundText(v) + "; expected a non-negative integer index");
  }
  return Status();
}

Status checkFrameRate(double fps, const std::string& context, const std::string& key) {
  if (!(fps >= kMinFrameRate && fps <= kMaxFrameRate))
    return makeError(context + ": " + key + " is " + boundText(fps) +
                     " frames per second; expected " + boundText(kMinFrameRate) + " to " +
                     boundText(kMaxFrameRate));
  return Status();
}

Status checkTexCoords(const double* values, size_t count, const std::string& context,
                      const std::string& key) {
  for (size_t i = 0; i < count; ++i)
    if (!(std::abs(values[i]) <= kMaxTexCoord))
      return makeError(context + ": " + key + " element " + std::to_string(i) + " is " +
                       boundText(values[i]) + "; expected finite texture coordinates within " +
                       boundText(kMaxTexCoord));
  return Status();
}

Status checkDmplBasisValues(const Array& eigvec, const std::string& context) {
  for (size_t i = 0; i < eigvec.data.size(); ++i) {
    const double v = eigvec.data[i];
    if (!(std::abs(v) <= kMaxDmplDisplacement))
      return makeError(context + ": 'eigvec' element " + std::to_string(i) + " is " + boundText(v) +
                       "; expected finite values within " + boundText(kMaxDmplDisplacement) +
                       " m per unit coefficient");
  }
  return Status();
}

Status checkDmplValues(const Eigen::MatrixXd& dmpls, const std::string& context) {
  for (Eigen::Index t = 0; t < dmpls.rows(); ++t)
    for (Eigen::Index d = 0; d < dmpls.cols(); ++d)
      if (!(std::abs(dmpls(t, d)) <= kMaxCoefficient))
        return makeError(context + ": 'dmpls' frame " + std::to_string(t) + " column " +
                         std::to_string(d) + " is " + boundText(dmpls(t, d)) +
                         "; expected a finite value with magnitude at most " +
                         boundText(kMaxCoefficient));
  return Status();
}

}  // namespace smpl
