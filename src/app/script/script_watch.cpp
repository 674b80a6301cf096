#include "app/script/script_watch.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <ctime>

#include <unistd.h>

namespace luz::app::script_watch {
namespace {

// Two buffers: `at` writes the one the handler is not reading, then makes it the current one.
std::array<std::array<char, 512>, 2> where_text{};
std::array<std::atomic<size_t>, 2> where_size{};
std::atomic<int> current{0};
std::atomic<long> frames{0};
std::atomic<long long> frame_began_ns{0};

long long monotonic_ns() {  // clock_gettime is async-signal-safe; std::chrono's clocks are not said to be
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (long long)t.tv_sec * 1000000000LL + t.tv_nsec;
}

// The handler may only call async-signal-safe functions: no stdio, no allocation.
void put(int fd, const char* text, size_t size) {
  while (size > 0) {
    const ssize_t n = write(fd, text, size);
    if (n <= 0) return;
    text += n;
    size -= size_t(n);
  }
}

void put(int fd, const char* text) {
  size_t size = 0;
  while (text[size]) ++size;
  put(fd, text, size);
}

void put(int fd, long long value) {
  char digits[24];
  int n = 0;
  const bool negative = value < 0;
  unsigned long long v = negative ? 0ULL - (unsigned long long)value : (unsigned long long)value;
  do {
    digits[n++] = char('0' + v % 10);
    v /= 10;
  } while (v > 0);
  if (negative) digits[n++] = '-';
  std::reverse(digits, digits + n);
  put(fd, digits, size_t(n));
}

extern "C" void on_signal(int signal) {
  const int fd = STDERR_FILENO;
  const int i = current.load();
  put(fd, "luz: stopped by signal ");
  put(fd, signal);
  put(fd, " during the script, at ");
  put(fd, where_text[size_t(i)].data(), where_size[size_t(i)].load());
  put(fd, "; ");
  put(fd, frames.load());
  put(fd, " frames drawn");
  if (const long long began = frame_began_ns.load(); began > 0) {
    put(fd, ", the last one began ");
    put(fd, (monotonic_ns() - began) / 1000000LL);
    put(fd, " ms ago");
  }
  put(fd, "\n");
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

}  // namespace

void install() {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  at("the script's start");
  std::signal(SIGTERM, on_signal);
  std::signal(SIGINT, on_signal);
}

void at(std::string_view where) {
  const int next = 1 - current.load();
  const size_t size = std::min(where.size(), where_text[0].size());
  std::copy_n(where.data(), size, where_text[size_t(next)].data());
  where_size[size_t(next)] = size;
  current = next;
}

void frame_begins() {
  ++frames;
  frame_began_ns = monotonic_ns();
}

}  // namespace luz::app::script_watch
