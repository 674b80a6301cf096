#include "core/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#if defined(__EMSCRIPTEN__)
#include <emscripten/threading.h>
#endif

namespace luz::parallel {

namespace {

// The cores of this machine (the browser's, in the page), at least one.
unsigned cores() { return std::max(1u, std::thread::hardware_concurrency()); }

bool on_browser_main_thread() {
#if defined(__EMSCRIPTEN__) && defined(__EMSCRIPTEN_PTHREADS__)
  return emscripten_is_main_browser_thread();
#else
  return false;
#endif
}

thread_local const std::function<void()>* spinning_serve = nullptr;  // the innermost SpinningThread's

// Whether this thread must never wait on a lock or a condition variable: on the browser's main
// thread a wait freezes the page (Emscripten warns of each), and the calls a worker proxies to
// it would never run.
bool spins_here() { return spinning_serve != nullptr || on_browser_main_thread(); }

// A spinning thread's turn between two looks at what it waits for.
void serve_while_spinning() {
#if defined(__EMSCRIPTEN__) && defined(__EMSCRIPTEN_PTHREADS__)
  if (on_browser_main_thread()) emscripten_main_thread_process_queued_calls();
#endif
  if (spinning_serve) (*spinning_serve)();
  std::this_thread::yield();
}

// Takes `lock`'s mutex: by waiting where this thread may wait, by trying again and again where
// it must not.
void take(std::unique_lock<std::mutex>& lock) {
  if (!spins_here()) return lock.lock();
  while (!lock.try_lock()) serve_while_spinning();
}

// A loop offered to the kept threads: its work, how many more of them may join it, and how many
// work on it now.
struct Offer {
  const std::function<void()>* work = nullptr;
  size_t seats = 0;
  size_t inside = 0;
};

// The threads the loops share, started once and kept: a loop that started its own would pay for
// their start every time, and in the page a thread started from a worker is started by the
// browser's main thread, between two of its frames, so a loop's helpers came a frame late.
// Never destroyed: its threads wait for work until the program ends.
class KeptThreads {
public:
  static KeptThreads& get() {
    static KeptThreads* threads = new KeptThreads;
    return *threads;
  }

  // Starts threads until `count` are kept (without a lock: the browser's main thread may call it).
  void start(size_t count) {
    for (size_t have = started_.load(); have < count;)
      if (started_.compare_exchange_weak(have, have + 1)) std::thread([this] { serve(); }).detach();
  }

  // Runs `work` on the calling thread and on up to `seats` kept threads that are free meanwhile;
  // returns once every one of them has returned from it.
  void run(const std::function<void()>& work, size_t seats) {
    Offer offer{&work, seats};
    std::unique_lock lock(mutex_, std::defer_lock);
    take(lock);
    offers_.push_back(&offer);
    lock.unlock();
    offered_.notify_all();
    work();
    take(lock);
    offers_.erase(std::find(offers_.begin(), offers_.end(), &offer));  // no thread joins it now
    if (spins_here()) return spin_until_left(lock, offer);
    left_.wait(lock, [&offer] { return offer.inside == 0; });
  }

private:
  KeptThreads() = default;

  // run()'s end on a thread that must not block: the kept threads inside `offer` awaited by
  // looking again and again, the lock let go in between.
  static void spin_until_left(std::unique_lock<std::mutex>& lock, const Offer& offer) {
    while (offer.inside != 0) {
      lock.unlock();
      serve_while_spinning();
      take(lock);
    }
  }

  Offer* open_offer() {
    const auto open = std::find_if(offers_.begin(), offers_.end(), [](const Offer* o) { return o->seats > 0; });
    return open == offers_.end() ? nullptr : *open;
  }

  void serve() {
    std::unique_lock lock(mutex_);
    for (;;) {
      offered_.wait(lock, [this] { return open_offer() != nullptr; });
      Offer& offer = *open_offer();
      --offer.seats;
      ++offer.inside;
      lock.unlock();
      (*offer.work)();
      lock.lock();
      if (--offer.inside == 0) left_.notify_all();
    }
  }

  std::atomic<size_t> started_{0};
  std::mutex mutex_;
  std::condition_variable offered_, left_;
  std::vector<Offer*> offers_;  // the loops running, oldest first
};

}  // namespace

void threads_for(size_t begin, size_t end, size_t grain, unsigned threads,
                 const std::function<void(size_t lo, size_t hi)>& body) {
  if (begin >= end) return;
  grain = std::max<size_t>(grain, 1);
  const size_t chunks = (end - begin + grain - 1) / grain;
  std::atomic<size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr first_error;
  std::mutex error_mutex;
  const std::function<void()> work = [&] {
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
  if (helpers == 0) {
    work();
  } else {
    KeptThreads::get().start(helpers);
    KeptThreads::get().run(work, helpers);
  }
  if (first_error) std::rethrow_exception(first_error);
}

unsigned thread_count([[maybe_unused]] MainThread main) {
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
  return 1;
#else
  if (main == MainThread::alone && on_browser_main_thread()) return 1;
  return cores();
#endif
}

SpinningThread::SpinningThread(std::function<void()> serve) : serve_(std::move(serve)), outer_(spinning_serve) {
  spinning_serve = &serve_;
}

SpinningThread::~SpinningThread() { spinning_serve = outer_; }

void start_threads() {
#if !(defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__))
  KeptThreads::get().start(cores() - 1);
#endif
}

}  // namespace luz::parallel
