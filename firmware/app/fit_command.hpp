// `kerf fit`: fit the fewest arcs to the points of a file, or the smallest
// tolerance for a number of pieces, and print them.
#pragma once

#include "io/options.hpp"
#include "job/criterion.hpp"
#include "job/fit_options.hpp"

namespace CLI {
class App;
}

namespace kerf::app {

// `kerf fit --criterion biarc` (app/fit_biarc_command.cpp).
int run_fit_biarc(const job::FitOptions& opts, job::Numeric numeric);

// Adds the `fit` subcommand to app, storing into opts.
CLI::App* add_fit_command(CLI::App& app, job::FitOptions& opts);

// Runs it; returns the exit code. Output goes to stdout only on success.
int run_fit(const job::FitOptions& opts);

}  // namespace kerf::app
