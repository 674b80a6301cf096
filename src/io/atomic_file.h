#pragma once
// Files that appear whole or not at all: written beside their final name under a temporary one,
// then renamed over it. A reader never sees half a file, and a failed write leaves the old file.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace luz::io {

// Writes what `contents` returns to `path`. The temporary (".NAME.tmpXXXXXXXX.EXT" beside it) is
// opened before `contents` is called, so a folder that cannot be written to fails before the
// work of making them; it is removed when anything fails, and if SIGINT or SIGTERM arrives
// meanwhile. Returns "" once written, else why not (the system's words, or what `contents`
// threw).
std::string write_atomically(const std::filesystem::path& path, const std::function<std::string()>& contents);

// While it lives, SIGINT and SIGTERM remove `paths` (the files, then the folders emptied) before
// the process ends as it would have: the disposition before the first guard is restored and the
// signal raised again. For outputs written under temporary names; guards nest (a handout's
// folder, and each image written into it), the last made gone first.
class RemovedOnSignal {
public:
  explicit RemovedOnSignal(const std::vector<std::filesystem::path>& paths);
  ~RemovedOnSignal();
  RemovedOnSignal(const RemovedOnSignal&) = delete;
  RemovedOnSignal& operator=(const RemovedOnSignal&) = delete;

private:
  size_t added_ = 0;
};

}  // namespace luz::io
