#pragma once
// What `luz --version` says: the version (CMake's project version, the one place it is written)
// and, for a build from a Git clone, the commit it was configured at.
#include <string>

namespace luz {

const char* version();          // "0.1"
const char* git_description();  // `git describe` at configure time; empty outside a clone

// "luz 0.1 (git v0.1-3-gabc1234)" and a line per kind of file: where this luz reads them.
std::string version_text();

}  // namespace luz
