// core/std_compat.h: the stand-ins the web page uses for std::bit_cast and std::jthread behave
// as the standard ones the desktop uses.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <limits>
#include <thread>

#include <gtest/gtest.h>

#include "core/std_compat.h"

namespace luz {
namespace {

// The bytes of `from` copied into a To: what bit_cast is defined to give, by memcpy, which every
// standard library the tests are built with has (Emscripten's has no std::bit_cast).
template <class To, class From>
To copied_bits(const From& from) {
  To to;
  std::memcpy(&to, &from, sizeof to);
  return to;
}

TEST(StdCompat, BitCastGivesTheIeeeBitsBothWays) {
  // IEEE 754 single precision: 1 = 0x3f800000, -2 = 0xc0000000, the smallest denormal = 1.
  EXPECT_EQ(fallback::bit_cast<uint32_t>(1.0f), 0x3f800000u);
  EXPECT_EQ(fallback::bit_cast<uint32_t>(-2.0f), 0xc0000000u);
  EXPECT_EQ(fallback::bit_cast<uint32_t>(std::numeric_limits<float>::denorm_min()), 1u);
  EXPECT_EQ(fallback::bit_cast<float>(0x3f800000u), 1.0f);
  for (const float x : {0.0f, -0.0f, 0.1f, 3.0e38f, -std::numeric_limits<float>::denorm_min()})
    EXPECT_EQ(fallback::bit_cast<int32_t>(x), copied_bits<int32_t>(x)) << x;
  static_assert(fallback::bit_cast<uint32_t>(1.0f) == 0x3f800000u, "usable in constant expressions");
}

// The thread's work is done once the jthread is destroyed (it joined), without a join() call.
template <class Thread>
void joins_when_destroyed() {
  std::atomic<bool> done{false};
  {
    Thread worker([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      done = true;
    });
    EXPECT_TRUE(worker.joinable());
  }
  EXPECT_TRUE(done);
}

// Assigning a new thread over a running one waits for the running one.
template <class Thread>
void joins_when_assigned_over() {
  std::atomic<bool> first_done{false}, second_done{false};
  Thread worker([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    first_done = true;
  });
  worker = Thread([&] { second_done = true; });
  EXPECT_TRUE(first_done);
  worker.join();
  EXPECT_TRUE(second_done);
  EXPECT_FALSE(worker.joinable());
}

TEST(StdCompat, JthreadJoinsWhenDestroyed) {
  joins_when_destroyed<fallback::jthread>();
  joins_when_destroyed<jthread>();
}

TEST(StdCompat, JthreadJoinsWhenAssignedOver) {
  joins_when_assigned_over<fallback::jthread>();
  joins_when_assigned_over<jthread>();
}

}  // namespace
}  // namespace luz
