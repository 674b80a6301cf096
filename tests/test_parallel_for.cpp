// core/parallel_for.h: the loop visits every index once, on every target's threads, and passes
// the body's exception on. threads_for (the web page's loop) is checked here with several
// threads, as the page runs it on a worker.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/parallel_for.h"

namespace luz {
namespace {

// Each index of [begin, end) counted once, none outside it.
void expect_each_once(const std::vector<std::atomic<int>>& seen, size_t begin, size_t end) {
  for (size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i].load(), i >= begin && i < end ? 1 : 0) << "index " << i;
}

// How many threads ran a loop of 64 chunks of 2 ms each on up to 4 threads.
long threads_in_a_slow_loop() {
  std::vector<std::thread::id> ids(64);
  parallel::threads_for(0, ids.size(), 1, 4, [&](size_t lo, size_t) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    ids[lo] = std::this_thread::get_id();
  });
  std::sort(ids.begin(), ids.end());
  return std::unique(ids.begin(), ids.end()) - ids.begin();
}

// A loop inside a loop's body (each a caller of its own): every index of both once.
void expect_nested_loops_visit_each_once() {
  std::vector<std::atomic<int>> seen(40 * 30);
  parallel::threads_for(0, 40, 1, 4, [&](size_t lo, size_t) {
    parallel::threads_for(0, 30, 4, 4, [&](size_t a, size_t b) {
      for (size_t i = a; i < b; ++i) ++seen[lo * 30 + i];
    });
  });
  expect_each_once(seen, 0, seen.size());
}

TEST(ParallelFor, ThreadsForVisitsEachIndexOnceInChunksOfTheGrain) {
  for (const unsigned threads : {1u, 2u, 7u})
    for (const size_t grain : {size_t(1), size_t(3), size_t(64), size_t(1000)}) {
      std::vector<std::atomic<int>> seen(200);
      std::atomic<int> chunks{0};
      parallel::threads_for(5, 190, grain, threads, [&](size_t lo, size_t hi) {
        EXPECT_LT(lo, hi);
        EXPECT_LE(hi - lo, grain);
        EXPECT_EQ((lo - 5) % grain, 0u) << "chunks start at multiples of the grain";
        for (size_t i = lo; i < hi; ++i) ++seen[i];
        ++chunks;
      });
      expect_each_once(seen, 5, 190);
      EXPECT_EQ(size_t(chunks), (185 + grain - 1) / grain) << threads << " threads, grain " << grain;
    }
}

TEST(ParallelFor, ThreadsForRunsOnSeveralThreads) {
  EXPECT_GT(threads_in_a_slow_loop(), 1);
}

// The threads that help a loop are kept for the next ones (in the page, a thread started per loop
// came a frame late), and the loop returns only once each of them has finished its chunk.
TEST(ParallelFor, ThreadsForKeepsItsThreadsAndWaitsForThem) {
  thread_local int loops_helped = 0;
  std::atomic<int> most_loops_helped{0};
  const std::thread::id caller = std::this_thread::get_id();
  for (int loop = 0; loop < 20; ++loop) {
    std::atomic<int> chunks_done{0};
    parallel::threads_for(0, 8, 1, 2, [&](size_t, size_t) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
      if (std::this_thread::get_id() != caller) {
        static thread_local int last_loop = -1;
        if (last_loop != loop) last_loop = loop, ++loops_helped;
        int seen = most_loops_helped;
        while (seen < loops_helped && !most_loops_helped.compare_exchange_weak(seen, loops_helped)) {
        }
      }
      ++chunks_done;
    });
    EXPECT_EQ(chunks_done.load(), 8) << "loop " << loop << " returned before its chunks were done";
  }
  EXPECT_GT(most_loops_helped.load(), 1) << "a helping thread helps one loop only: threads are started per loop";
}

// A loop inside a loop's body (each a caller of its own) visits its indices once, the kept
// threads helping whichever loop they find.
TEST(ParallelFor, ThreadsForInsideThreadsFor) {
  expect_nested_loops_visit_each_once();
}

TEST(ParallelFor, ThreadsForOnOneThreadRunsInOrderOnTheCaller) {
  std::vector<size_t> order;
  const std::thread::id caller = std::this_thread::get_id();
  parallel::threads_for(0, 10, 3, 1, [&](size_t lo, size_t hi) {
    EXPECT_EQ(std::this_thread::get_id(), caller);
    order.push_back(lo);
    order.push_back(hi);
  });
  EXPECT_EQ(order, (std::vector<size_t>{0, 3, 3, 6, 6, 9, 9, 10}));
}

