// Range checks for every number that enters from a file or the command line,
// applied where it enters, so a bad value is reported as a load error (exit 2)
// naming the file and the key rather than surfacing later as NaN vertices, an
// +Inf key in the output or an export error naming the output. A loaded
// motion's values are checked by core/motions/validate_motion.h against
// the same bounds.
//
// Bounds (documented in the README):
//   betas, expression   finite, |value| <= 1000 (kMaxCoefficient). Fitted
//                       bodies stay within a few units; 1000 standard
//                       deviations is far beyond any body and still keeps the
//                       float32 output finite.
//   model arrays        finite and within float32 range (|v| <= FLT_MAX): the
//                       writers store float32, so 1e300 would become Inf.
//   face indices        integral (1.5 is refused, not truncated), >= 0, < 2^31.
//   frame rates         1 to 10000 frames per second (kMinFrameRate..kMaxFrameRate).
//   translations        |component| <= 10000 m (kMaxTranslation).
//   UV coordinates      finite, |value| <= 1000 (kMaxTexCoord; 1 = one texture
//                       width: UDIM layouts use 0..10), from .npy, .obj or the
//                       model file's vt.
//   DMPL basis          `eigvec` finite, |value| <= 10 m per unit coefficient
//                       (kMaxDmplDisplacement: soft tissue moves centimetres;
//                       the public basis stays below 0.1).
//   DMPL coefficients   a motion's `dmpls` finite, |value| <= 1000
//                       (kMaxCoefficient, as betas: the coefficients are in
//                       the basis' standard deviations).
//   rotation matrices   orthonormal with det +1: ||R^T R - I||_F <= 1e-3
//                       (kRotationTolerance, float32 storage is ~1e-7). Within
//                       the tolerance R is replaced by its nearest rotation
//                       (polar decomposition, U V^T of the SVD), so later math
//                       sees an exact rotation; beyond it the file is refused
//                       with the frame and joint named (a zero or scaled matrix
//                       is not a rotation: guessing one would hide a bug in
//                       whatever wrote the file).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/array.h"
#include "core/result.h"

namespace smpl {

constexpr double kMaxCoefficient = 1e3;
constexpr double kMaxTranslation = 1e4;  // metres
constexpr double kMinFrameRate = 1.0;    // frames per second
constexpr double kMaxFrameRate = 10000.0;
constexpr double kRotationTolerance = 1e-3;  // Frobenius norm of R^T R - I
constexpr double kMaxTexCoord = 1e3;
constexpr double kMaxDmplDisplacement = 10.0;  // metres per unit DMPL coefficient

// A value as the range errors print it (printf "%.6g": "1e+300", "-0.5").
std::string boundText(double v);

// Betas or expression coefficients; `what` names them in errors ("'betas'").
Status checkCoefficients(const std::vector<double>& values, const std::string& context,
                         const std::string& what);

// Every value finite and representable as float32.
Status checkFloatRange(const Array& a, const std::string& context, const std::string& key);

// Every value an integer in [0, 2^31): face and other index arrays.
Status checkIndices(const Array& a, const std::string& context, const std::string& key);

// A frame rate in [kMinFrameRate, kMaxFrameRate]; `key` names where it came from.
Status checkFrameRate(double fps, const std::string& context, const std::string& key);

// `count` UV coordinates (u, v interleaved or one column after the other: only
// the values matter); `key` names them ("'vt'", "UV coordinates"), element i
// is named in the error.
Status checkTexCoords(const double* values, size_t count, const std::string& context,
                      const std::string& key);

// A DMPL basis `eigvec` (N,3,D): finite, within kMaxDmplDisplacement.
Status checkDmplBasisValues(const Array& eigvec, const std::string& context);

// A motion's DMPL coefficients `dmpls` (T x D): finite, within
// kMaxCoefficient; the error names the frame and the column.
Status checkDmplValues(const Eigen::MatrixXd& dmpls, const std::string& context);

}  // namespace smpl
