#include "weld/fit_memo.hpp"

#include <cstdint>
#include <cstring>

#include "job/fit_job.hpp"

namespace kerf::weld::detail {

namespace {

// At most this many fits, of parts of at most this many points: about 1 MB
// of points a thread at most, whatever the file's length.
constexpr std::size_t kEntries = 16;
constexpr std::size_t kMaxPoints = 4096;

struct Entry {
  std::vector<Vec2<double>> pts;
  double tol = 0;
  job::Criterion criterion = job::Criterion::band;
  double tie_break = 0;
  std::vector<fit::Piece<double>> pieces;
  bool split = false;
  std::uint64_t used = 0;  // for evicting the least recently used
};

struct Memo {
  std::vector<Entry> entries;
  std::uint64_t clock = 0;
};

bool same_bits(const std::vector<Vec2<double>>& a, const std::vector<Vec2<double>>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec2<double>)) == 0;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

bool fit_memo(const std::vector<Vec2<double>>& pts, double tol, job::Criterion criterion, double tie_break,
              std::vector<fit::Piece<double>>& out, std::string& error, bool& split) {
  thread_local Memo memo;
  for (Entry& e : memo.entries) {
    if (e.criterion == criterion && same_bits(e.tol, tol) && same_bits(e.tie_break, tie_break) &&
        same_bits(e.pts, pts)) {
      e.used = ++memo.clock;
      out = e.pieces;
      split = e.split;
      return true;
    }
  }
  Status status = Status::ok;
  if (!job::fit_job(pts, {}, tol, criterion, out, error, status, job::Numeric::floating, tie_break, &split))
    return false;
  if (pts.size() > kMaxPoints) return true;
  Entry* slot = nullptr;
  if (memo.entries.size() < kEntries) {
    slot = &memo.entries.emplace_back();
  } else {
    slot = &memo.entries.front();
    for (Entry& e : memo.entries)
      if (e.used < slot->used) slot = &e;
  }
  slot->pts = pts;
  slot->tol = tol;
  slot->criterion = criterion;
  slot->tie_break = tie_break;
  slot->pieces = out;
  slot->split = split;
  slot->used = ++memo.clock;
  return true;
}

}  // namespace kerf::weld::detail
