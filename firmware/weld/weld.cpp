#include "weld/weld.hpp"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <exception>
#include <optional>
#include <thread>
#include <vector>

#include "weld/weld_plan.hpp"
#include "io/prefault.hpp"

namespace kerf::weld {

namespace {

using detail::P;
using detail::PartPlan;
using detail::Planned;
using detail::Run;
using detail::Written;

// Inserts "G1 " after a leading N word (or at the start): a line that relied
// on the modal G1 which a written arc has replaced.
std::string with_g1(const job::GBlock& b) {
  if (!b.words.empty() && b.words.front().letter == 'N') {
    const std::size_t at = b.words.front().pos + b.words.front().len;
    std::string s(b.text.substr(0, at));
    s += " G1";
    s += b.text.substr(at);
    return s;
  }
  const std::size_t at = b.text.find_first_not_of(" \t");
  std::string s(b.text.substr(0, at));
  s += "G1 ";
  s += b.text.substr(at);
  return s;
}

std::string_view word_text(const job::GBlock& b, char letter) {
  for (const job::GWord& w : b.words)
    if (w.letter == letter) return b.text.substr(w.pos, w.len);
  return {};
}

}  // namespace

namespace detail {

class Emitter {
 public:
  explicit Emitter(std::string& out) : out_(out) {}

  void verbatim(const job::GBlock& b) {
    if (b.moves && b.motion_word) arc_modal_ = false;
    if (b.moves && !b.motion_word && arc_modal_) out_ += with_g1(b);
    else out_ += b.text;
    out_ += b.end;
  }
  void written(std::string_view text, bool arc, std::string_view end) {
    out_ += text;
    out_ += end;
    arc_modal_ = arc;
  }

 private:
  std::string& out_;
  bool arc_modal_ = false;  // the last move written was a G2/G3 that replaced G1 lines
};

// Writes the input lines and the plans, in file order; keeps the stats.
struct Writer {
  const job::GcodeFile* g = nullptr;  // the part of the file being written
  const WeldOptions& opts;
  WeldStats& stats;
  Emitter emit;
  // Where the machine is minus where the input says, after the moves written
  // so far: nonzero only when --decimals rounds the input's own end points.
  P offset{};

  // Writes an input line as it is.
  void pass(const job::GBlock& b) {
    emit.verbatim(b);
    if (!b.moves && b.unknown.empty() && word_text(b, 'X').empty() && word_text(b, 'Y').empty()) return;
    if (b.moves) ++stats.output_moves;
    if (!word_text(b, 'X').empty() && !b.relative) offset.x = 0;
    if (!word_text(b, 'Y').empty() && !b.relative) offset.y = 0;
    if (!b.unknown.empty()) offset = {};  // homing, offsets: the input's own coordinates again
  }

  // Writes pl, welded as `pieces` (planned from `offset`), ending at `end`.
  void write(const job::GPolyline& pl, const Run& r, const std::vector<Planned>& pieces, P end) {
    ++stats.polylines;
    offset = end - r.pts.back();
    std::size_t next_block = pl.first_block;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      const Planned& p = pieces[k];
      const Written& w = p.written;
      const std::size_t block = pl.point_block[r.from_index[p.piece.last]];
      const bool last_piece = k + 1 == pieces.size();
      const std::size_t end_block = last_piece ? pl.last_block : block;
      if (p.keep) {
        for (std::size_t i = next_block; i <= end_block; ++i) {
          emit.verbatim(g->blocks[i]);
          if (g->blocks[i].moves) ++stats.output_moves;
        }  // its X/Y words are the input's: offset is zero after it (resolve)
        next_block = end_block + 1;
        continue;
      }
      stats.max_deviation_mm = std::max(stats.max_deviation_mm, w.deviation * r.unit);
      const job::GBlock& eb = g->blocks[block];
      std::string line;
      if (const std::string_view n = word_text(eb, 'N'); !n.empty()) {
        line = n;
        line += ' ';
      }
      line += w.text;
      if (k == 0)
        if (const std::string_view f = word_text(g->blocks[pl.first_block], 'F'); !f.empty()) {
          line += ' ';
          line += f;
        }
      for (const std::string_view c : eb.comments) {
        line += ' ';
        line += c;
      }
      const bool arc = p.piece.segment.is_arc();
      emit.written(line, arc, eb.end);
      ++stats.output_moves;
      if (arc) ++stats.arcs;
      // The comments of the replaced lines stay, in order, after the piece.
      for (std::size_t i = next_block; i <= end_block; ++i) {
        const job::GBlock& b = g->blocks[i];
        if (&b == &eb) continue;
        if (b.only_comment()) {
          emit.verbatim(b);
        } else if (!b.comments.empty()) {
          std::string c;
          for (const std::string_view t : b.comments) {
            if (!c.empty()) c += ' ';
            c += t;
          }
          emit.written(c, arc, b.end);
        }
      }
      next_block = end_block + 1;
    }
  }
};

}  // namespace detail

