// cut_to() is called every control cycle: it must not allocate. Its own
// binary, because it replaces the global operator new to count.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "control/journal.hpp"
#include "journal_fixture.hpp"

namespace {
std::atomic<long> g_allocations{0};
}

void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace {

using namespace kerf::control;
using JournalAllocTest = TempDir;

TEST_F(JournalAllocTest, CutToDoesNotAllocateEvenOnError) {
  std::string err;
  const std::string p = path("a-rather-long-journal-file-name-to-defeat-small-strings.journal");
  auto j = Journal::create(p, {7, 100}, err);
  ASSERT_NE(j, nullptr) << err;
  const long before = g_allocations.load();
  for (int i = 0; i < 1000; ++i) ASSERT_TRUE(j->cut_to({0, {i * 0.001, 123456.789}}));
  EXPECT_FALSE(j->cut_to({0, {1e300, 0.0}}));  // too large for the slot: an error, no allocation
  const long after = g_allocations.load();
  EXPECT_EQ(after, before);
  EXPECT_NE(std::string(j->last_error()).find("cut_to"), std::string::npos);
}

TEST_F(JournalAllocTest, CountingWorks) {  // the check above could fail
  const long before = g_allocations.load();
  auto* s = new std::string(100, 'x');
  delete s;
  EXPECT_GT(g_allocations.load(), before);
}

}  // namespace
