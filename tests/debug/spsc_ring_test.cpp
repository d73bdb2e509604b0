// The ring between the control loop and the debug server's thread: order, bounds, and its cached
// view of the other side's index, alone and with the two sides on two threads.
#include <gtest/gtest.h>

#include <thread>

#include "robot/debug/spsc_ring.hpp"

namespace stride::test {
namespace {

using debug::SpscRing;

TEST(SpscRing, KeepsOrderAndRefusesWhenFullOrEmpty) {
  SpscRing<int, 4> ring;
  int out = -1;
  EXPECT_FALSE(ring.try_pop(out));
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(ring.try_push(i));
  int extra = 99;
  EXPECT_FALSE(ring.try_push(extra));
  EXPECT_EQ(extra, 99);  // a refused push leaves the value with the caller
  EXPECT_FALSE(ring.has_room(1));
  for (int i = 0; i < 2; ++i) {
    ASSERT_TRUE(ring.try_pop(out));
    EXPECT_EQ(out, i);
  }
  // The producer saw a full ring last; asked for room it looks again and finds the two freed.
  EXPECT_TRUE(ring.has_room(2));
  EXPECT_FALSE(ring.has_room(3));
  EXPECT_TRUE(ring.try_push(4));
  EXPECT_TRUE(ring.try_push(5));
  EXPECT_FALSE(ring.try_push(extra));
  for (int want = 2; want <= 5; ++want) {
    ASSERT_TRUE(ring.try_pop(out));
    EXPECT_EQ(out, want);
  }
  EXPECT_FALSE(ring.try_pop(out));
  EXPECT_EQ(ring.size(), 0u);
}

TEST(SpscRing, TwoThreadsPassEveryItemOnceInOrder) {
  constexpr int kItems = 50000;
  SpscRing<int, 8> ring;
  std::thread producer([&] {
    for (int i = 0; i < kItems;)
      if (ring.try_push(i))
        ++i;
      else
        std::this_thread::yield();  // a CI core may be shared by both threads
  });
  long long sum = 0;
  int next = 0;
  bool ordered = true;
  for (int got = 0; got < kItems;) {
    int v = 0;
    if (!ring.try_pop(v)) {
      std::this_thread::yield();
      continue;
    }
    ordered &= v == next++;
    sum += v;
    ++got;
  }
  producer.join();
  EXPECT_TRUE(ordered);
  EXPECT_EQ(sum, static_cast<long long>(kItems) * (kItems - 1) / 2);
  int v = 0;
  EXPECT_FALSE(ring.try_pop(v));
}

}  // namespace
}  // namespace stride::test
