#include "core/docs_location.h"

#include <mutex>

namespace smpl {
namespace {

std::mutex& folderMutex() {
  static std::mutex m;
  return m;
}

std::string& folderText() {
  static std::string folder;
  return folder;
}

}  // namespace

void setDocsFolder(const std::string& folder) {
  std::lock_guard<std::mutex> lock(folderMutex());
  folderText() = folder;
}

std::string docsFolder() {
  std::lock_guard<std::mutex> lock(folderMutex());
  return folderText();
}

std::string docsPageReference(const std::string& page) {
  const std::string folder = docsFolder();
  if (folder.empty()) return page + " in the smpl-export documentation (docs/ in its sources)";
  return page + " in " + folder;
}

}  // namespace smpl
