// A bounded single-producer/single-consumer hand-off: the job's producer (a
// non-real-time thread that reads and fits) pushes, the controller's side
// pops. Fixed capacity, storage inside the object: neither side allocates,
// neither side waits (a full ring refuses the push, an empty one the pop;
// the producer decides how to wait, the consumer never does).
#pragma once

#include <atomic>
#include <cstddef>

namespace kerf::control {

template <class T, std::size_t N>
class StreamRing {
  static_assert(N >= 2 && (N & (N - 1)) == 0, "a power of two");

 public:
  static constexpr std::size_t kCapacity = N;

  // Producer only. False when full (nothing is written).
  bool try_push(const T& v) {
    const std::size_t t = tail_.load(std::memory_order_relaxed);
    if (t - head_.load(std::memory_order_acquire) == N) return false;
    items_[t & (N - 1)] = v;
    tail_.store(t + 1, std::memory_order_release);
    return true;
  }
  // Consumer only. False when empty.
  bool try_pop(T& out) {
    const std::size_t h = head_.load(std::memory_order_relaxed);
    if (h == tail_.load(std::memory_order_acquire)) return false;
    out = items_[h & (N - 1)];
    head_.store(h + 1, std::memory_order_release);
    return true;
  }
  // Either side; exact only when the other side is idle.
  std::size_t size() const { return tail_.load(std::memory_order_acquire) - head_.load(std::memory_order_acquire); }
  // Producer: no more items will come. Consumer: it ended once empty.
  void close() { closed_.store(true, std::memory_order_release); }
  bool closed() const { return closed_.load(std::memory_order_acquire); }

 private:
  alignas(64) std::atomic<std::size_t> head_{0};  // next to pop
  alignas(64) std::atomic<std::size_t> tail_{0};  // next to push
  std::atomic<bool> closed_{false};
  T items_[N]{};
};

}  // namespace kerf::control
