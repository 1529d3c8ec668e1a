// The conformance kit's malformed sidecars (docs/conformance.md, "Bad
// sidecars"): each must be refused by every runtime's sidecar reader with an
// error naming `error` (or, for "json", any parse error).
#pragma once

#include <string>
#include <vector>

namespace smpl {

struct BadSidecar {
  std::string name;    ///< file stem: bad/<name>.smpl.json
  std::string error;   ///< the field the error names: json, joint_names, parents, correctives,
                       ///< corrective_basis
  std::string what;    ///< what is wrong, one line
  std::string text;    ///< the file's bytes
  bool schema = true;  ///< docs/sidecar.schema.json rejects it (false: a cross-field rule)
};

/// The fixed list, on a 3-joint skeleton a <- b <- c (P = 18 features).
std::vector<BadSidecar> badSidecars();

}  // namespace smpl
