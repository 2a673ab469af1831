// The journal off the real-time cycle: the controller pushes records into a
// single-producer/single-consumer lock-free queue (hal::SpscQueue, fixed
// size, no allocation, no system call) and this writer's thread writes them
// to the Journal in order and syncs them.
//
// - Order: the file is always a prefix of what was pushed. Each batch (all
//   that is queued) the thread appends its `done` records, syncs once
//   (fdatasync), and only then overwrites the cut slot with the batch's last
//   cut point (when it follows the batch's last `done`): a cut slot is never
//   on disk ahead of the `done` records before it.
// - Done means synced: synced_last() is the last completed segment on disk;
//   caught_up() holds once everything pushed is written and synced. The
//   controller ends a run only then (control/controller.hpp).
// - Full: a push is refused (false), never dropped silently; the controller
//   turns that into a fault. kReserve slots are kept for urgent pushes: the
//   refused `done` again and the cut point where the stop turns the torch
//   off, so that the fault loses no record.
// - A record the Journal refuses (disk full, I/O error) stops the writer:
//   failed() and last_error() say why; nothing after it is written.
// - kill -9: records still queued are lost, at most one batch (a sync's time,
//   2 to 5 ms here); the file stays a consistent prefix and a resume re-cuts at
//   most that much of the path. A fault the controller survives loses nothing.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <thread>

#include "control/journal.hpp"
#include "kerf/hal/rings.hpp"

namespace kerf::control {

struct JournalOp {
  enum class Kind : std::uint8_t { completed, cut_to, finished };
  Kind kind = Kind::completed;
  CutPoint cut;  // completed: cut.segment is the segment
};

class JournalWriter {
 public:
  static constexpr std::size_t kDefaultCapacity = 8192;
  static constexpr std::size_t kReserve = 3;

  // Starts the thread. `journal` must outlive the writer and is the thread's
  // until close() (read its state() only after).
  explicit JournalWriter(Journal& journal, std::size_t capacity = kDefaultCapacity);
  ~JournalWriter();
  JournalWriter(const JournalWriter&) = delete;
  JournalWriter& operator=(const JournalWriter&) = delete;

  // The producer (one thread): never blocks, never allocates. False: full.
  bool completed(std::uint32_t segment, bool urgent = false);
  bool cut_to(const CutPoint& p, bool urgent = false);
  bool finished();

  bool caught_up() const { return applied_.load(std::memory_order_acquire) == pushed_; }
  std::int64_t synced_last() const { return synced_last_.load(std::memory_order_acquire); }
  std::size_t queued() const { return q_.size(); }
  std::size_t capacity() const { return q_.capacity(); }
  bool failed() const { return failed_.load(std::memory_order_acquire); }
  const char* last_error() const { return failed() ? error_ : ""; }

  // Writes and syncs whatever is queued, then joins the thread (idempotent).
  void close();
  // Tests: while held the thread takes nothing from the queue.
  void hold(bool on) { hold_.store(on, std::memory_order_release); }

 private:
  bool push(const JournalOp& op, bool urgent);
  void run();
  bool write_batch(std::uint64_t& n);
  void fail();

  Journal& journal_;
  hal::SpscQueue<JournalOp> q_;
  std::uint64_t pushed_ = 0;  // the producer's count
  std::atomic<std::uint64_t> applied_{0};
  std::atomic<std::int64_t> synced_last_;
  std::atomic<bool> failed_{false}, stop_{false}, hold_{false};
  char error_[256] = "";  // the thread's, published by failed_
  std::thread thread_;
};

}  // namespace kerf::control