namespace {

bool same_point(P a, P b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Runs fn(i) for i in [0, n) on `threads` threads, each taking the next i.
template <class Fn>
void parallel_for(std::size_t n, unsigned threads, const Fn& fn) {
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t i = next.fetch_add(1); i < n; i = next.fetch_add(1)) fn(i);
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
}

// Every polyline prepared (on all the threads), then the plans of the
// parts of at least kPooledPoints points, made by `threads - 1` workers and
// the writer, each taking the next part in file order: the writer takes one
// while the part it is to write next is not ready (it sleeps only when
// every part is taken), so that no more threads run than there are cores.
// It plans the small parts itself, when it writes them (a hand-over costs
// more than their fit: octocat's 24k single-line polylines took 9 times
// longer through the pool). A pooled part's plan assumes the machine
// starts at the part's first input point (the rule, unless --decimals
// rounds the input): the writer plans it again when the machine is
// elsewhere.
class PlanPool {
 public:
  static constexpr std::size_t kPooledPoints = 32;

  // Plans the first `polylines` polylines of g.
  PlanPool(const job::GcodeFile& g, std::size_t polylines, const WeldOptions& opts, int decimals,
           unsigned threads)
      : opts_(opts), decimals_(decimals), runs_(polylines) {
    parallel_for(runs_.size(), threads,
                 [&](std::size_t p) { detail::prepare(g.polylines[p], opts, decimals, runs_[p]); });
    first_part_.reserve(runs_.size());
    for (std::size_t p = 0; p < runs_.size(); ++p) {
      first_part_.push_back(task_of_.size());
      for (std::size_t j = 0; j < runs_[p].parts(); ++j) {
        const bool pooled = runs_[p].cuts[j + 1] - runs_[p].cuts[j] + 1 >= kPooledPoints;
        task_of_.push_back(pooled ? tasks_.size() : kNone);
        if (pooled) tasks_.push_back({p, j});
      }
    }
    plans_.resize(tasks_.size());
    ready_ = std::vector<std::atomic<bool>>(tasks_.size());
    workers_.reserve(threads);
    for (unsigned t = 1; t < threads && !tasks_.empty(); ++t)  // and the writer
      workers_.emplace_back([this] {
        while (!stop_ && take()) {
        }
      });
  }
  PlanPool(const PlanPool&) = delete;
  PlanPool& operator=(const PlanPool&) = delete;
  ~PlanPool() {
    stop_ = true;  // the workers finish the part they plan, then take no other
    for (std::thread& t : workers_) t.join();
  }

  // Polyline p, prepared; the caller may free it once its parts are ready.
  Run& run(std::size_t p) { return runs_[p]; }

  // The plan of part j of polyline p, once made (the caller plans other
  // parts meanwhile), and the caller's from then; null when the part is the
  // caller's to plan.
  PartPlan* wait(std::size_t p, std::size_t j) {
    const std::size_t t = task_of_[first_part_[p] + j];
    if (t == kNone) return nullptr;
    while (!ready_[t].load(std::memory_order_acquire))
      if (!take()) ready_[t].wait(false, std::memory_order_acquire);  // the part is being planned
    return &plans_[t];
  }

 private:
  static constexpr std::size_t kNone = ~std::size_t{0};
  struct Task {
    std::size_t polyline, part;
  };

  // Plans the next part no thread has taken; false when there is none.
  bool take() {
    const std::size_t t = next_.fetch_add(1);
    if (t >= tasks_.size()) return false;
    const Run& r = runs_[tasks_[t].polyline];
    try {
      detail::plan_part(r, tasks_[t].part, r.part_start(tasks_[t].part), opts_, decimals_, plans_[t]);
    } catch (...) {
      plans_[t].exception = std::current_exception();
    }
    ready_[t].store(true, std::memory_order_release);  // publishes plans_[t]
    ready_[t].notify_one();                            // only the writer waits
    return true;
  }

