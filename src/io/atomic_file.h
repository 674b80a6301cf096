#pragma once
// Files that appear whole or not at all: written beside their final name under a temporary one,
// then renamed over it. A reader never sees half a file, and a failed write leaves the old file.
#include <filesystem>
#include <functional>
#include <string>

namespace luz::io {

// Writes what `contents` returns to `path`. The temporary (".NAME.tmpXXXXXXXX.EXT" beside it) is
// opened before `contents` is called, so a folder that cannot be written to fails before the
// work of making them; it is removed when anything fails, and if SIGINT or SIGTERM arrives
// meanwhile. Returns "" once written, else why not (the system's words, or what `contents`
// threw).
std::string write_atomically(const std::filesystem::path& path, const std::function<std::string()>& contents);

}  // namespace luz::io
