#include "io/atomic_file.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <exception>
#include <fstream>
#include <random>

#include <signal.h>
#include <unistd.h>

#include <fmt/format.h>

namespace luz::io {
namespace fs = std::filesystem;

namespace {

// A name beside the target, with the same extension.
fs::path temporary_beside(const fs::path& path) {
  std::random_device random;
  return path.parent_path() /
         fmt::format(".{}.tmp{:08x}{}", path.stem().string(), random(), path.extension().string());
}

// While the temporary file exists, SIGINT and SIGTERM remove it before the process ends as it
// would have (the previous disposition is restored and the signal raised again). The handler
// only calls async-signal-safe functions (unlink, sigaction, raise) on a fixed buffer.
char g_temporary[4096];
struct sigaction g_previous_int, g_previous_term;

extern "C" void remove_temporary_and_reraise(int signal_number) {
  unlink(g_temporary);
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
  raise(signal_number);
}

class TemporaryGuard {
 public:
  explicit TemporaryGuard(const fs::path& temporary) {
    const std::string name = temporary.string();
    armed_ = name.size() < sizeof g_temporary;
    if (!armed_) return;
    std::memcpy(g_temporary, name.c_str(), name.size() + 1);
    struct sigaction action {};
    action.sa_handler = remove_temporary_and_reraise;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &g_previous_int);
    sigaction(SIGTERM, &action, &g_previous_term);
  }
  ~TemporaryGuard() {
    if (!armed_) return;
    sigaction(SIGINT, &g_previous_int, nullptr);
    sigaction(SIGTERM, &g_previous_term, nullptr);
  }
  TemporaryGuard(const TemporaryGuard&) = delete;
  TemporaryGuard& operator=(const TemporaryGuard&) = delete;

 private:
  bool armed_ = false;
};

}  // namespace

std::string write_atomically(const fs::path& path, const std::function<std::string()>& contents) {
  const fs::path temporary = temporary_beside(path);
  const TemporaryGuard guard(temporary);
  auto fail = [&](std::string why) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    return why;
  };
  std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
  if (!file) return fail(std::strerror(errno));
  std::string bytes;
  try {
    bytes = contents();
  } catch (const std::exception& e) {  // out of memory
    return fail(e.what());
  }
  file.write(bytes.data(), std::streamsize(bytes.size()));
  file.close();
  if (!file) return fail(std::strerror(errno));
  std::error_code error;
  fs::rename(temporary, path, error);
  if (error) return fail(error.message());
  return {};
}

}  // namespace luz::io
