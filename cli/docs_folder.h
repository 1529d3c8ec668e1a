// The documentation pages beside the program, so that --help and error
// messages name a folder that exists where the user runs it: an installed
// tree (bin/smpl-export -> share/doc/smpl-export/, as cmake --install, the
// .deb and the release archives lay it out) or a build inside a clone
// (build/cli/smpl-export -> docs/).
#pragma once

#include <string>

namespace smpl {

// The first of <dir>/../share/doc/smpl-export, <dir>/../../docs, <dir>/../docs
// (dir: the folder of `executable`, a UTF-8 path) that holds motions.md and
// cli.md, as a normalised absolute path; "" when none does or `executable` is "".
std::string findDocsFolder(const std::string& executable);

}  // namespace smpl
