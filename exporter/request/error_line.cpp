#include "exporter/request/error_line.h"

#include "core/io/printable.h"

namespace smpl {

std::string errorLine(const std::string& verb, const std::string& path,
                      const std::string& message) {
  if (message.compare(0, path.size() + 1, path + ":") == 0)
    return printable("Error " + verb + " " + message, 4096);
  return printable("Error " + verb + " " + path + ": " + message, 4096);
}

}  // namespace smpl
