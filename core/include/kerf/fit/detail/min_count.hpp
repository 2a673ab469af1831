// Fewest pieces: breadth-first search over the DAG of feasible pairs i -> j,
// layer by layer, in O(n) memory beyond the input.
//
// Feasibility is not monotone in j (p_i -> p_j may work when p_i -> p_{j-1}
// does not), so a start point i is given up only when the oracle's monotone
// necessary condition fails for it (fit/detail/prefix_guard.hpp for the vertex
// criterion); until then every later j is tried. Layer k+1 is built by walking j upwards from the first start in
// layer k and asking the live starts of layer k, nearest first, for one that
// reaches j. The walk ends when every start of layer k is dead, so a node left
// out of layer k+1 is provably unreachable in k+1 pieces.
#pragma once

#include <cstdint>

#include "kerf/core/span.hpp"
#include "kerf/core/status.hpp"
#include "kerf/geom/vec2.hpp"

namespace kerf::fit {

constexpr std::uint32_t unreached = 0xFFFFFFFFu;

// Words of index storage the search needs for n points.
constexpr std::size_t min_count_words(std::size_t n) { return 5 * n; }

struct MinCount {
  std::uint32_t pieces = 0;  // 0 when the budget was exceeded
};

// Oracle: bool feasible(i, j, hint) for i < j, where hint is a word kept per
// start for the oracle's own use (0 at first), and bool alive(i, j), asked
// after feasible(i, j) failed: false only if no j' >= j can be reached from
// i (a monotone necessary condition; the start is then dropped for good). pred receives, for each reached
// node, the start of its last piece. Stops with pieces = 0 as soon as more
// than `budget` pieces would be needed.
//
// layer_of, if given, names for each node the only layer at which it may be
// reached (unreached: none), and the search reaches nothing else. A tie-break
// passes the layers of a wider band that needs exactly `budget` pieces: if
// feasibility only shrinks with the band, no node is reached sooner in a
// narrower one, and one reached later cannot finish within the budget (it was
// at least `budget - layer` pieces from the end), so the verdict "within
// budget" is the same. Either way a path found is a real path: the
// restriction can only make a tie-break stop at a wider band, never accept an
// infeasible one.
template <class Oracle>
Result<MinCount> min_count(std::uint32_t n, Oracle& feasible, Span<std::uint32_t> words,
                           std::uint32_t budget, std::uint32_t*& pred_out,
                           const std::uint32_t* layer_of = nullptr) {
  if (n < 2) return Status::invalid_argument;
  if (words.size() < min_count_words(n)) return Status::capacity_exceeded;
  std::uint32_t* dist = words.data();
  std::uint32_t* pred = dist + n;
  std::uint32_t* cur = pred + n;   // live starts of layer k, ascending
  std::uint32_t* next = cur + n;   // layer k + 1, ascending
  std::uint32_t* hint = next + n;  // the oracle's word for each live start
  for (std::uint32_t k = 0; k < n; ++k) dist[k] = unreached;
  dist[0] = 0;
  pred[0] = 0;
  pred_out = pred;
  cur[0] = 0;
  hint[0] = 0;
  std::uint32_t cur_size = 1;

  for (std::uint32_t layer = 0; dist[n - 1] == unreached; ++layer) {
    if (layer >= budget || cur_size == 0) return MinCount{0};
    std::uint32_t next_size = 0;
    std::uint32_t below = 0;  // starts cur[0..below) lie before j
    for (std::uint32_t j = cur[0] + 1; j < n && cur_size > 0; ++j) {
      while (below < cur_size && cur[below] < j) ++below;
      if (dist[j] != unreached) continue;
      if (layer_of != nullptr && layer_of[j] != layer + 1) continue;
      bool died = false;
      for (std::uint32_t s = below; s-- > 0;) {
        const std::uint32_t i = cur[s];
        if (i == unreached) continue;
        if (feasible(i, j, hint[s])) {
          dist[j] = layer + 1;
          pred[j] = i;
          next[next_size++] = j;
          break;
        }
        // Only a start that just failed needs the guard's verdict.
        if (!feasible.alive(i, j)) {
          cur[s] = unreached;
          died = true;
        }
      }
      if (died) {  // drop dead starts, keeping order
        std::uint32_t w = 0;
        std::uint32_t new_below = 0;
        for (std::uint32_t s = 0; s < cur_size; ++s) {
          if (cur[s] == unreached) continue;
          if (s < below) ++new_below;
          hint[w] = hint[s];
          cur[w++] = cur[s];
        }
        cur_size = w;
        below = new_below;
      }
    }
    for (std::uint32_t s = 0; s < next_size; ++s) {
      cur[s] = next[s];
      hint[s] = 0;
    }
    cur_size = next_size;
  }
  return MinCount{dist[n - 1]};
}

}  // namespace kerf::fit
