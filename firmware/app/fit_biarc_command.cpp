// `kerf fit --criterion biarc`'s options; the fit itself is
// job/fit_file.hpp's fit_biarc_file.
#include <string>

#include "app/fit_command.hpp"
#include "io/options.hpp"
#include "job/fit_file.hpp"
#include "job/fit_write.hpp"

namespace kerf::app {

using io::kExitOk;

namespace {

int check_biarc_options(const job::FitOptions& opts, double& tol, bool& estimate) {
  std::string error;
  if (opts.method != "optimal")
    return io::usage_error("--method: " + io::quoted(opts.method) +
                           " is a vertex-criterion rule; --criterion biarc is always optimal");
  if (!opts.pieces.empty()) return io::usage_error("--pieces: not available with --criterion biarc");
  if (!opts.tol_left.empty() || !opts.tol_right.empty())
    return io::usage_error("--tol-left and --tol-right: --criterion biarc takes a symmetric --tol");
  if (opts.tangent_format != "vector" && opts.tangent_format != "angle")
    return io::usage_error("--tangent-format: unknown format " + io::quoted(opts.tangent_format) +
                           " (expected vector or angle)");
  if (!opts.tangents.empty() && opts.tangents != "given" && opts.tangents != "estimate")
    return io::usage_error("--tangents: expected given or estimate, got " + io::quoted(opts.tangents));
  if (!io::parse_length("--tol", opts.tol, false, tol, error)) return io::usage_error(error);
  estimate = opts.tangents == "estimate";
  return kExitOk;
}

}  // namespace

int run_fit_biarc(const job::FitOptions& opts, job::Numeric numeric) {
  double tol = 0.0;
  bool estimate = false;
  if (const int rc = check_biarc_options(opts, tol, estimate); rc != kExitOk) return rc;
  double feed = 1000.0;
  if (const int rc = job::check_output_options(opts, feed); rc != kExitOk) return rc;
  return job::fit_biarc_file(opts, numeric == job::Numeric::fixed, tol, estimate, feed);
}

}  // namespace kerf::app
