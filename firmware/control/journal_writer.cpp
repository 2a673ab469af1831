#include "control/journal_writer.hpp"

#include <pthread.h>
#include <sched.h>

#include <chrono>
#include <cstdio>

namespace kerf::control {

namespace {
// The thread polls: the producer makes no system call to wake it. An empty
// queue costs a wake-up every kIdle; a record waits at most that long.
constexpr std::chrono::microseconds kIdle{200};
constexpr std::size_t kMaxBatch = 1 << 16;  // records between two syncs, at most
}  // namespace

JournalWriter::JournalWriter(Journal& journal, std::size_t capacity)
    : journal_(journal), q_(capacity < kReserve + 1 ? kReserve + 1 : capacity),
      synced_last_(journal.state().last_completed) {
  thread_ = std::thread([this] { run(); });
}

JournalWriter::~JournalWriter() { close(); }

bool JournalWriter::push(const JournalOp& op, bool urgent) {
  if (!q_.try_push(op, urgent ? 0 : kReserve)) return false;
  ++pushed_;
  return true;
}

bool JournalWriter::completed(std::uint32_t segment, bool urgent) {
  JournalOp op;
  op.kind = JournalOp::Kind::completed;
  op.cut.segment = segment;
  return push(op, urgent);
}

bool JournalWriter::cut_to(const CutPoint& p, bool urgent) {
  JournalOp op;
  op.kind = JournalOp::Kind::cut_to;
  op.cut = p;
  return push(op, urgent);
}

bool JournalWriter::finished() {
  JournalOp op;
  op.kind = JournalOp::Kind::finished;
  return push(op, false);
}

void JournalWriter::close() {
  if (!thread_.joinable()) return;
  hold_.store(false, std::memory_order_release);
  stop_.store(true, std::memory_order_release);
  thread_.join();
}

void JournalWriter::fail() {
  std::snprintf(error_, sizeof error_, "%s", journal_.last_error());
  failed_.store(true, std::memory_order_release);
}

void JournalWriter::run() {
  // Not real-time: a thread started from a SCHED_FIFO one inherits its policy.
  sched_param sp{};
  pthread_setschedparam(pthread_self(), SCHED_OTHER, &sp);
  for (;;) {
    const bool stopping = stop_.load(std::memory_order_acquire);
    if (hold_.load(std::memory_order_acquire) || failed() || q_.empty()) {
      // Stopping: once not held, stop_ was set after the last push, so an
      // empty queue here is empty for good.
      if (stopping && (failed() || q_.empty())) return;
      std::this_thread::sleep_for(kIdle);
      continue;
    }
    std::uint64_t n = 0;
    if (!write_batch(n)) {
      fail();
      continue;
    }
    applied_.fetch_add(n, std::memory_order_release);
  }
}

// Everything queued (up to kMaxBatch): the `done` records appended, one sync,
// then the last cut point if it follows the last `done`.
bool JournalWriter::write_batch(std::uint64_t& n) {
  bool appended = false, cut = false, finish = false;
  CutPoint last_cut;
  JournalOp op;
  while (n < kMaxBatch && q_.try_pop(op)) {
    ++n;
    switch (op.kind) {
      case JournalOp::Kind::completed:
        if (!journal_.completed(op.cut.segment, false)) return false;
        appended = true;
        cut = false;
        break;
      case JournalOp::Kind::cut_to:
        last_cut = op.cut;
        cut = true;
        break;
      case JournalOp::Kind::finished: finish = true; break;
    }
  }
  if (appended && !journal_.sync()) return false;
  synced_last_.store(journal_.state().last_completed, std::memory_order_release);
  if (cut && !journal_.cut_to(last_cut)) return false;
  if (finish && !journal_.finished()) return false;  // appended and synced
  return true;
}

}  // namespace kerf::control
