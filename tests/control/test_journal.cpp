// The progress journal: round trip, resume checks, torn and corrupt records,
// the cut_to slot, duplicates and totals over runs.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "control/journal.hpp"
#include "control/journal_record.hpp"
#include "journal_fixture.hpp"

namespace {

using namespace kerf::control;
namespace rec = kerf::control::journal_record;

const JobId kJob{0x1a2b3c4d5e6f7081ull, 10};

using JournalTest = TempDir;

std::unique_ptr<Journal> make(const std::string& p, const JobId& job = kJob) {
  std::string err;
  auto j = Journal::create(p, job, err);
  EXPECT_NE(j, nullptr) << err;
  return j;
}

JournalState read_ok(const std::string& p) {
  JournalState s;
  std::string err;
  EXPECT_TRUE(Journal::read(p, s, err)) << err;
  return s;
}

TEST(JournalRecord, Crc32MatchesTheStandardCheckValue) {
  EXPECT_EQ(rec::crc32("123456789", 9), 0xCBF43926u);  // the CRC-32/ISO-HDLC check value
}

TEST(JournalRecord, EncodeDecodeAndRejectAnyFlippedByte) {
  char line[rec::kMaxLine];
  const std::size_t n = rec::encode("done 17", 7, 0, line);
  ASSERT_GT(n, 0u);
  const char* text = nullptr;
  std::size_t len = 0;
  ASSERT_TRUE(rec::decode(line, n, text, len));
  EXPECT_EQ(std::string(text, len), "done 17");
  for (std::size_t i = 0; i < n; ++i) {
    char bad[rec::kMaxLine];
    std::copy(line, line + n, bad);
    bad[i] ^= 0x04;
    EXPECT_FALSE(rec::decode(bad, n, text, len)) << "byte " << i;
  }
  const std::size_t w = rec::encode("cut none", 8, rec::kFixedWidth, line);
  EXPECT_EQ(w, rec::kFixedWidth);
  ASSERT_TRUE(rec::decode(line, w, text, len));
  EXPECT_EQ(std::string(text, len), "cut none");
}

TEST_F(JournalTest, RoundTripIsReadableText) {
  const std::string p = path("job.journal");
  {
    auto j = make(p);
    ASSERT_TRUE(j->completed(0));
    ASSERT_TRUE(j->cut_to({1, {12.345678, -3.25}}));
    ASSERT_TRUE(j->completed(1));
    ASSERT_TRUE(j->cut_to({2, {1.5, 2.5}}));
    EXPECT_EQ(j->state().last_completed, 1);
    EXPECT_TRUE(j->state().has_cut_to);
  }
  const JournalState s = read_ok(p);
  EXPECT_EQ(s.job.hash, kJob.hash);
  EXPECT_EQ(s.job.segments, kJob.segments);
  EXPECT_EQ(s.last_completed, 1);
  ASSERT_TRUE(s.has_cut_to);
  EXPECT_EQ(s.cut_to.segment, 2u);
  EXPECT_DOUBLE_EQ(s.cut_to.at.x, 1.5);
  EXPECT_DOUBLE_EQ(s.cut_to.at.y, 2.5);
  EXPECT_EQ(s.executed_total, 2u);
  EXPECT_EQ(s.duplicates, 0u);
  EXPECT_EQ(s.runs, 1u);
  EXPECT_FALSE(s.finished);
  EXPECT_FALSE(s.torn_tail);
  const std::string text = slurp(p);
  EXPECT_EQ(text.rfind("kerf-journal 1 job=1a2b3c4d5e6f7081 segments=10 ", 0), 0u) << text;
  EXPECT_NE(text.find("\ncut 2 1.500000 2.500000 "), std::string::npos) << text;
  EXPECT_NE(text.find("\nrun 1 #"), std::string::npos) << text;
  EXPECT_NE(text.find("\ndone 1 #"), std::string::npos) << text;
  EXPECT_FALSE(std::filesystem::exists(p + ".tmp"));
}

TEST_F(JournalTest, CreateReplacesAnOldJournal) {
  const std::string p = path("j");
  {
    auto j = make(p);
    ASSERT_TRUE(j->completed(0));
    ASSERT_TRUE(j->finished());
  }
  const JobId other{42, 3};
  make(p, other);
  const JournalState s = read_ok(p);
  EXPECT_EQ(s.job.hash, 42u);
  EXPECT_EQ(s.last_completed, -1);
  EXPECT_FALSE(s.finished);
}

TEST_F(JournalTest, ResumeRefusesAMissingFile) {
  std::string err;
  EXPECT_EQ(Journal::resume(path("none"), kJob, err), nullptr);
  EXPECT_NE(err.find(path("none")), std::string::npos) << err;
  EXPECT_NE(err.find("no journal to resume"), std::string::npos) << err;
}

TEST_F(JournalTest, ResumeRefusesAnotherJob) {
  const std::string p = path("j");
  make(p);
  std::string err;
  EXPECT_EQ(Journal::resume(p, {kJob.hash ^ 1, kJob.segments}, err), nullptr);
  EXPECT_NE(err.find("journal " + p + ": written for another job (hash 1a2b3c4d5e6f7081"),
            std::string::npos)
      << err;
  EXPECT_NE(err.find("this job hash 1a2b3c4d5e6f7080"), std::string::npos) << err;
  err.clear();
  EXPECT_EQ(Journal::resume(p, {kJob.hash, kJob.segments + 1}, err), nullptr);
  EXPECT_NE(err.find("another job"), std::string::npos) << err;
  std::string ok;
  EXPECT_NE(Journal::resume(p, kJob, ok), nullptr) << ok;
}

TEST_F(JournalTest, ResumeRefusesAFinishedJob) {
  const std::string p = path("j");
  {
    auto j = make(p);
    for (std::uint32_t k = 0; k < kJob.segments; ++k) ASSERT_TRUE(j->completed(k));
    ASSERT_TRUE(j->finished());
  }
  EXPECT_TRUE(read_ok(p).finished);
  std::string err;
  EXPECT_EQ(Journal::resume(p, kJob, err), nullptr);
  EXPECT_NE(err.find("finished"), std::string::npos) << err;
}

TEST_F(JournalTest, ResumeRefusesWhileAnotherJournalHoldsTheFile) {
  const std::string p = path("j");
  auto first = make(p);
  std::string err;
  EXPECT_EQ(Journal::resume(p, kJob, err), nullptr);  // flock is per open file, so this is seen
  EXPECT_NE(err.find("in use"), std::string::npos) << err;
  first.reset();
  EXPECT_NE(Journal::resume(p, kJob, err), nullptr) << err;
}

TEST_F(JournalTest, ReadRefusesAFileThatIsNotAJournal) {
  const std::string p = path("j");
  spit(p, "hello\n");
  JournalState s;
  std::string err;
  EXPECT_FALSE(Journal::read(p, s, err));
  EXPECT_NE(err.find("journal " + p + ": line 1: not a kerf journal"), std::string::npos) << err;
}

TEST_F(JournalTest, ExecutedTotalAndRunsAcrossCreateAndResume) {
  const std::string p = path("j");
  {
    auto j = make(p);
    ASSERT_TRUE(j->completed(0));
    ASSERT_TRUE(j->completed(1));
  }
  for (int run = 2; run <= 3; ++run) {
    std::string err;
    auto j = Journal::resume(p, kJob, err);
    ASSERT_NE(j, nullptr) << err;
    EXPECT_EQ(j->state().runs, static_cast<std::uint32_t>(run));
    ASSERT_TRUE(j->completed(static_cast<std::uint32_t>(run)));
  }
  const JournalState s = read_ok(p);
  EXPECT_EQ(s.runs, 3u);
  EXPECT_EQ(s.executed_total, 4u);
  EXPECT_EQ(s.last_completed, 3);
  EXPECT_NE(slurp(p).find("\nrun 3 #"), std::string::npos);
}

TEST_F(JournalTest, DuplicatesAreCountedAndGapsRefused) {
  const std::string p = path("j");
  {
    auto j = make(p);
    ASSERT_TRUE(j->completed(0));
    ASSERT_TRUE(j->completed(1));
    ASSERT_TRUE(j->completed(1));  // the same segment twice: cut twice, so counted
    ASSERT_TRUE(j->completed(0));
    EXPECT_EQ(j->state().duplicates, 2u);
    EXPECT_FALSE(j->completed(3));  // 2 is missing
    EXPECT_NE(std::string(j->last_error()).find("segment 3 completed out of order"),
              std::string::npos)
        << j->last_error();
    EXPECT_FALSE(j->completed(kJob.segments));
  }
  const JournalState s = read_ok(p);
  EXPECT_EQ(s.duplicates, 2u);
  EXPECT_EQ(s.executed_total, 4u);
  EXPECT_EQ(s.last_completed, 1);
}

TEST_F(JournalTest, CutSlotIsOverwrittenInPlace) {
  const std::string p = path("j");
  auto j = make(p);
  ASSERT_TRUE(j->completed(0));
  const auto size = std::filesystem::file_size(p);
  for (int i = 0; i < 100; ++i) ASSERT_TRUE(j->cut_to({1, {i * 0.5, -i * 0.25}}));
  EXPECT_EQ(std::filesystem::file_size(p), size);  // not appended
  JournalState s = read_ok(p);
  ASSERT_TRUE(s.has_cut_to);
  EXPECT_EQ(s.cut_to.segment, 1u);
  EXPECT_DOUBLE_EQ(s.cut_to.at.x, 49.5);
  EXPECT_DOUBLE_EQ(s.cut_to.at.y, -24.75);
  // Once segment 1 is done the slot (still saying segment 1) is stale.
  ASSERT_TRUE(j->completed(1));
  EXPECT_FALSE(j->state().has_cut_to);
  s = read_ok(p);
  EXPECT_FALSE(s.has_cut_to);
  EXPECT_FALSE(s.cut_slot_corrupt);
  EXPECT_FALSE(j->cut_to({2, {std::nan(""), 0.0}}));
}

TEST_F(JournalTest, CorruptCutSlotIsReportedNotTrusted) {
  const std::string p = path("j");
  {
    auto j = make(p);
    ASSERT_TRUE(j->cut_to({0, {3.0, 4.0}}));
  }
  std::string data = slurp(p);
  const std::size_t at = data.find("cut 0 3.000000");
  ASSERT_EQ(at, rec::kSlotOffset);
  data[at + 6] = '9';
  spit(p, data);
  const JournalState s = read_ok(p);
  EXPECT_FALSE(s.has_cut_to);
  EXPECT_TRUE(s.cut_slot_corrupt);
  EXPECT_FALSE(s.torn_tail);
}

// A journal with done 0..4 written in one run.
std::string five_done(const std::string& p) {
  auto j = make(p);
  for (std::uint32_t k = 0; k < 5; ++k) EXPECT_TRUE(j->completed(k));
  EXPECT_TRUE(j->cut_to({5, {1.0, 2.0}}));
  return TempDir::slurp(p);
}

TEST_F(JournalTest, TruncatedMidRecordEndsReadingAtTheLastWholeRecord) {
  const std::string p = path("j");
  const std::string data = five_done(p);
  const std::size_t last = data.rfind("done 4");
  ASSERT_NE(last, std::string::npos);
  for (std::size_t cut = last + 1; cut < data.size(); ++cut) {  // every tear inside `done 4`
    spit(p, data.substr(0, cut));
    const JournalState s = read_ok(p);
    EXPECT_TRUE(s.torn_tail) << cut;
    EXPECT_EQ(s.last_completed, 3) << "segment 4 is not known done: it is cut again";
    EXPECT_EQ(s.executed_total, 4u);
    EXPECT_FALSE(s.has_cut_to) << "the slot says segment 5, so it says nothing about 4";
  }
  spit(p, data.substr(0, last));  // cut exactly at a record boundary: nothing torn
  EXPECT_FALSE(read_ok(p).torn_tail);
}

TEST_F(JournalTest, CorruptByteEndsReadingAndEverythingAfterIsIgnored) {
  const std::string p = path("j");
  std::string data = five_done(p);
  const std::size_t at = data.find("done 2");
  ASSERT_NE(at, std::string::npos);
  data[at + 5] = '7';  // "done 7" with done 2's checksum
  spit(p, data);
  const JournalState s = read_ok(p);
  EXPECT_TRUE(s.torn_tail);
  EXPECT_EQ(s.last_completed, 1);
  EXPECT_EQ(s.executed_total, 2u);
}

TEST_F(JournalTest, ResumeCutsTheTornTailSoNewRecordsAreRead) {
  const std::string p = path("j");
  const std::string data = five_done(p);
  spit(p, data.substr(0, data.size() - 3));
  {
    std::string err;
    auto j = Journal::resume(p, kJob, err);
    ASSERT_NE(j, nullptr) << err;
    EXPECT_TRUE(j->state().torn_tail);  // reported to the caller
    EXPECT_EQ(j->state().last_completed, 3);
    ASSERT_TRUE(j->completed(4));  // re-run once
    ASSERT_TRUE(j->completed(5));
  }
  const JournalState s = read_ok(p);
  EXPECT_FALSE(s.torn_tail);
  EXPECT_EQ(s.last_completed, 5);
  EXPECT_EQ(s.runs, 2u);
  EXPECT_EQ(s.executed_total, 6u);
  EXPECT_EQ(s.duplicates, 0u);
}

TEST_F(JournalTest, ValidChecksumButImpossibleRecordIsAnErrorWithItsLine) {
  const std::string p = path("j");
  make(p);
  char line[rec::kMaxLine];
  const std::size_t n = rec::encode("done 7", 6, 0, line);
  spit(p, slurp(p) + std::string(line, n));
  JournalState s;
  std::string err;
  EXPECT_FALSE(Journal::read(p, s, err));
  EXPECT_NE(err.find("journal " + p + ": line 4: segment 7 done out of order"), std::string::npos)
      << err;
}

}  // namespace
