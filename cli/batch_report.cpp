#include "cli/batch_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace smpl {

std::string formatDuration(double seconds) {
  const long total = static_cast<long>(std::ceil(std::max(0.0, seconds)));
  char text[32];
  if (total >= 3600)
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
  else
    std::snprintf(text, sizeof text, "%ld:%02ld", total / 60, total % 60);
  return text;
}

std::string batchProgressPrefix(size_t k, size_t n, double elapsed_s, bool eta) {
  std::string text = "[" + std::to_string(k) + "/" + std::to_string(n);
  if (eta && k > 0 && k < n)
    text +=
        ", ETA " + formatDuration(elapsed_s / static_cast<double>(k) * static_cast<double>(n - k));
  return text + "] ";
}

std::string batchThroughputLine(int converted, double wall_s, const StageSeconds& summed) {
  if (converted <= 0) return "";
  const double total = summed.read + summed.fit + summed.bake + summed.write;
  auto share = [&](double s) { return total > 0.0 ? 100.0 * s / total : 0.0; };
  char text[200];
  std::snprintf(text, sizeof text,
                "batch: %d motion%s in %.2f s (%.2f motions/s); time in read %.0f%%, fit %.0f%%, "
                "bake %.0f%%, write %.0f%%",
                converted, converted == 1 ? "" : "s", wall_s,
                wall_s > 0.0 ? converted / wall_s : 0.0, share(summed.read), share(summed.fit),
                share(summed.bake), share(summed.write));
  return text;
}

void BatchNotes::set(size_t index, const std::string& motion_name, std::vector<std::string> notes) {
  per_motion_[index] = Entry{motion_name, std::move(notes)};
}

std::vector<std::string> BatchNotes::folded() const {
  struct Group {
    size_t order;
    std::string first;  // the note as the first motion had it
    size_t count = 0;   // motions that have it
    size_t last = static_cast<size_t>(-1);
  };
  std::map<std::string, Group> groups;  // by the note without the motion's name
  size_t order = 0;
  for (size_t m = 0; m < per_motion_.size(); ++m) {
    const Entry& e = per_motion_[m];
    for (const std::string& note : e.notes) {
      const std::string prefix = e.name + ": ";
      const bool named = !e.name.empty() && note.compare(0, prefix.size(), prefix) == 0;
      const std::string key = named ? note.substr(prefix.size()) : note;
      auto [it, inserted] = groups.try_emplace(key, Group{order, note});
      if (inserted) ++order;
      if (it->second.last != m) ++it->second.count, it->second.last = m;
    }
  }
  std::vector<std::string> lines(groups.size());
  for (const auto& [key, g] : groups)
    lines[g.order] = g.count == 1 ? g.first : key + " (" + std::to_string(g.count) + " motions)";
  return lines;
}

}  // namespace smpl
