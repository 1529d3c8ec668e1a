#include "cli/batch_shard.h"

#include <algorithm>

namespace smpl {
namespace fs = std::filesystem;

std::vector<fs::path> shardMotions(std::vector<fs::path> files, const fs::path& root, int index, int count) {
  auto key = [&](const fs::path& p) { return p.lexically_relative(root).generic_string(); };
  std::sort(files.begin(), files.end(), [&](const fs::path& a, const fs::path& b) { return key(a) < key(b); });
  std::vector<fs::path> share;
  for (size_t p = 0; p < files.size(); ++p)
    if (count <= 1 || static_cast<int>(p % static_cast<size_t>(count)) == index) share.push_back(files[p]);
  return share;
}

}  // namespace smpl
