#include "io/atomic_file.h"

#include <array>
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

// The paths the handler removes, in fixed slots: it only calls async-signal-safe functions
// (unlink, rmdir, sigaction, raise) on what was laid out before the count took it in.
constexpr size_t kSlots = 256;
std::array<std::array<char, 4096>, kSlots> g_paths;
volatile std::sig_atomic_t g_count = 0;
int g_guards = 0;
struct sigaction g_previous_int, g_previous_term;

extern "C" void remove_temporaries_and_reraise(int signal_number) {
  // The files first, whichever guard holds them, then the folders, the last laid out first: a
  // folder goes once what was written into it has.
  for (std::sig_atomic_t i = 0; i < g_count; ++i) unlink(g_paths[size_t(i)].data());
  for (std::sig_atomic_t i = g_count; i > 0; --i) rmdir(g_paths[size_t(i - 1)].data());
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
  raise(signal_number);
}

}  // namespace

RemovedOnSignal::RemovedOnSignal(const std::vector<fs::path>& paths) {
  for (const fs::path& path : paths) {
    const std::string name = path.string();
    // A path longer than a slot, or past the last slot, is not removed on a signal.
    if (name.size() >= g_paths[0].size() || size_t(g_count) == kSlots) continue;
    std::memcpy(g_paths[size_t(g_count)].data(), name.c_str(), name.size() + 1);
    g_count = g_count + 1;
    ++added_;
  }
  if (g_guards++ > 0) return;
  struct sigaction action {};
  action.sa_handler = remove_temporaries_and_reraise;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &g_previous_int);
  sigaction(SIGTERM, &action, &g_previous_term);
}

RemovedOnSignal::~RemovedOnSignal() {
  g_count = g_count - std::sig_atomic_t(added_);
  if (--g_guards > 0) return;
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
}

std::string write_atomically(const fs::path& path, const std::function<std::string()>& contents) {
  const fs::path temporary = temporary_beside(path);
  const RemovedOnSignal guard({temporary});
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
