// The .usda text forms the USD writer needs: numbers, vectors, matrices,
// quaternions, identifiers and strings, each deterministic (same value, same
// bytes on every platform). Grammar: the OpenUSD text file format
// (pxr/usd/sdf/textFileFormat.yy); GfQuat text is (real, i, j, k) and
// GfMatrix4d text is row by row, ((m00, m01, m02, m03), ...), in USD's
// row-vector convention (a translation is the last row).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>

namespace smpl {
namespace usd {

// Text that reads back as the same float / double: %g with the fewest
// digits that round-trip (a float: at least 6); -0 as "0".
void appendFloat(std::string& out, float v);
void appendDouble(std::string& out, double v);

// "(x, y, z)" of a float triple.
void appendFloat3(std::string& out, float x, float y, float z);

// "(w, x, y, z)": a GfQuatf as the text format writes it (real part first).
void appendQuat(std::string& out, const Eigen::Quaternionf& q);

// "((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (tx, ty, tz, 1))": the
// matrix4d of a translation by `t` (metres), row-vector convention.
void appendTranslationMatrix(std::string& out, const Eigen::Vector3d& t);

// True when `name` is a USD identifier [A-Za-z_][A-Za-z0-9_]* (a prim name, a
// path element of a UsdSkel joint token).
bool isIdentifier(const std::string& name);

// `text` as a double-quoted USD string: '"' and '\' escaped, control bytes as
// \n, \t or \xHH.
std::string quoted(const std::string& text);

}  // namespace usd
}  // namespace smpl
