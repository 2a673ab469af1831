// The journal writer thread (control/journal_writer.hpp): records reach the
// file in order and synced; a held writer fills the queue and the run stops
// as a fault with the reason, the torch off and the axes at rest on the path,
// and nothing it had queued is lost: the resumed run cuts every segment once.
// A child killed with SIGKILL while its writer works leaves a consistent file.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>

#include "control/journal_writer.hpp"
#include "cycle_rig.hpp"

namespace kerf::test {
namespace {

using control::CutPoint;
using control::Journal;
using control::JournalState;
using control::JournalWriter;

std::string temp_journal(const char* name) {
  return ::testing::TempDir() + "kerf_writer_" + std::to_string(::getpid()) + "_" + name + ".journal";
}

TEST(JournalWriter, WritesInOrderAndSyncsBeforeCatchingUp) {
  const std::string path = temp_journal("order");
  std::string err;
  auto j = Journal::create(path, {42, 100}, err);
  ASSERT_TRUE(j) << err;
  {
    JournalWriter w(*j, 64);
    for (std::uint32_t k = 0; k < 100; ++k) {
      for (int i = 0; i < 3; ++i)
        while (!w.cut_to({k, {static_cast<double>(k), static_cast<double>(i)}})) std::this_thread::yield();
      while (!w.completed(k)) std::this_thread::yield();  // the test's producer waits; the controller faults
    }
    while (!w.cut_to({100 - 1, {1, 2}})) std::this_thread::yield();  // for a done segment: not written
    while (!w.caught_up()) std::this_thread::yield();
    EXPECT_EQ(w.synced_last(), 99);
    EXPECT_FALSE(w.failed());
    w.close();
  }
  JournalState s;
  ASSERT_TRUE(Journal::read(path, s, err)) << err;
  EXPECT_EQ(s.last_completed, 99);
  EXPECT_EQ(s.executed_total, 100u);
  EXPECT_EQ(s.duplicates, 0u);
  EXPECT_FALSE(s.has_cut_to);
  std::remove(path.c_str());
}

TEST(JournalWriter, FullQueueRefusesAndKeepsItsReserveForUrgentRecords) {
  const std::string path = temp_journal("full");
  std::string err;
  auto j = Journal::create(path, {42, 100}, err);
  ASSERT_TRUE(j) << err;
  JournalWriter w(*j, 8);
  w.hold(true);
  int taken = 0;
  while (w.cut_to({0, {1.0 * taken, 0}})) ++taken;
  EXPECT_EQ(taken, 8 - static_cast<int>(JournalWriter::kReserve));
  EXPECT_TRUE(w.completed(0, true));  // urgent: from the reserve
  EXPECT_TRUE(w.cut_to({1, {7, 7}}, true));
  EXPECT_FALSE(w.caught_up());
  w.hold(false);
  while (!w.caught_up()) std::this_thread::yield();
  w.close();
  JournalState s;
  ASSERT_TRUE(Journal::read(path, s, err)) << err;
  EXPECT_EQ(s.last_completed, 0);
  ASSERT_TRUE(s.has_cut_to);
  EXPECT_EQ(s.cut_to.at.x, 7.0);
  std::remove(path.c_str());
}

// A held writer mid-job: the queue fills with the cut points of the cycles
// while the torch is on; the run stops safely, and resuming finishes the job.
TEST(JournalWriter, HeldWriterFaultsTheRunSafelyAndTheResumeCutsEachSegmentOnce) {
  const std::string path = temp_journal("held");
  control::ControllerConfig cfg = quick_controller();
  cfg.journal_queue = 64;
  std::string err;
  std::unique_ptr<Journal> journal;
  {
    CycleRig rig(cfg, nullptr);
    journal = Journal::create(path, rig.job.id(), err);
  }
  ASSERT_TRUE(journal) << err;
  control::RunReport first;
  {
    CycleRig rig(cfg, journal.get());
    rig.ctl->start({});
    bool held = false;
    double held_at = -1;
    rig.run(60.0, {}, [&] {
      if (!held && rig.ctl->report().last_completed >= 5) {
        while (!rig.ctl->journal_writer()->caught_up()) std::this_thread::yield();
        rig.pace_journal = false;
        rig.ctl->journal_writer()->hold(true);
        held = true;
        held_at = rig.t;
      }
      if (held && rig.ctl->state() == control::State::fault && rig.t > held_at + 1.0 &&
          rig.ctl->journal_writer() != nullptr)
        rig.ctl->journal_writer()->hold(false);  // the disk comes back: what was queued is written
    });
    ASSERT_TRUE(rig.ctl->finished()) << "t " << rig.t << " held at " << held_at << " state "
                                     << control::to_string(rig.ctl->state()) << ": " << rig.ctl->report().reason;
    first = rig.ctl->report();
    EXPECT_EQ(first.state, control::State::fault);
    EXPECT_NE(first.reason.find("journal: the writer's queue is full"), std::string::npos) << first.reason;
    EXPECT_FALSE(rig.gpio.torch());
    ASSERT_TRUE(first.torch_off_valid);
    EXPECT_LT(first.reason_t_s, held_at + 0.2) << "the queue took too long to fill";
    const hal::BoardStatus b = rig.plant->truth();
    EXPECT_NE(b.state, hal::BoardState::running);
    EXPECT_LT(first.last_completed, 11);
  }
  // On disk: exactly what the report says.
  EXPECT_EQ(journal->state().last_completed, first.last_completed);
  EXPECT_EQ(journal->state().duplicates, 0u);
  journal.reset();
  JournalState s;
  ASSERT_TRUE(Journal::read(path, s, err)) << err;
  EXPECT_EQ(s.last_completed, first.last_completed);
  EXPECT_EQ(s.has_cut_to, first.has_cut_to);
  if (s.has_cut_to) {
    EXPECT_EQ(distance(s.cut_to.at, first.cut_to.at), 0.0);
  }
  // The resume finishes it: every segment once over both runs.
  CycleRig again(quick_controller(), nullptr);
  journal = Journal::resume(path, again.job.id(), err);
  ASSERT_TRUE(journal) << err;
  CycleRig rig(quick_controller(), journal.get());
  rig.ctl->start(control::resume_point(rig.job, journal->state()));
  ASSERT_TRUE(rig.run(60.0));
  EXPECT_EQ(rig.ctl->report().state, control::State::done) << rig.ctl->report().reason;
  EXPECT_EQ(journal->state().executed_total, 12u);
  EXPECT_EQ(journal->state().duplicates, 0u);
  EXPECT_TRUE(journal->state().finished);
  std::remove(path.c_str());
}

// As tests/control/test_journal_kill.cpp, through the writer: the child
// reports segment k once synced_last() says it is on disk.
TEST(JournalWriterKill, StateAfterSigkillIsAConsistentPrefix) {
  constexpr control::JobId kJob{0xfeedfacecafebeefull, 1000000};
  for (int round = 0; round < 3; ++round) {
    const std::string p = temp_journal("kill");
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      ::close(fds[0]);
      std::string err;
      auto j = Journal::create(p, kJob, err);
      if (!j) ::_exit(2);
      JournalWriter w(*j, 1024);
      std::int64_t told = -1;
      for (std::uint32_t k = 0;; ++k) {
        for (int i = 0; i < 20; ++i)
          while (!w.cut_to({k, {static_cast<double>(k), static_cast<double>(i)}})) ::usleep(50);
        while (!w.completed(k)) ::usleep(50);
        for (std::int64_t s = w.synced_last(); told < s;) {
          const std::uint32_t t = static_cast<std::uint32_t>(++told);
          if (::write(fds[1], &t, sizeof t) != sizeof t) ::_exit(5);
        }
      }
    }
    ::close(fds[1]);
    const std::uint32_t wanted = 3 + 20 * static_cast<std::uint32_t>(round);
    std::int64_t reported = -1;
    std::uint32_t k = 0;
    while (reported + 1 < wanted && ::read(fds[0], &k, sizeof k) == sizeof k) reported = k;
    ASSERT_EQ(reported + 1, wanted) << "the child stopped early";
    ASSERT_EQ(::kill(child, SIGKILL), 0);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    while (::read(fds[0], &k, sizeof k) == sizeof k) reported = k;
    ::close(fds[0]);
    JournalState s;
    std::string err;
    ASSERT_TRUE(Journal::read(p, s, err)) << err;
    EXPECT_GE(s.last_completed, reported) << "a segment reported synced is missing";
    EXPECT_EQ(s.executed_total, static_cast<std::uint64_t>(s.last_completed + 1));
    EXPECT_EQ(s.duplicates, 0u);
    EXPECT_FALSE(s.cut_slot_corrupt);
    if (s.has_cut_to) {  // never ahead of the done records: a point of the next segment
      EXPECT_EQ(s.cut_to.segment, s.last_completed + 1);
      EXPECT_EQ(s.cut_to.at.x, static_cast<double>(s.cut_to.segment));
    }
    std::remove(p.c_str());
  }
}

}  // namespace
}  // namespace kerf::test