TEST(ParallelFor, ThreadsForPassesTheBodysExceptionOn) {
  for (const unsigned threads : {1u, 4u}) {
    std::atomic<int> calls{0};
    EXPECT_THROW(parallel::threads_for(0, 1000, 1, threads,
                                       [&](size_t lo, size_t) {
                                         ++calls;
                                         if (lo == 3) throw std::runtime_error("index 3");
                                         // The later chunks take a while, as real work does: four
                                         // threads must not all finish before the failure is seen.
                                         if (lo > 3) std::this_thread::sleep_for(std::chrono::milliseconds(1));
                                       }),
                 std::runtime_error);
    EXPECT_LT(calls.load(), 1000) << "the chunks after the failure are skipped";
  }
}

// On a thread that must never block (the browser's main thread in the page, as SpinningThread
// marks one here) the loop is the same loop: each index once, on several threads, the body's
// exception passed on, loops inside its body; and its caller spins for the kept threads' last
// chunks (the next test).
TEST(ParallelFor, ThreadsForOnASpinningThread) {
  const parallel::SpinningThread spinning([] {});
  for (const unsigned threads : {1u, 2u, 7u})
    for (const size_t grain : {size_t(1), size_t(3), size_t(1000)}) {
      std::vector<std::atomic<int>> seen(200);
      parallel::threads_for(5, 190, grain, threads, [&](size_t lo, size_t hi) {
        for (size_t i = lo; i < hi; ++i) ++seen[i];
      });
      expect_each_once(seen, 5, 190);
    }

  EXPECT_GT(threads_in_a_slow_loop(), 1);

  EXPECT_THROW(parallel::threads_for(0, 1000, 1, 4,
                                     [&](size_t lo, size_t) {
                                       if (lo == 3) throw std::runtime_error("index 3");
                                       if (lo > 3) std::this_thread::sleep_for(std::chrono::milliseconds(1));
                                     }),
               std::runtime_error);

  expect_nested_loops_visit_each_once();
}

// A kept thread whose chunk waits for the spinning caller (in the page, a worker's call proxied to
// the main thread) gets its answer: the caller serves it while it spins for that chunk, where a
// caller waiting on a condition would never answer (here the chunk gives up after 5 s, not served).
TEST(ParallelFor, ASpinningCallerServesWhatItsHelpersWaitFor) {
  std::atomic<bool> asked{false}, answered{false};
  std::atomic<int> waits{0}, unanswered{0};
  const parallel::SpinningThread spinning([&] {
    if (asked.exchange(false)) answered = true;
  });
  const std::thread::id caller = std::this_thread::get_id();
  parallel::threads_for(0, 200, 1, 2, [&](size_t, size_t) {
    if (std::this_thread::get_id() == caller) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      return;
    }
    ++waits;
    answered = false;
    asked = true;
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (!answered && std::chrono::steady_clock::now() < give_up) std::this_thread::yield();
    if (!answered) ++unanswered;
  });
  EXPECT_GT(waits.load(), 0) << "no chunk of the kept thread's: nothing was checked";
  EXPECT_EQ(unanswered.load(), 0) << "the caller did not serve while a helper waited on it";
}

TEST(ParallelFor, EmptyAndSingleRanges) {
  int calls = 0;
  parallel::threads_for(4, 4, 1, 4, [&](size_t, size_t) { ++calls; });
  parallel_for(size_t(4), size_t(4), [&](size_t) { ++calls; });
  parallel_for_ranges(7, 7, 2, [&](int, int) { ++calls; });
  EXPECT_EQ(calls, 0);
  std::vector<std::atomic<int>> seen(3);
  parallel_for(1, 2, [&](int i) { ++seen[size_t(i)]; });
  expect_each_once(seen, 1, 2);
}

// The loops the renderers call, on whichever threads this build chose (TBB on the desktop).
TEST(ParallelFor, BuildsLoopsVisitEachIndexOnce) {
  std::vector<std::atomic<int>> seen(5000);
  parallel_for(size_t(10), size_t(4990), [&](size_t i) { ++seen[i]; });
  expect_each_once(seen, 10, 4990);

  std::vector<std::atomic<int>> rows(1000);
  parallel_for_ranges(-3, 997, 32, [&](int lo, int hi) {
    EXPECT_LT(lo, hi);
    for (int i = lo; i < hi; ++i) ++rows[size_t(i + 3)];
  });
  expect_each_once(rows, 0, 1000);
  EXPECT_GT(parallel::thread_count(), 0u);
}

}  // namespace
}  // namespace luz
