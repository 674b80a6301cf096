#pragma once
// The two C++20 library pieces Luz uses that not every standard library it is built with has:
// luz::bit_cast and luz::jthread. GCC's libstdc++ (the desktop build) has both, and then they
// are exactly std::bit_cast and std::jthread; Emscripten's libc++ 13 (the web page) has
// neither, and then bit_cast is the compiler's __builtin_bit_cast (what std::bit_cast is made
// of in every library that has it) and jthread a std::thread that joins when it is destroyed
// or assigned over, the only part of std::jthread Luz relies on (no stop tokens). Both stand-ins
// are compiled everywhere (in luz::fallback), so the desktop tests check the page's code too.
#include <bit>
#include <thread>
#include <type_traits>
#include <utility>

namespace luz {

namespace fallback {

template <class To, class From>
  requires(sizeof(To) == sizeof(From) && std::is_trivially_copyable_v<To> &&
           std::is_trivially_copyable_v<From>)
constexpr To bit_cast(const From& from) noexcept {
  return __builtin_bit_cast(To, from);
}

class jthread {
public:
  jthread() noexcept = default;
  template <class F, class... Args>
    requires(!std::is_same_v<std::remove_cvref_t<F>, jthread>)
  explicit jthread(F&& f, Args&&... args) : thread_(std::forward<F>(f), std::forward<Args>(args)...) {}
  ~jthread() { join_if_running(); }
  jthread(jthread&&) noexcept = default;
  jthread& operator=(jthread&& other) noexcept {
    if (this != &other) {
      join_if_running();
      thread_ = std::move(other.thread_);
    }
    return *this;
  }
  jthread(const jthread&) = delete;
  jthread& operator=(const jthread&) = delete;

  bool joinable() const noexcept { return thread_.joinable(); }
  void join() { thread_.join(); }

private:
  void join_if_running() {
    if (thread_.joinable()) thread_.join();
  }
  std::thread thread_;
};

}  // namespace fallback

#if defined(__cpp_lib_bit_cast)
using std::bit_cast;
#else
using fallback::bit_cast;
#endif

#if defined(__cpp_lib_jthread)
using std::jthread;
#else
using fallback::jthread;
#endif

}  // namespace luz
