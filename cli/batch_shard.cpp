#include "cli/batch_shard.h"

#include <algorithm>
#include <filesystem>

#include "core/os/path.h"

namespace smpl {
namespace fs = std::filesystem;

std::vector<std::string> shardMotions(std::vector<std::string> files, const std::string& root,
                                      int index, int count) {
  auto key = [&](const std::string& p) {
    return os::genericUtf8(os::fsPath(p).lexically_relative(os::fsPath(root)));
  };
  std::sort(files.begin(), files.end(),
            [&](const std::string& a, const std::string& b) { return key(a) < key(b); });
  std::vector<std::string> share;
  for (size_t p = 0; p < files.size(); ++p)
    if (count <= 1 || static_cast<int>(p % static_cast<size_t>(count)) == index)
      share.push_back(files[p]);
  return share;
}

}  // namespace smpl
