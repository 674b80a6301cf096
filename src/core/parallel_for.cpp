#include "core/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#if defined(__EMSCRIPTEN__)
#include <emscripten/threading.h>
#endif

namespace luz::parallel {

void threads_for(size_t begin, size_t end, size_t grain, unsigned threads,
                 const std::function<void(size_t lo, size_t hi)>& body) {
  if (begin >= end) return;
  grain = std::max<size_t>(grain, 1);
  const size_t chunks = (end - begin + grain - 1) / grain;
  std::atomic<size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr first_error;
  std::mutex error_mutex;
  const auto work = [&] {
    for (size_t c = next++; c < chunks && !failed.load(std::memory_order_relaxed); c = next++) {
      const size_t lo = begin + c * grain;
      try {
        body(lo, std::min(end, lo + grain));
      } catch (...) {
        const std::lock_guard lock(error_mutex);
        if (!first_error) first_error = std::current_exception();
        failed = true;
      }
    }
  };
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
  threads = 1;  // a page built without threads cannot start one
#endif
  const size_t helpers = std::min<size_t>(threads > 1 ? threads - 1 : 0, chunks - 1);
  std::vector<std::thread> started;
  started.reserve(helpers);
  for (size_t t = 0; t < helpers; ++t) started.emplace_back(work);
  work();
  for (std::thread& t : started) t.join();
  if (first_error) std::rethrow_exception(first_error);
}

unsigned thread_count() {
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
  return 1;
#else
#if defined(__EMSCRIPTEN__)
  if (emscripten_is_main_browser_thread()) return 1;
#endif
  return std::max(1u, std::thread::hardware_concurrency());
#endif
}

}  // namespace luz::parallel
