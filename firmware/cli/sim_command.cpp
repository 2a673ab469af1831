#include "cli/sim_command.hpp"

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "cli/fit_command.hpp"
#include "cli/fit_job.hpp"
#include "cli/options.hpp"
#include "control/sim_job.hpp"
#include "io/fit_storage.hpp"
#include "io/point_file.hpp"
#include "io/output_file.hpp"
#include "io/sim_output.hpp"
#include "kerf/fit/fit.hpp"
#include "kerf/sim/motion_executor.hpp"

namespace kerf::cli {

namespace {

// KIND@SECONDS[:DURATION]
bool parse_fault(const std::string& text, bool rtu, control::ScheduledFault& f, std::string& error) {
  const std::size_t at = text.find('@');
  const std::string kind = text.substr(0, at);
  if (kind == "link-drop") f.kind = control::FaultKind::link_drop;
  else if (kind == "link-stall") f.kind = control::FaultKind::link_stall;
  else if (kind == "modbus-exception") f.kind = control::FaultKind::modbus_exception;
  else if (kind == "crc-error") f.kind = control::FaultKind::crc_error;
  else {
    error = "--fault: unknown kind \"" + kind +
            "\" (expected link-drop, link-stall, modbus-exception or crc-error)";
    return false;
  }
  if (f.kind == control::FaultKind::crc_error && !rtu) {
    error = "--fault: crc-error needs --link modbus-rtu (TCP frames carry no CRC)";
    return false;
  }
  if (at == std::string::npos) {
    error = "--fault: expected KIND@SECONDS[:DURATION], got \"" + text + "\"";
    return false;
  }
  const std::string rest = text.substr(at + 1);
  const std::size_t colon = rest.find(':');
  if (!parse_length("--fault", rest.substr(0, colon), true, f.at_s, error)) return false;
  if (colon != std::string::npos &&
      !parse_length("--fault", rest.substr(colon + 1), false, f.duration_s, error))
    return false;
  return true;
}

}  // namespace

int run_sim(const SimOptions& opts) {
  return run_sim_with(opts, [](std::string& why_not) {
    return sim::make_motion_executor({}, why_not);
  });
}

int run_sim_with(const SimOptions& opts, const ExecutorFactory& make_executor) {
  std::string error;
  if (opts.link != "modbus-tcp" && opts.link != "modbus-rtu")
    return usage_error("--link: unknown link \"" + opts.link + "\" (expected modbus-tcp or modbus-rtu)");
  const bool rtu = opts.link == "modbus-rtu";
  if (!criterion_supported(opts.criterion))
    return usage_error("--criterion: unknown criterion \"" + opts.criterion + "\" (expected vertex or band)");
  double tol = 0.0, feed = 0.0, speed = 0.0, link_timeout = 0.0;
  if (!parse_length("--tol", opts.tol, false, tol, error) ||
      !parse_length("--feed", opts.feed, false, feed, error) ||
      !parse_length("--speed", opts.speed, true, speed, error) ||
      !parse_length("--link-timeout", opts.link_timeout, false, link_timeout, error))
    return usage_error(error);
  control::SimJob job;
  for (const std::string& text : opts.faults) {
    control::ScheduledFault f;
    if (!parse_fault(text, rtu, f, error)) return usage_error(error);
    job.faults.push_back(f);
  }
  io::PointFile in;
  if (!read_job(opts.file, opts.criterion, in)) return kExitUsage;
  std::vector<fit::Piece<double>> fitted;
  Status fit_status = Status::ok;
  if (!fit_job(in.points, in.tols, tol, opts.criterion, fitted, error, fit_status)) {
    std::fprintf(stderr, "kerf: %s: %s\n", in.file.c_str(), error.c_str());
    return fit_status == Status::invalid_argument || fit_status == Status::degenerate ? kExitUsage
                                                                                     : kExitFailure;
  }
  const std::vector<fit::Piece<double>>& pieces = fitted;
  for (std::uint32_t k = 0; k < pieces.size(); ++k) {
    const fit::Piece<double>& p = pieces[k];
    hal::SegmentCommand c;
    c.seq = k + 1;
    c.kind = p.segment.kind;
    c.end = p.segment.end;
    c.centre = p.segment.centre;
    c.dir = p.segment.dir;
    c.feed = feed / 60.0;  // mm/min -> mm/s, the wire's unit
    c.torch = true;
    job.segments.push_back(c);
  }
  job.rtu = rtu;
  job.start = in.points.front();
  job.speed = speed;
  job.link_timeout_s = link_timeout;
  std::string why_not;
  std::unique_ptr<sim::SegmentExecutor> exec = make_executor(why_not);
  if (!exec) {
    std::fprintf(stderr, "kerf: sim: %s\n", why_not.c_str());
    return kExitFailure;
  }

  const control::SimJobResult res = control::run_sim_job(job, std::move(exec));
  if (!res.setup_error.empty()) {
    std::fprintf(stderr, "kerf: sim: cannot start the simulated board: %s\n", res.setup_error.c_str());
    return kExitFailure;
  }
  const io::SimSummary sum = io::summarise(res, pieces, opts.link);
  if (!opts.trace.empty() && !io::write_output(opts.trace, io::format_trace_csv(res.trace))) {
    std::fprintf(stderr, "kerf: --trace: cannot write %s: %s\n", opts.trace.c_str(), std::strerror(errno));
    return kExitFailure;
  }
  if (!opts.report.empty() && !io::write_output(opts.report, io::format_sim_json(sum))) {
    std::fprintf(stderr, "kerf: --report: cannot write %s: %s\n", opts.report.c_str(), std::strerror(errno));
    return kExitFailure;
  }
  std::fputs(io::format_sim_summary(sum).c_str(), stdout);
  if (!res.stream.ok) {
    std::fprintf(stderr, "kerf: sim: stopped after segment %u: %s\n", sum.last_executed, sum.fault.c_str());
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace kerf::cli
