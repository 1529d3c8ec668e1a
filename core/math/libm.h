// The transcendental functions every output depends on, from one
// implementation on every platform: musl's libm (Debian's musl-dev on Linux,
// Debian's musl source compiled for Windows; cmake/PortableLibm.cmake), not
// the C library's. glibc and mingw-w64 disagree in the last bit of about 3%
// of sin/cos/atan2/asin/exp values, and glibc picks FMA code paths by CPU, so
// with the C library's functions a Linux and a Windows build (or two CPUs)
// write different bytes. Code that computes an output calls smpl::libm::,
// never std::sin & co, nor Eigen's AngleAxis / slerp / eulerAngles (which call
// std::); scripts/check-portable.py (test layers.portable) enforces it. sqrt, fabs,
// floor and the arithmetic operators are exact (IEEE 754) everywhere.
// Arguments and results in radians where angles are meant.
#pragma once

#include <smpl_m.h>

namespace smpl::libm {

inline double sin(double x) { return smpl_m_sin(x); }
inline double cos(double x) { return smpl_m_cos(x); }
inline double tan(double x) { return smpl_m_tan(x); }
inline double asin(double x) { return smpl_m_asin(x); }
inline double acos(double x) { return smpl_m_acos(x); }
inline double atan(double x) { return smpl_m_atan(x); }
inline double atan2(double y, double x) { return smpl_m_atan2(y, x); }
inline double exp(double x) { return smpl_m_exp(x); }
inline double log(double x) { return smpl_m_log(x); }
inline double pow(double x, double y) { return smpl_m_pow(x, y); }
inline double hypot(double x, double y) { return smpl_m_hypot(x, y); }

}  // namespace smpl::libm
