#include "cli/docs_folder.h"

#include <filesystem>
#include <system_error>

#include "core/os/path.h"

namespace smpl {

std::string findDocsFolder(const std::string& executable) {
  if (executable.empty()) return "";
  namespace fs = std::filesystem;
  const fs::path dir = os::fsPath(executable).parent_path();
  for (const char* relative : {"../share/doc/smpl-export", "../../docs", "../docs"}) {
    const fs::path candidate = (dir / os::fsPath(relative)).lexically_normal();
    std::error_code ec;
    if (fs::is_regular_file(candidate / "motions.md", ec) &&
        fs::is_regular_file(candidate / "cli.md", ec)) {
      std::string text = os::utf8(candidate);
      while (text.size() > 1 && (text.back() == '/' || text.back() == '\\')) text.pop_back();
      return text;
    }
  }
  return "";
}

}  // namespace smpl
