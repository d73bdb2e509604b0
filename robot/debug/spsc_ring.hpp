#pragma once
// A bounded single-producer single-consumer queue: the only way the control loop and the debug
// server thread hand things to each other. Neither side ever waits: a full ring refuses a push
// (the caller counts or answers the loss), an empty ring refuses a pop.
#include <array>
#include <atomic>
#include <cstddef>
#include <utility>

namespace stride::debug {

template <class T, std::size_t N>
class SpscRing {
  static_assert(N >= 2 && (N & (N - 1)) == 0, "capacity must be a power of two");

 public:
  // Producer thread only. On false `v` is unchanged.
  bool try_push(T& v) {
    const std::size_t head = head_.load(std::memory_order_relaxed);
    // The consumer's index is read (a line from the other core) only when the ring looks full.
    if (head - seen_tail_ == N && head - (seen_tail_ = tail_.load(std::memory_order_acquire)) == N)
      return false;
    items_[head & (N - 1)] = std::move(v);
    head_.store(head + 1, std::memory_order_release);
    return true;
  }
  bool try_push(T&& v) { return try_push(v); }

  // Consumer thread only.
  bool try_pop(T& out) {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);
    // The producer's index is read only when the items seen before are used up.
    if (seen_head_ == tail && (seen_head_ = head_.load(std::memory_order_acquire)) == tail)
      return false;
    out = std::move(items_[tail & (N - 1)]);
    tail_.store(tail + 1, std::memory_order_release);
    return true;
  }

  // Either thread; exact only when the other side is idle.
  std::size_t size() const {
    return head_.load(std::memory_order_acquire) - tail_.load(std::memory_order_acquire);
  }
  // Producer thread only: can `n` more items surely be pushed? (Reads the consumer's index only
  // when the last look left too little room.)
  bool has_room(std::size_t n) {
    const std::size_t head = head_.load(std::memory_order_relaxed);
    if (N - (head - seen_tail_) < n) seen_tail_ = tail_.load(std::memory_order_acquire);
    return N - (head - seen_tail_) >= n;
  }
  static constexpr std::size_t capacity() { return N; }

 private:
  std::array<T, N> items_{};
  alignas(64) std::atomic<std::size_t> head_{0};  // next slot to write
  std::size_t seen_tail_ = 0;                     // producer's last look at tail_
  alignas(64) std::atomic<std::size_t> tail_{0};  // next slot to read
  std::size_t seen_head_ = 0;                     // consumer's last look at head_
};

}  // namespace stride::debug
