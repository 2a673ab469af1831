// `kerf fit --criterion biarc`'s options; the fit itself is
// job/fit_file.hpp's fit_biarc_file.
#include <string>

#include "app/fit_command.hpp"
#include "io/options.hpp"
#include "job/fit_file.hpp"
#include "job/fit_write.hpp"

namespace kerf::cli {

namespace {

int check_biarc_options(const FitOptions& opts, double& tol, bool& estimate) {
  std::string error;
  if (opts.method != "optimal")
    return usage_error("--method: " + quoted(opts.method) +
                       " is a vertex-criterion rule; --criterion biarc is always optimal");
  if (!opts.pieces.empty()) return usage_error("--pieces: not available with --criterion biarc");
  if (!opts.tol_left.empty() || !opts.tol_right.empty())
    return usage_error("--tol-left and --tol-right: --criterion biarc takes a symmetric --tol");
  if (opts.tangent_format != "vector" && opts.tangent_format != "angle")
    return usage_error("--tangent-format: unknown format " + quoted(opts.tangent_format) +
                       " (expected vector or angle)");
  if (!opts.tangents.empty() && opts.tangents != "given" && opts.tangents != "estimate")
    return usage_error("--tangents: expected given or estimate, got " + quoted(opts.tangents));
  if (!parse_length("--tol", opts.tol, false, tol, error)) return usage_error(error);
  estimate = opts.tangents == "estimate";
  return kExitOk;
}

}  // namespace

int run_fit_biarc(const FitOptions& opts, Numeric numeric) {
  double tol = 0.0;
  bool estimate = false;
  if (const int rc = check_biarc_options(opts, tol, estimate); rc != kExitOk) return rc;
  double feed = 1000.0;
  if (const int rc = check_output_options(opts, feed); rc != kExitOk) return rc;
  return fit_biarc_file(opts, numeric == Numeric::fixed, tol, estimate, feed);
}

}  // namespace kerf::cli
