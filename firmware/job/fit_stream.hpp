// `kerf fit --stream --window N`: one path read line by line, each piece
// written as soon as it is decided (job/fit_stream.cpp).
#pragma once

#include "job/fit_options.hpp"

namespace kerf::cli {

// Returns the exit code (io/options.hpp); output goes to stdout.
int run_fit_stream(const FitOptions& opts);

}  // namespace kerf::cli
