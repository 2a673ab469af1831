#include "weld/weld_plan.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <utility>

#include "weld/arc_samples.hpp"
#include "weld/fit_memo.hpp"
#include "weld/segment_distance.hpp"
#include "kerf/fit/detail/chord.hpp"
#include "kerf/geom/segment.hpp"

namespace kerf::weld::detail {

namespace {

// v printed with `decimals` digits, trailing zeros (and a bare point) cut,
// "-0" as "0". `exact`, if given, is set when the text reads back as a
// double that prints as the same text (at most 15 digits, DBL_DIG): the
// caller may then reuse the text instead of printing the read value again.
// to_chars prints what printf's "%.*f" prints (both exact, ties to even),
// at a fifth of the cost; from_chars reads like strtod.
std::string format_number(double v, int decimals, bool* exact = nullptr) {
  char buf[400];  // DBL_MAX with 11 decimals (--decimals 9, + 2) fits
  const std::to_chars_result printed = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  std::string s(buf, printed.ec == std::errc() ? static_cast<std::size_t>(printed.ptr - buf) : 0);
  if (exact != nullptr) {
    const std::size_t point = s.find('.');
    const std::size_t whole = (point == std::string::npos ? s.size() : point) - (s[0] == '-' ? 1 : 0);
    *exact = whole + static_cast<std::size_t>(decimals) <= 15;
  }
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

// v rounded to `decimals` as the output writes it, and its text
// (format_number of the rounded value, printed once when that is exact).
struct Rounded {
  double value;
  std::string text;
};
Rounded round_number(double v, int decimals) {
  bool exact = false;
  std::string text = format_number(v, decimals, &exact);
  double value = 0;
  std::from_chars(text.data(), text.data() + text.size(), value);
  if (!exact) text = format_number(value, decimals);
  return {value, std::move(text)};
}

// max(dev, distance from q to the polyline pts[a..b] + widen), exactly. The
// scan starts at segment `near` (the last sample's nearest: the samples walk
// along the polyline) and goes outwards; it stops once q is within dev, where
// the rest of the minimum cannot change the maximum. `near` receives q's
// nearest segment when the scan went through; `seg` the segment of the
// smallest distance found (b: the point pts[a]).
double raise_to_polyline(const std::vector<P>& pts, std::size_t a, std::size_t b, P q, double widen,
                         double dev, std::size_t& near, std::size_t& seg) {
  double best = distance(pts[a], q);
  seg = b;
  if (best + widen <= dev) return dev;
  const std::size_t from = std::clamp(near, a, b - 1);
  auto within = [&](std::size_t k) {  // true once q is known to be within dev
    const double d = distance_to_line_segment(pts[k], pts[k + 1], q);
    if (d < best) {
      best = d;
      near = k;
      seg = k;
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

// Writes piece `s` from the rounded start `from` with `decimals`, and
// measures it against pts[a..b] (see weld.hpp).
Written write_piece(const Segment<double>& s, P from, const std::vector<P>& pts, std::size_t a,
                    std::size_t b, int decimals, double tol) {
  Written w;
  const Rounded ex = round_number(s.end.x, decimals), ey = round_number(s.end.y, decimals);
  w.end = {ex.value, ey.value};
  const bool arc = s.is_arc();
  P c{};
  if (arc) {
    const Rounded ox = round_number(s.centre.x - from.x, decimals), oy = round_number(s.centre.y - from.y, decimals);
    const P off{ox.value, oy.value};
    c = from + off;
    w.text = (s.dir < 0 ? "G2 X" : "G3 X") + ex.text + " Y" + ey.text + " I" + ox.text + " J" + oy.text;
  } else {
    w.text = "G1 X" + ex.text + " Y" + ey.text;
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
  const std::size_t n =
      std::clamp<std::size_t>(static_cast<std::size_t>(std::ceil(4 * length / tol)), 8, ArcSamples::kMaxSteps);
  std::size_t near = a;
  const ArcSamples on_arc(c, r, a0, (s.dir > 0 ? 1 : -1) * sweep, arc ? n : 0);
  auto sample = [&](std::size_t k) {
    if (arc) return on_arc.at(k);
    return from + (w.end - from) * (static_cast<double>(k) / static_cast<double>(n));
  };
  // The samples walk along the polyline: each is measured first against the
  // segment nearest the last one scanned, then the segment after it; a
  // distance within dev - widen settles it as raise_to_polyline would (the
  // same distance, the same test). Where one segment settles sample k and
  // sample k + kJump with room to spare, the samples between are skipped:
  // their distance to the segment (convex) is at most the larger of the
  // two along the chord, and the piece between lies within the chord's
  // sagitta of it (r a^2 / 8 for an angle a, 0 on a line). `margin` is far
  // above the rounding of a sample and of a distance (a few ulps of the
  // coordinates), so they cannot raise dev: it is the maximum over all the
  // samples, bit for bit. A jump is tried at most once per kJump samples.
  constexpr std::size_t kJump = 4;
  const double jump_angle = arc ? sweep * kJump / static_cast<double>(n) : 0.0;
  const double sagitta = r * jump_angle * jump_angle / 8 * (1 + 1e-9);
  const double size = std::fabs(from.x) + std::fabs(from.y) + std::fabs(w.end.x) + std::fabs(w.end.y) +
                      std::fabs(c.x) + std::fabs(c.y) + r + length + 1;
  const double margin = 1e-6 * tol + 1e-12 * size;
  const bool jumps = jump_angle <= 1 && kJump < n;
  std::size_t seg = b, ahead = 0;  // ahead: a sample computed before its turn (q_ahead), 0: none
  P q_ahead{};
  SegmentDistance last(pts[a], pts[a]);
  for (std::size_t k = 1; k < n; ++k) {
    const P q = k == ahead ? q_ahead : sample(k);
    if (seg != b) {
      const double d = last(q);
      if (d + widen <= dev) {
        if (jumps && ahead <= k && k + kJump < n) {
          ahead = k + kJump;
          q_ahead = sample(ahead);
          if (std::max(d, last(q_ahead)) + sagitta + widen + margin <= dev) k = ahead - 1;
        }
        continue;
      }
    }
    if (seg + 1 < b) {  // most often the sample has walked on to the next segment
      const SegmentDistance next(pts[seg + 1], pts[seg + 2]);
      if (next(q) + widen <= dev) {
        last = next;
        near = ++seg;
        continue;
      }
    }
    const std::size_t was = seg;
    dev = raise_to_polyline(pts, a, b, q, widen, dev, near, seg);
    if (seg != b && seg != was) last = SegmentDistance(pts[seg], pts[seg + 1]);
  }
  w.deviation = dev;
  return w;
}

// pts without its jitter: a point that lies, with the points skipped before
// it (at most 32 in a row), within `e` of the chord from the last kept point
// to the next point.
// kept_index maps each kept point to its index in pts; `moved` is the largest
// distance of a skipped point from its chord.
std::vector<P> without_jitter(const std::vector<P>& pts, double e, std::vector<std::size_t>& kept_index,
                              double& moved) {
  kept_index.clear();
  kept_index.reserve(pts.size());
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
  bool split = false;        // its fit failed its own check and was made in halves (job::fit_job)

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
    const bool two_pass = opts.tie_break < 0 && fine < 1 && opts.criterion == job::Criterion::band;
    const std::size_t begin = r.cuts[j], k = r.cuts[j + 1];
    std::vector<Planned>& first = out.pieces;
    P first_from = from;
    if (!fit_part(r, begin, k, two_pass ? 1.0 : fine, first_from, first)) return false;
    const bool first_split = split;
    std::size_t first_kept = kept;
    // Without trouble each piece is one move (a kept single segment with
    // no repeated points between): no plan of the same count has fewer.
    // A first fit of single segments only, not split in halves for its own
    // check, had the fewest pieces with every segment its own piece: so
    // has every fit of that count, the tie-break's too, and its plan would
    // be this one (kept input lines): it is not made.
    bool singles = !first_split;
    for (const Planned& pl : first) singles = singles && pl.keep && pl.piece.last - pl.piece.first < 2;
    if (two_pass && !singles && (trouble > 0 || moves_of(first, r.from_index) > first.size())) {
      std::vector<Planned> again;
      P again_from = from;
      if (!fit_part(r, begin, k, fine, again_from, again)) return false;
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

  // Fits r.simple[begin..end] with `tie_break` and plans its pieces over
  // r.pts (resolve); counts the trouble met.
  bool fit_part(const Run& r, std::size_t begin, std::size_t end, double tie_break, P& from,
                std::vector<Planned>& plan) {
    const std::vector<P> part(r.simple.begin() + static_cast<std::ptrdiff_t>(begin),
                              r.simple.begin() + static_cast<std::ptrdiff_t>(end) + 1);
    std::vector<fit::Piece<double>> pieces;
    if (part.size() == 2 && opts.criterion != job::Criterion::biarc && !fit::closes_on_itself(part[0], part[1])) {
      // One segment: its only fit is one piece, kept as its input line
      // (resolve reads nothing else of it). The fitter's setup cost a
      // calibration file's hundreds of such parts a fifth of its time.
      pieces.push_back({0, 1, Segment<double>::line(part[0], part[1]), 0.0});
      split = false;
    } else if (!fit_memo(part, r.fit_tol - r.moved, opts.criterion, tie_break, pieces, error, split)) {
      return false;
    }
    for (fit::Piece<double>& pc : pieces) {
      pc.first = static_cast<std::uint32_t>(r.kept_index[pc.first + begin]);
      pc.last = static_cast<std::uint32_t>(r.kept_index[pc.last + begin]);
    }
    trouble = 0;
    kept = 0;
    closed_part = r.simple[begin] == r.simple[end];
    return resolve(r.pts, pieces, r.fit_tol, r.tol, 0, from, plan);
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
        // A finer tie-break than the first fit: rare, and its pieces then hug the input.
        bool again_split = false;
        if (!fit_memo(part, fit_tol / 2, job::Criterion::band, 1e-3, again, error, again_split)) return false;
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

}  // namespace

void prepare(const job::GPolyline& pl, const WeldOptions& opts, int decimals, Run& r) {
  r.unit = pl.inches ? 25.4 : 1.0;
  r.tol = opts.tol_mm / r.unit;
  // One allocation each (most polylines are short: growing them by
  // doubling was most of a small file's allocations).
  r.pts.reserve(pl.points.size());
  r.from_index.reserve(pl.points.size());
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
  r.cuts.reserve(8);
  r.cuts.push_back(0);
  for (std::size_t k = 1; k <= simple.size() - 1; ++k) {
    const bool last = k == simple.size() - 1;
    const bool turn =
        !last && opts.split_turns && (simple[k] - simple[k - 1]).dot(simple[k + 1] - simple[k]) < 0;
    if (last || turn) r.cuts.push_back(k);
  }
}

void plan_part(const Run& r, std::size_t j, P from, const WeldOptions& opts, int decimals, PartPlan& out) {
  Planner{opts, decimals, {}}.plan(r, j, from, out);
}

}  // namespace kerf::weld::detail
