#pragma once
// The one parallel loop of Luz (DESIGN.md "Two targets"): the tracers' tiles, the radiosity's
// rows, the PNG encoder's rows all go through it. Which threads run it is chosen when Luz is
// built (LUZ_PARALLEL in src/core/CMakeLists.txt):
// - tbb: oneTBB's work-stealing scheduler (the desktop). The calls below are exactly the
//   tbb::parallel_for calls the code would make itself, so the desktop build is unchanged.
// - threads: threads_for below, plain std::threads, kept from loop to loop, sharing a counter of
//   chunks (the web page, where oneTBB does not build; on one thread where the page cannot have
//   threads).
// The loop returns when every call of `body` has; an exception thrown by `body` comes out of the
// loop (the first one thrown; the chunks not yet started are skipped).
#include <cstddef>
#include <functional>

#if LUZ_PARALLEL_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

namespace luz {

namespace parallel {

// Calls body(lo, hi) for consecutive chunks [lo, hi) of [begin, end), `grain` indices long (the
// last one shorter), on up to `threads` threads: the calling thread and up to threads - 1 of the
// threads the loops keep (started by the first loop that wants them, or by start_threads), each
// taking the next chunk not yet taken. threads <= 1 runs them in order on the calling thread.
// On a thread that must never block (the browser's main thread, a SpinningThread) the caller
// never waits on a lock or a condition: it spins until the kept threads' chunks are done,
// serving meanwhile what it is asked to serve.
void threads_for(size_t begin, size_t end, size_t grain, unsigned threads,
                 const std::function<void(size_t lo, size_t hi)>& body);

// While one lives, the calling thread is one that must never block, as the browser's main thread
// is in the page (where it always is): its loops take chunks themselves, the kept threads the
// others, and it spins for theirs, calling `serve` while it spins (the page's main thread runs
// the calls that workers proxied to it: a worker waiting on one would otherwise never return).
// Off the browser, for the tests of that path.
class SpinningThread {
public:
  explicit SpinningThread(std::function<void()> serve);
  ~SpinningThread();
  SpinningThread(const SpinningThread&) = delete;
  SpinningThread& operator=(const SpinningThread&) = delete;

private:
  std::function<void()> serve_;
  const std::function<void()>* outer_;
};

// Starts the threads threads_for keeps, one fewer than the cores, before a loop asks for them:
// the page calls it as it opens, because a thread a worker starts is started by the browser's
// main thread between two frames, a frame late for the loop that asked.
void start_threads();

// Whether a loop's body may run on the browser's main thread while the kept threads run it too.
// There, a thread that first meets a function-local static with a dynamic initialiser (`static
// T t = f();`, in Luz, a library or the C++ runtime) while another thread initialises it waits on
// a condition variable (libc++abi's guard), and so does the first thread-local object with a
// destructor of a thread that meets the runtime's list of those being set up: a wait the page's
// main thread must never make. So the main thread keeps a loop to itself (`alone`) unless the
// loop's body reaches neither, nor allocates (the page's allocator has one lock): `joins`, the
// radiosity's loops, whose bodies tests/test_main_thread_bodies.cpp holds to that.
enum class MainThread { alone, joins };

// The threads threads_for uses on this thread for a loop whose body is `main`: every core
// natively; in the page every core the browser offers, on its main thread only for a body that
// `joins` (the main thread then spins for the others' chunks) and one for the rest, and one in a
// build without threads.
unsigned thread_count(MainThread main = MainThread::alone);

}  // namespace parallel

// body(i) for every i in [begin, end).
template <class Index, class Body>
void parallel_for(Index begin, Index end, const Body& body) {
#if LUZ_PARALLEL_TBB
  tbb::parallel_for(begin, end, body);
#else
  if (!(begin < end)) return;
  parallel::threads_for(0, size_t(end - begin), 1, parallel::thread_count(), [&](size_t lo, size_t hi) {
    for (size_t i = lo; i < hi; ++i) body(Index(begin + Index(i)));
  });
#endif
}

// body(lo, hi) for subranges [lo, hi) that cover [begin, end) once, each at most about `grain`
// long (oneTBB may split a range down to grain / 2): for loops whose body is cheap, so that
// each thread takes work in pieces worth their overhead. `main`: whether the page's main thread
// may run the body beside the kept threads (MainThread above); oneTBB has no such thread.
template <class Index, class Body>
void parallel_for_ranges(Index begin, Index end, Index grain, const Body& body,
                         [[maybe_unused]] parallel::MainThread main = parallel::MainThread::alone) {
#if LUZ_PARALLEL_TBB
  tbb::parallel_for(tbb::blocked_range<Index>(begin, end, size_t(grain)),
                    [&](const tbb::blocked_range<Index>& range) { body(range.begin(), range.end()); });
#else
  if (!(begin < end)) return;
  parallel::threads_for(0, size_t(end - begin), size_t(grain), parallel::thread_count(main),
                        [&](size_t lo, size_t hi) { body(Index(begin + Index(lo)), Index(begin + Index(hi))); });
#endif
}

}  // namespace luz
