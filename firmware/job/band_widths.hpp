// The band's widths for `kerf fit --criterion band`, from --tol,
// --tol-left / --tol-right, or the point file's third column.
#pragma once

#include <string>
#include <vector>

#include "io/point_file.hpp"
#include "kerf/fit/band/region.hpp"

namespace kerf::job {

struct WidthOptions {
  std::string tol;    // both sides
  std::string left;   // overrides the left side (may be 0)
  std::string right;  // overrides the right side (may be 0)
  bool by_pieces = false;  // --pieces K: the widths are only a shape
};

// One width per point of `in`. With --pieces and no widths given, the shape
// is symmetric. Returns false with `error` ("--option: reason" or
// "FILE: reason") on bad or conflicting values.
bool band_widths(const WidthOptions& opts, const io::PointFile& in,
                 std::vector<fit::BandWidth<double>>& out, std::string& error);

}  // namespace kerf::job
