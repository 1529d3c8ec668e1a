#include "request/error_line.h"

#include "core/io/printable.h"

namespace smpl {

std::string errorLine(const std::string& verb, const std::string& path,
                      const std::string& message) {
  // Paths and messages may carry bytes from files or the command line: one
  // printable line. A long path loses its middle (each time it appears), and
  // a line still over 4 KiB loses its middle too: the reason, last, stays.
  constexpr size_t kPathBytes = 1024, kLineBytes = 4096;
  const std::string full = printable(path, static_cast<size_t>(-1));
  const std::string shown = printableMiddle(path, kPathBytes);
  std::string text = printable(message, static_cast<size_t>(-1));
  for (size_t at = 0;
       full != shown && !full.empty() && (at = text.find(full, at)) != std::string::npos;
       at += shown.size())
    text.replace(at, full.size(), shown);
  if (text.compare(0, shown.size() + 1, shown + ":") == 0)
    return printableMiddle("Error " + verb + " " + text, kLineBytes);
  return printableMiddle("Error " + verb + " " + shown + ": " + text, kLineBytes);
}

}  // namespace smpl
