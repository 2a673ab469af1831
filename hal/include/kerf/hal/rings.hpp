// Fixed-size rings for the real-time cycle: the storage is allocated when
// they are made, never after, so pushing from the cycle allocates nothing.
//
// - SpscQueue<T>: one producer thread, one consumer thread, lock-free (two
//   atomic indices, acquire/release). try_push() refuses when full: the
//   producer decides what full means (a fault for the journal, a counted drop
//   for a trace sink). `reserve` slots can be kept for urgent pushes.
// - HistoryRing<T>: the last `capacity` items, oldest overwritten, for one
//   thread (the caller locks). copy() returns them oldest first.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace kerf::hal {

template <class T>
class SpscQueue {
 public:
  explicit SpscQueue(std::size_t capacity) : slots_(capacity + 1) {}
  SpscQueue(const SpscQueue&) = delete;
  SpscQueue& operator=(const SpscQueue&) = delete;

  std::size_t capacity() const { return slots_.size() - 1; }
  // Producer: false when fewer than `keep` + 1 slots are free (nothing pushed).
  bool try_push(const T& v, std::size_t keep = 0) {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);
    const std::size_t head = head_.load(std::memory_order_acquire);
    if (free_slots(head, tail) <= keep) return false;
    slots_[tail] = v;
    tail_.store(next(tail), std::memory_order_release);
    return true;
  }
  // Consumer: false when empty.
  bool try_pop(T& v) {
    const std::size_t head = head_.load(std::memory_order_relaxed);
    if (head == tail_.load(std::memory_order_acquire)) return false;
    v = slots_[head];
    head_.store(next(head), std::memory_order_release);
    return true;
  }
  // Either side: a snapshot (exact on the side that is not moving).
  std::size_t size() const {
    const std::size_t head = head_.load(std::memory_order_acquire);
    const std::size_t tail = tail_.load(std::memory_order_acquire);
    return tail >= head ? tail - head : tail + slots_.size() - head;
  }
  bool empty() const { return size() == 0; }

 private:
  std::size_t next(std::size_t i) const { return i + 1 == slots_.size() ? 0 : i + 1; }
  std::size_t free_slots(std::size_t head, std::size_t tail) const {
    return capacity() - (tail >= head ? tail - head : tail + slots_.size() - head);
  }
  std::vector<T> slots_;  // one slot stays empty: head == tail means empty
  alignas(64) std::atomic<std::size_t> head_{0};
  alignas(64) std::atomic<std::size_t> tail_{0};
};

template <class T>
class HistoryRing {
 public:
  explicit HistoryRing(std::size_t capacity) : items_(capacity) {}
  std::size_t capacity() const { return items_.size(); }
  std::size_t size() const { return total_ < items_.size() ? static_cast<std::size_t>(total_) : items_.size(); }
  std::uint64_t total() const { return total_; }      // pushed since made
  std::uint64_t overwritten() const { return total_ - size(); }
  void push(const T& v) {
    if (items_.empty()) {
      ++total_;
      return;
    }
    items_[static_cast<std::size_t>(total_ % items_.size())] = v;
    ++total_;
  }
  std::vector<T> copy() const {
    std::vector<T> out;
    out.reserve(size());
    for (std::uint64_t i = total_ - size(); i < total_; ++i) out.push_back(items_[static_cast<std::size_t>(i % items_.size())]);
    return out;
  }

 private:
  std::vector<T> items_;
  std::uint64_t total_ = 0;
};

}  // namespace kerf::hal
