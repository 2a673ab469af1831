#include "cli/weld.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <optional>
#include <thread>
#include <vector>

#include "cli/fit_job.hpp"
#include "io/prefault.hpp"
#include "kerf/geom/segment.hpp"

namespace kerf::cli {

namespace {

using P = Vec2<double>;

std::string format_number(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s = buf;
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

double rounded(double v, int decimals) { return std::strtod(format_number(v, decimals).c_str(), nullptr); }

// max(dev, distance from q to the polyline pts[a..b] + widen), exactly. The
// scan starts at segment `near` (the last sample's nearest: the samples walk
// along the polyline) and goes outwards; it stops once q is within dev, where
// the rest of the minimum cannot change the maximum. `near` receives q's
// nearest segment when the scan went through.
double raise_to_polyline(const std::vector<P>& pts, std::size_t a, std::size_t b, P q, double widen,
                         double dev, std::size_t& near) {
  double best = distance(pts[a], q);
  if (best + widen <= dev) return dev;
  const std::size_t from = std::clamp(near, a, b - 1);
  auto within = [&](std::size_t k) {  // true once q is known to be within dev
    const double d = distance_to_line_segment(pts[k], pts[k + 1], q);
    if (d < best) {
      best = d;
      near = k;
    }
    return best + widen <= dev;
  };
  for (std::size_t step = 0;; ++step) {
    const bool up = from + step < b;
    const bool down = step > 0 && from >= a + step;
    if (!up && !down) break;
    if ((up && within(from + step)) || (down && within(from - step))) return dev;
  }
  return std::max(dev, best + widen);
}

// A piece as written: its rounded end and centre, the text after the G word.
struct Written {
  std::string text;
  P end{};
  double deviation = 0;
};

// Writes piece `s` from the rounded start `from` with `decimals`, and
// measures it against pts[a..b] (see weld.hpp).
Written write_piece(const Segment<double>& s, P from, const std::vector<P>& pts, std::size_t a,
                    std::size_t b, int decimals, double tol) {
  Written w;
  w.end = {rounded(s.end.x, decimals), rounded(s.end.y, decimals)};
  const bool arc = s.is_arc();
  P c{};
  if (arc) {
    const P off{rounded(s.centre.x - from.x, decimals), rounded(s.centre.y - from.y, decimals)};
    c = from + off;
    w.text = (s.dir < 0 ? "G2 X" : "G3 X") + format_number(w.end.x, decimals) + " Y" +
             format_number(w.end.y, decimals) + " I" + format_number(off.x, decimals) + " J" +
             format_number(off.y, decimals);
  } else {
    w.text = "G1 X" + format_number(w.end.x, decimals) + " Y" + format_number(w.end.y, decimals);
  }
  const Segment<double> drawn = arc ? Segment<double>::arc(from, w.end, c, s.dir) : Segment<double>::line(from, w.end);
  const double widen = arc ? std::fabs((from - c).norm() - (w.end - c).norm()) : 0.0;
  double dev = std::max(distance(w.end, pts[b]), distance(from, pts[a]));
  for (std::size_t k = a + 1; k < b; ++k) dev = std::max(dev, distance_to_segment(drawn, pts[k]) + widen);
  // Samples of the drawn piece against the polyline: the band side.
  double sweep = 0, r = 0, a0 = 0;
  double length = distance(from, w.end);
  if (arc) {
    r = (from - c).norm();
    a0 = std::atan2(from.y - c.y, from.x - c.x);
    const double a1 = std::atan2(w.end.y - c.y, w.end.x - c.x);
    sweep = s.dir > 0 ? a1 - a0 : a0 - a1;
    if (sweep <= 0) sweep += 2 * 3.14159265358979323846;
    length = r * sweep;
  }
  const std::size_t n = std::clamp<std::size_t>(static_cast<std::size_t>(std::ceil(4 * length / tol)), 8, 512);
  std::size_t near = a;
  for (std::size_t k = 1; k < n; ++k) {
    const double t = static_cast<double>(k) / static_cast<double>(n);
    P q;
    if (arc) {
      const double ang = a0 + (s.dir > 0 ? 1 : -1) * sweep * t;
      q = {c.x + r * std::cos(ang), c.y + r * std::sin(ang)};
    } else {
      q = from + (w.end - from) * t;
    }
    dev = raise_to_polyline(pts, a, b, q, widen, dev, near);
  }
  w.deviation = dev;
  return w;
}

// Inserts "G1 " after a leading N word (or at the start): a line that relied
// on the modal G1 which a written arc has replaced.
std::string with_g1(const io::GBlock& b) {
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

std::string_view word_text(const io::GBlock& b, char letter) {
  for (const io::GWord& w : b.words)
    if (w.letter == letter) return b.text.substr(w.pos, w.len);
  return {};
}

class Emitter {
 public:
  explicit Emitter(std::string& out) : out_(out) {}

  void verbatim(const io::GBlock& b) {
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

// pts without its jitter: a point that lies, with the points skipped before
// it (at most 32 in a row), within `e` of the chord from the last kept point
// to the next point.
// kept_index maps each kept point to its index in pts; `moved` is the largest
// distance of a skipped point from its chord.
std::vector<P> without_jitter(const std::vector<P>& pts, double e, std::vector<std::size_t>& kept_index,
                              double& moved) {
  kept_index.clear();
  kept_index.push_back(0);
  moved = 0;
  std::size_t a = 0;
  for (std::size_t k = 1; k + 1 < pts.size(); ++k) {
    bool drop = e > 0 && k - a <= 32;
    double worst = 0;
    for (std::size_t m = a + 1; m <= k && drop; ++m) {
      worst = std::max(worst, distance_to_line_segment(pts[a], pts[k + 1], pts[m]));
      drop = worst <= e;
    }
    if (drop) {
      moved = std::max(moved, worst);
      continue;
    }
    kept_index.push_back(k);
    a = k;
  }
  kept_index.push_back(pts.size() - 1);
  std::vector<P> out;
  out.reserve(kept_index.size());
  for (std::size_t k : kept_index) out.push_back(pts[k]);
  return out;
}

struct Planned {
  fit::Piece<double> piece;
  bool keep = false;  // write its input lines
  Written written;
};

// A polyline made ready to plan: its distinct points, the run fitted (the
// points without their jitter) and where that run is cut into parts.
struct Run {
  bool welded = false;  // false: its lines are passed through (G91, a single point)
  double unit = 1, tol = 0, fit_tol = 0, moved = 0;
  std::vector<P> pts;                   // distinct consecutive points
  std::vector<std::size_t> from_index;  // each one's index in the polyline
  std::vector<P> simple;                // pts without the jitter
  std::vector<std::size_t> kept_index;  // each one's index in pts
  std::vector<std::size_t> cuts;        // the parts: simple[cuts[j]..cuts[j + 1]]

  std::size_t parts() const { return cuts.empty() ? 0 : cuts.size() - 1; }
  P part_start(std::size_t j) const { return simple[cuts[j]]; }
};

// Fits separately at turns sharper than 90 degrees (opts.split_turns).
void prepare(const io::GPolyline& pl, const WeldOptions& opts, int decimals, Run& r) {
  r.unit = pl.inches ? 25.4 : 1.0;
  r.tol = opts.tol_mm / r.unit;
  for (std::size_t k = 0; k < pl.points.size(); ++k) {
    if (!r.pts.empty() && r.pts.back() == pl.points[k]) continue;
    r.pts.push_back(pl.points[k]);
    r.from_index.push_back(k);
  }
  if (pl.relative || r.pts.size() < 2) return;  // G91 polylines are not welded (see README)
  r.welded = true;
  const double budget = 2 * std::pow(10.0, -decimals);
  r.fit_tol = r.tol > 2 * budget ? r.tol - budget : r.tol / 2;
  // The fit sees the run without its jitter (CAM output is full of 0.0003
  // mm back-and-forths, each a cusp the fitters must stop at), at a tol
  // less by how far the skipped points lie from their chords; every piece
  // is then measured against all the input points (resolve).
  r.simple = without_jitter(r.pts, r.tol * opts.jitter, r.kept_index, r.moved);
  const std::vector<P>& simple = r.simple;
  r.cuts.push_back(0);
  for (std::size_t k = 1; k <= simple.size() - 1; ++k) {
    const bool last = k == simple.size() - 1;
    const bool turn =
        !last && opts.split_turns && (simple[k] - simple[k - 1]).dot(simple[k + 1] - simple[k]) < 0;
    if (last || turn) r.cuts.push_back(k);
  }
}

// What planning one part gives: planned apart from the output, as the parts
// are planned on several threads and written in file order.
struct PartPlan {
  bool ok = true;
  std::string error;  // when !ok
  P from_in{};        // where the machine was at its start when it was planned
  P from_out{};       // where the machine is after it
  std::vector<Planned> pieces;
  std::size_t kept = 0;          // pieces kept as their input lines (rounding)
  std::exception_ptr exception;  // thrown while planning on a worker thread
};

// Plans parts: reads opts only, so that planners on several threads share
// nothing (fit_job's workspace is thread_local).
struct Planner {
  const WeldOptions& opts;
  int decimals = 0;
  std::string error;

  // The trouble resolve met in the run being planned: pieces refitted or
  // kept as their input lines.
  std::size_t trouble = 0;
  std::size_t kept = 0;
  bool closed_part = false;  // the part being planned ends where it starts

  // Plans part j of r with the machine at `from` at its start. With the band
  // criterion the part is fitted first without the fitters' tie-break (each
  // of its steps is a whole search): the count is the same, only the pieces'
  // place in the band differs. When a piece then fails the rounding check
  // (refitted or kept, or a loop closed by a single segment), the part is
  // planned again with weld's tie-break, whose pieces hug the input, and that
  // plan is kept unless it has more moves: never more moves than the
  // tie-break alone.
  void plan(const Run& r, std::size_t j, P from, PartPlan& out) {
    out = PartPlan{};
    out.from_in = from;
    error.clear();
    if (!plan_two_pass(r, j, from, out)) {
      out.ok = false;
      out.error = error;
    }
  }

  bool plan_two_pass(const Run& r, std::size_t j, P from, PartPlan& out) {
    const double fine = opts.tie_break < 0 ? tie_break_for(opts.criterion) : opts.tie_break;
    // The vertex criterion's fast pieces leave the band often (refits): it
    // would plan most parts twice.
    const bool two_pass = opts.tie_break < 0 && fine < 1 && opts.criterion == "band";
    const std::size_t begin = r.cuts[j], k = r.cuts[j + 1];
    std::vector<Planned>& first = out.pieces;
    P first_from = from;
    if (!plan_part(r.simple, begin, k, r.kept_index, r.pts, r.fit_tol, r.moved, r.tol, two_pass ? 1.0 : fine,
                   first_from, first))
      return false;
    std::size_t first_kept = kept;
    // Without trouble each piece is one move (a kept single segment with
    // no repeated points between): no plan of the same count has fewer.
    if (two_pass && (trouble > 0 || moves_of(first, r.from_index) > first.size())) {
      std::vector<Planned> again;
      P again_from = from;
      if (!plan_part(r.simple, begin, k, r.kept_index, r.pts, r.fit_tol, r.moved, r.tol, fine, again_from, again))
        return false;
      if (moves_of(again, r.from_index) <= moves_of(first, r.from_index)) {
        first.swap(again);
        first_from = again_from;
        first_kept = kept;
      }
    }
    out.from_out = first_from;
    out.kept = first_kept;
    return true;
  }

  // Fits simple[begin..end] with `tie_break` and plans its pieces over pts
  // (resolve); counts the trouble met.
  bool plan_part(const std::vector<P>& simple, std::size_t begin, std::size_t end,
                 const std::vector<std::size_t>& kept_index, const std::vector<P>& pts, double fit_tol,
                 double moved, double tol, double tie_break, P& from, std::vector<Planned>& plan) {
    const std::vector<P> part(simple.begin() + static_cast<std::ptrdiff_t>(begin),
                              simple.begin() + static_cast<std::ptrdiff_t>(end) + 1);
    std::vector<fit::Piece<double>> pieces;
    Status status = Status::ok;
    if (!fit_job(part, {}, fit_tol - moved, opts.criterion, pieces, error, status, "double", tie_break))
      return false;
    for (fit::Piece<double>& pc : pieces) {
      pc.first = static_cast<std::uint32_t>(kept_index[pc.first + begin]);
      pc.last = static_cast<std::uint32_t>(kept_index[pc.last + begin]);
    }
    trouble = 0;
    kept = 0;
    closed_part = simple[begin] == simple[end];
    return resolve(pts, pieces, fit_tol, tol, 0, from, plan);
  }

  // The moves a plan writes for the run (input blocks from_index apart).
  static std::size_t moves_of(const std::vector<Planned>& plan, const std::vector<std::size_t>& from_index) {
    std::size_t moves = 0;
    for (const Planned& p : plan) moves += p.keep ? from_index[p.piece.last] - from_index[p.piece.first] : 1;
    return moves;
  }

  // Writes each piece from the rounded end of the one before, with more
  // decimals when rounding costs too much; a piece still over tol (or whose
  // drawn arc leaves the band, which the vertex criterion allows) is fitted
  // again with the band criterion at half the tol, once, before its input
  // lines are kept.
  bool resolve(const std::vector<P>& pts, const std::vector<fit::Piece<double>>& pieces, double fit_tol,
               double tol, int depth, P& from, std::vector<Planned>& plan) {
    for (const fit::Piece<double>& pc : pieces) {
      Planned pl{pc, false, {}};
      if (pc.last - pc.first < 2) {  // a single segment: its input line is already the best
        // Closing a loop beside other pieces: an unbalanced split (a full
        // circle drawn as one arc and a line); the tie-break's is tried too.
        if (closed_part && pieces.size() > 1) ++trouble;
        pl.keep = true;
        plan.push_back(pl);
        from = pts[pc.last];
        continue;
      }
      bool ok = false;
      if (pc.segment.is_arc()) {  // a nearly straight arc (huge radius) is written as a line when one fits
        const double r = pc.segment.radius();
        const double half = distance(pc.segment.start, pc.segment.end) / 2;
        if (half < r && r - std::sqrt(r * r - half * half) < tol) {
          const Written line = write_piece(Segment<double>::line(pc.segment.start, pc.segment.end), from, pts,
                                           pc.first, pc.last, decimals, tol);
          if (line.deviation <= tol) {
            pl.written = line;
            pl.piece.segment = Segment<double>::line(pc.segment.start, pc.segment.end);
            ok = true;
          }
        }
      }
      for (int d = decimals; d <= decimals + 2 && !ok; ++d) {
        pl.written = write_piece(pc.segment, from, pts, pc.first, pc.last, d, tol);
        ok = pl.written.deviation <= tol;
      }
      if (ok) {
        plan.push_back(pl);
        from = pl.written.end;
        continue;
      }
      ++trouble;
      if (depth == 0) {
        const std::vector<P> part(pts.begin() + pc.first, pts.begin() + pc.last + 1);
        std::vector<fit::Piece<double>> again;
        Status status = Status::ok;
        // A finer tie-break than the first fit: rare, and its pieces then hug the input.
        if (!fit_job(part, {}, fit_tol / 2, "band", again, error, status, "double", 1e-3)) return false;
        for (fit::Piece<double>& p : again) {
          p.first += pc.first;
          p.last += pc.first;
        }
        if (!resolve(pts, again, fit_tol / 2, tol, 1, from, plan)) return false;
        continue;
      }
      ++kept;
      pl.keep = true;
      plan.push_back(pl);
      from = pts[pc.last];
    }
    return true;
  }
};


// Writes the input lines and the plans, in file order; keeps the stats.
struct Writer {
  const io::GcodeFile& g;
  const WeldOptions& opts;
  WeldStats& stats;
  Emitter emit;
  // Where the machine is minus where the input says, after the moves written
  // so far: nonzero only when --decimals rounds the input's own end points.
  P offset{};

  // Writes an input line as it is.
  void pass(const io::GBlock& b) {
    emit.verbatim(b);
    if (!b.moves && b.unknown.empty() && word_text(b, 'X').empty() && word_text(b, 'Y').empty()) return;
    if (b.moves) ++stats.output_moves;
    if (!word_text(b, 'X').empty() && !b.relative) offset.x = 0;
    if (!word_text(b, 'Y').empty() && !b.relative) offset.y = 0;
    if (!b.unknown.empty()) offset = {};  // homing, offsets: the input's own coordinates again
  }

  // Writes pl, welded as `pieces` (planned from `offset`), ending at `end`.
  void write(const io::GPolyline& pl, const Run& r, const std::vector<Planned>& pieces, P end) {
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
          emit.verbatim(g.blocks[i]);
          if (g.blocks[i].moves) ++stats.output_moves;
        }  // its X/Y words are the input's: offset is zero after it (resolve)
        next_block = end_block + 1;
        continue;
      }
      stats.max_deviation_mm = std::max(stats.max_deviation_mm, w.deviation * r.unit);
      const io::GBlock& eb = g.blocks[block];
      std::string line;
      if (const std::string_view n = word_text(eb, 'N'); !n.empty()) {
        line = n;
        line += ' ';
      }
      line += w.text;
      if (k == 0)
        if (const std::string_view f = word_text(g.blocks[pl.first_block], 'F'); !f.empty()) {
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
        const io::GBlock& b = g.blocks[i];
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
// parts of at least kPooledPoints points, made by `threads` workers that take
// the next part in file order; the writer waits for each in turn and plans
// the small parts itself (a hand-over costs more than their fit: octocat's
// 24k single-line polylines took 9 times longer through the pool). A pooled
// part's plan assumes the machine starts at the part's first input point
// (the rule, unless --decimals rounds the input): the writer plans it
// again, on its own thread, when the machine is elsewhere.
class PlanPool {
 public:
  static constexpr std::size_t kPooledPoints = 32;

  PlanPool(const io::GcodeFile& g, const WeldOptions& opts, int decimals, unsigned threads)
      : opts_(opts), decimals_(decimals), runs_(g.polylines.size()) {
    parallel_for(runs_.size(), threads, [&](std::size_t p) { prepare(g.polylines[p], opts, decimals, runs_[p]); });
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
    for (unsigned t = 0; t < threads && !tasks_.empty(); ++t) workers_.emplace_back([this] { work(); });
  }
  PlanPool(const PlanPool&) = delete;
  PlanPool& operator=(const PlanPool&) = delete;
  ~PlanPool() {
    stop_ = true;  // the workers finish the part they plan, then take no other
    for (std::thread& t : workers_) t.join();
  }

  // Polyline p, prepared; the caller may free it once its parts are taken.
  Run& run(std::size_t p) { return runs_[p]; }

  // The plan of part j of polyline p, once made, and the caller's from then;
  // null when the part is the caller's to plan.
  PartPlan* wait(std::size_t p, std::size_t j) {
    const std::size_t t = task_of_[first_part_[p] + j];
    if (t == kNone) return nullptr;
    ready_[t].wait(false, std::memory_order_acquire);
    return &plans_[t];
  }

 private:
  static constexpr std::size_t kNone = ~std::size_t{0};
  struct Task {
    std::size_t polyline, part;
  };

  void work() {
    Planner planner{opts_, decimals_, {}};
    for (;;) {
      const std::size_t t = next_.fetch_add(1);
      if (t >= tasks_.size() || stop_) return;
      const Run& r = runs_[tasks_[t].polyline];
      try {
        planner.plan(r, tasks_[t].part, r.part_start(tasks_[t].part), plans_[t]);
      } catch (...) {
        plans_[t].exception = std::current_exception();
      }
      ready_[t].store(true, std::memory_order_release);  // publishes plans_[t]
      ready_[t].notify_one();                            // only the writer waits
    }
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
double tie_break_for(const std::string& criterion) { return criterion == "band" ? 0.1 : 1e-3; }

unsigned weld_threads(int requested) {
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  return requested <= 0 ? cores : std::min(cores, static_cast<unsigned>(requested));
}

bool weld_gcode(const io::GcodeFile& g, const WeldOptions& opts, std::string& out,
                WeldStats& stats, std::string& error) {
  stats = WeldStats{};
  stats.decimals = opts.decimals >= 0 ? opts.decimals : std::max<int>(3, static_cast<int>(g.decimals));
  out.clear();
  std::size_t bytes = 0;
  for (const io::GBlock& b : g.blocks) bytes += b.text.size() + b.end.size();
  out.reserve(bytes + bytes / 8);  // arcs shorten the text; a "G1 " added after one lengthens it
  io::prefault(out.data(), bytes);
  Writer w{g, opts, stats, Emitter(out), {}};
  Planner here{opts, stats.decimals, {}};  // the sequential path, and the parts planned again
  const unsigned threads = g.polylines.empty() ? 1 : weld_threads(opts.threads);
  std::optional<PlanPool> pool;
  if (threads > 1) pool.emplace(g, opts, stats.decimals, threads);
  Run local;
  PartPlan part;
  std::vector<Planned> pieces;
  std::size_t next = 0;
  for (std::size_t p = 0; p < g.polylines.size(); ++p) {
    const io::GPolyline& pl = g.polylines[p];
    for (; next < pl.first_block; ++next) w.pass(g.blocks[next]);
    next = pl.last_block + 1;
    Run& r = pool ? pool->run(p) : local;
    if (!pool) {
      r = Run{};
      prepare(pl, opts, stats.decimals, r);
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
        if (!same_point(made->from_in, from)) here.plan(r, j, from, *made);
      } else {
        made = &part;
        here.plan(r, j, from, part);
      }
      if (!made->ok) {
        error = g.file + ":" + std::to_string(g.blocks[pl.first_block].line) + ": " + made->error;
        return false;
      }
      stats.kept_pieces += made->kept;
      if (opts.progress)
        opts.progress(pl.point_block[r.from_index[r.kept_index[r.cuts[j + 1]]]], g.blocks.size());
      pieces.insert(pieces.end(), made->pieces.begin(), made->pieces.end());
      from = made->from_out;
      *made = PartPlan{};  // taken: its memory is free again
    }
    w.write(pl, r, pieces, from);
    r = Run{};
  }
  for (; next < g.blocks.size(); ++next) w.pass(g.blocks[next]);
  for (const io::GBlock& b : g.blocks) stats.input_moves += b.moves ? 1 : 0;
  return true;
}

}  // namespace kerf::cli
