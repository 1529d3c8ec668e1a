// Where this user's copy of the documentation pages is, for messages that
// point at a page (--help, an unknown motion layout). A message may name only
// a path that exists where the user runs the program: the command-line program
// looks for the pages beside its executable at startup (cli/docs_folder.h)
// and sets the folder here; without one (the Python module, WebAssembly, a
// binary copied on its own) messages name the page without a path.
#pragma once

#include <string>

namespace smpl {

// Sets the folder holding the pages (UTF-8, no trailing separator); "" clears
// it. Called once at startup, before any worker thread.
void setDocsFolder(const std::string& folder);

// "<page> in <folder>" when a folder is set, else "<page> in the smpl-export
// documentation (docs/ in its sources)". `page`: a file name like "motions.md".
std::string docsPageReference(const std::string& page);

// The folder set by setDocsFolder ("" when none).
std::string docsFolder();

}  // namespace smpl
