// A controller killed with SIGKILL in the middle of journalling: a child
// process writes completed records and cut_to updates in a loop and reports
// each completed segment through a pipe once completed() has returned; the
// parent kills it after a few and reads the journal. No timing is assumed:
// the kill lands wherever it lands.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>

#include "control/journal.hpp"
#include "journal_fixture.hpp"

namespace {

using namespace kerf::control;

constexpr JobId kJob{0xfeedfacecafebeefull, 1000000};

// The child: never returns. Points on segment k are (k, i) for i = 0, 1, ...
[[noreturn]] void journal_until_killed(const std::string& p, int report_fd) {
  std::string err;
  auto j = Journal::create(p, kJob, err);
  if (j == nullptr) ::_exit(2);
  for (std::uint32_t k = 0;; ++k) {
    for (int i = 0; i < 50; ++i)
      if (!j->cut_to({k, {static_cast<double>(k), static_cast<double>(i)}})) ::_exit(3);
    if (!j->completed(k)) ::_exit(4);
    if (::write(report_fd, &k, sizeof k) != sizeof k) ::_exit(5);
  }
}

using JournalKillTest = TempDir;

TEST_F(JournalKillTest, StateAfterSigkillIsConsistent) {
  for (int round = 0; round < 5; ++round) {
    const std::string p = path("j");
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      ::close(fds[0]);
      journal_until_killed(p, fds[1]);
    }
    ::close(fds[1]);
    // Wait until the child says it has completed a few segments (more each round).
    const std::uint32_t wanted = 3 + 7 * static_cast<std::uint32_t>(round);
    std::int64_t reported = -1;
    std::uint32_t k = 0;
    while (reported + 1 < wanted && ::read(fds[0], &k, sizeof k) == sizeof k) reported = k;
    ASSERT_EQ(reported + 1, wanted) << "the child stopped early";
    ASSERT_EQ(::kill(child, SIGKILL), 0);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << status;
    while (::read(fds[0], &k, sizeof k) == sizeof k) reported = k;  // sent before the kill
    ::close(fds[0]);

    JournalState s;
    std::string err;
    ASSERT_TRUE(Journal::read(p, s, err)) << err;
    // Every reported segment is journalled; at most the one in flight beyond it.
    EXPECT_GE(s.last_completed, reported) << "round " << round;
    EXPECT_LE(s.last_completed, reported + 1) << "round " << round;
    EXPECT_EQ(s.executed_total, static_cast<std::uint64_t>(s.last_completed + 1));
    EXPECT_EQ(s.duplicates, 0u);
    EXPECT_EQ(s.runs, 1u);
    EXPECT_FALSE(s.finished);
    EXPECT_FALSE(s.cut_slot_corrupt);
    if (s.has_cut_to) {  // a point the child wrote for the next segment, never a mix
      EXPECT_EQ(s.cut_to.segment, s.last_completed + 1);
      EXPECT_EQ(s.cut_to.at.x, static_cast<double>(s.cut_to.segment));
      EXPECT_EQ(s.cut_to.at.y, std::floor(s.cut_to.at.y));
      EXPECT_GE(s.cut_to.at.y, 0.0);
      EXPECT_LT(s.cut_to.at.y, 50.0);
    }
    // And the job resumes from there.
    auto j = Journal::resume(p, kJob, err);
    ASSERT_NE(j, nullptr) << err;
    ASSERT_TRUE(j->completed(static_cast<std::uint32_t>(s.last_completed + 1)));
    EXPECT_EQ(j->state().duplicates, 0u);
  }
}

}  // namespace