  const WeldOptions& opts_;
  const int decimals_;
  std::vector<Run> runs_;  // built before the workers start; runs_[p] freed by the writer after its parts
  std::vector<std::size_t> first_part_;  // polyline p's first part in task_of_
  std::vector<std::size_t> task_of_;     // each part's task, or kNone
  std::vector<Task> tasks_;
  std::vector<PartPlan> plans_;  // plans_[t]: written by the worker that took t, then the writer's
  std::vector<std::atomic<bool>> ready_;
  std::atomic<std::size_t> next_{0};
  std::atomic<bool> stop_{false};
  std::vector<std::thread> workers_;  // last: started once the rest is built
};

}  // namespace

// Each step of a tie-break is a whole search: at the fitters' own precision
// it was 90% of a weld. The band's pieces are inside the band of the fit tol
// without it. The vertex criterion's pieces pass the band check after
// rounding more often when they hug the points, and 1e-3 keeps the corpus's
// counts (tests/gcode WeldCounts); coarser (1e-2) wrote more moves.
double tie_break_for(job::Criterion criterion) { return criterion == job::Criterion::band ? 0.1 : 1e-3; }

unsigned weld_threads(int requested) {
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  return requested <= 0 ? cores : std::min(cores, static_cast<unsigned>(requested));
}

Welder::Welder(const WeldOptions& opts, int decimals, WeldStats& stats, std::string& out)
    : opts_(opts), stats_(stats), writer_(std::make_unique<detail::Writer>(detail::Writer{nullptr, opts, stats, detail::Emitter(out), {}})) {
  stats_.decimals = decimals;
}

Welder::~Welder() = default;

bool Welder::add(const job::GcodeFile& g, std::size_t end, std::string& error) {
  detail::Writer& w = *writer_;
  w.g = &g;
  std::size_t polylines = 0;
  while (polylines < g.polylines.size() && g.polylines[polylines].last_block < end) ++polylines;
  const unsigned threads = polylines == 0 ? 1 : weld_threads(opts_.threads);
  std::optional<PlanPool> pool;
  if (threads > 1) pool.emplace(g, polylines, opts_, stats_.decimals, threads);
  Run local;
  PartPlan part;
  std::vector<Planned> pieces;
  std::size_t next = 0;
  for (std::size_t p = 0; p < polylines; ++p) {
    const job::GPolyline& pl = g.polylines[p];
    for (; next < pl.first_block; ++next) w.pass(g.blocks[next]);
    next = pl.last_block + 1;
    Run& r = pool ? pool->run(p) : local;
    if (!pool) {
      r = Run{};
      detail::prepare(pl, opts_, stats_.decimals, r);
    }
    if (!r.welded) {
      for (std::size_t i = pl.first_block; i <= pl.last_block; ++i) w.pass(g.blocks[i]);
      continue;
    }
    P from = r.pts.front() + w.offset;
    pieces.clear();
    for (std::size_t j = 0; j < r.parts(); ++j) {
      PartPlan* made = pool ? pool->wait(p, j) : nullptr;
      if (made) {
        if (made->exception) std::rethrow_exception(made->exception);
        if (!same_point(made->from_in, from)) detail::plan_part(r, j, from, opts_, stats_.decimals, *made);
      } else {
        made = &part;
        detail::plan_part(r, j, from, opts_, stats_.decimals, part);
      }
      if (!made->ok) {
        error = g.file + ":" + std::to_string(g.blocks[pl.first_block].line) + ": " + made->error;
        return false;
      }
      stats_.kept_pieces += made->kept;
      if (opts_.progress)
        opts_.progress(g.blocks[pl.point_block[r.from_index[r.kept_index[r.cuts[j + 1]]]]].line);
      pieces.insert(pieces.end(), made->pieces.begin(), made->pieces.end());
      from = made->from_out;
      *made = PartPlan{};  // taken: its memory is free again
    }
    w.write(pl, r, pieces, from);
    r = Run{};
  }
  for (; next < end; ++next) w.pass(g.blocks[next]);
  for (std::size_t i = 0; i < end; ++i) stats_.input_moves += g.blocks[i].moves ? 1 : 0;
  return true;
}

bool weld_gcode(const job::GcodeFile& g, const WeldOptions& opts, std::string& out,
                WeldStats& stats, std::string& error) {
  stats = WeldStats{};
  out.clear();
  std::size_t bytes = 0;
  for (const job::GBlock& b : g.blocks) bytes += b.text.size() + b.end.size();
  out.reserve(bytes + bytes / 8);  // arcs shorten the text; a "G1 " added after one lengthens it
  io::prefault(out.data(), bytes);
  Welder welder(opts, opts.decimals >= 0 ? opts.decimals : std::max<int>(3, static_cast<int>(g.decimals)),
                stats, out);
  return welder.add(g, g.blocks.size(), error);
}

}  // namespace kerf::weld
