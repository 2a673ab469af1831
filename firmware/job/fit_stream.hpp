// `kerf fit --stream --window N`: one path read line by line, each piece
// written as soon as it is decided (job/fit_stream.cpp).
#pragma once

#include <optional>

#include "job/criterion.hpp"
#include "job/fit_options.hpp"

namespace kerf::job {

// Returns the exit code (io/options.hpp); output goes to stdout. criterion,
// numeric: opts' names as parsed, empty when unknown (refused here).
int run_fit_stream(const FitOptions& opts, std::optional<Criterion> criterion, std::optional<Numeric> numeric);

}  // namespace kerf::job
