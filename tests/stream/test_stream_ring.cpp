// The bounded hand-off between the job's producer thread and the controller.
#include <gtest/gtest.h>

#include <cstdint>
#include <thread>

#include "control/stream_ring.hpp"

namespace {

using kerf::control::StreamRing;

TEST(StreamRing, RefusesWhenFullAndWhenEmpty) {
  StreamRing<int, 4> r;
  int v = -1;
  EXPECT_FALSE(r.try_pop(v));
  for (int k = 0; k < 4; ++k) EXPECT_TRUE(r.try_push(k));
  EXPECT_FALSE(r.try_push(99));  // full: refused, nothing overwritten
  EXPECT_EQ(r.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    ASSERT_TRUE(r.try_pop(v));
    EXPECT_EQ(v, k);
  }
  EXPECT_FALSE(r.try_pop(v));
  // Around the end of the storage, many times.
  for (int k = 0; k < 1000; ++k) {
    ASSERT_TRUE(r.try_push(k));
    ASSERT_TRUE(r.try_push(k + 1));
    ASSERT_TRUE(r.try_pop(v));
    EXPECT_EQ(v, k);
    ASSERT_TRUE(r.try_pop(v));
    EXPECT_EQ(v, k + 1);
  }
}

// Two threads: every item arrives once, in order; close() after the last.
TEST(StreamRing, TwoThreadsKeepOrder) {
  constexpr std::uint64_t kItems = 300000;
  static StreamRing<std::uint64_t, 64> r;
  std::thread producer([] {
    for (std::uint64_t k = 0; k < kItems; ++k)
      while (!r.try_push(k)) std::this_thread::yield();
    r.close();
  });
  std::uint64_t want = 0, v = 0;
  for (;;) {
    if (r.try_pop(v)) {
      ASSERT_EQ(v, want);
      ++want;
    } else if (r.closed() && r.size() == 0) {
      break;
    } else {
      std::this_thread::yield();
    }
  }
  producer.join();
  EXPECT_EQ(want, kItems);
}

}  // namespace
