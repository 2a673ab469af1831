#include "simulated/sim_command.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>

#include "job/fit_job.hpp"
#include "io/options.hpp"
#include "config/config.hpp"
#include "simulated/can_sim_machine.hpp"
#include "control/machine_config.hpp"
#include "control/run_report.hpp"
#include "simulated/sim_machine.hpp"
#include "io/output_file.hpp"
#include "io/run_svg.hpp"
#include "simulated/job_watch.hpp"
#include "simulated/sim_job.hpp"
#include "simulated/sim_output.hpp"
#include "simulated/sim_progress.hpp"
#include "simulated/trace_recorder.hpp"
#include "kerf/sim/scripted_gpio.hpp"

namespace kerf::simulated {

using io::kExitFailure;
using io::kExitOk;
using io::kExitUsage;

namespace {

constexpr const char* kFaultKinds =
    "estop, arc-lost, no-arc, limit, hold, cycle-start, reset, drive-fault, stall, link-drop, link-stall, "
    "modbus-exception, crc-error, heartbeat-loss, emcy, bus-off or enable-refused";

// KIND@SECONDS[:DURATION]: a GPIO event for the scripted inputs, or a fault
// on the board's side.
bool parse_fault(const std::string& text, const std::string& link, std::vector<sim::GpioEvent>& gpio,
                 std::vector<BoardFault>& board, std::vector<CanFault>& can, std::string& error) {
  const bool rtu = link == "modbus-rtu", on_can = link == "can";
  const std::size_t at = text.find('@');
  const std::string kind = text.substr(0, at);
  sim::GpioEvent g;
  BoardFault b;
  CanFault c;
  bool is_gpio = true, is_can = false;
  if (kind == "estop") g.kind = sim::GpioEvent::Kind::estop;
  else if (kind == "arc-lost") g.kind = sim::GpioEvent::Kind::arc_lost;
  else if (kind == "no-arc") g.kind = sim::GpioEvent::Kind::no_arc;
  else if (kind == "limit") g.kind = sim::GpioEvent::Kind::limit, g.limit = 0;
  else if (kind == "hold") g.kind = sim::GpioEvent::Kind::hold;
  else if (kind == "cycle-start") g.kind = sim::GpioEvent::Kind::cycle_start;
  else if (kind == "reset") g.kind = sim::GpioEvent::Kind::reset;
  else {
    is_gpio = false;
    if (kind == "drive-fault") b.kind = BoardFaultKind::drive_fault;
    else if (kind == "stall") b.kind = BoardFaultKind::stall;
    else if (kind == "link-drop") b.kind = BoardFaultKind::link_drop;
    else if (kind == "link-stall") b.kind = BoardFaultKind::link_stall;
    else if (kind == "modbus-exception") b.kind = BoardFaultKind::modbus_exception;
    else if (kind == "crc-error") b.kind = BoardFaultKind::crc_error;
    else if (parse_can_fault(kind, c.kind)) is_can = true;
    else {
      error = "--fault: unknown kind " + io::quoted(kind) + " (expected " + kFaultKinds + ")";
      return false;
    }
  }
  if (on_can && !is_gpio && !is_can && b.kind == BoardFaultKind::stall) {
    is_can = true;  // the x drive jams
    c.kind = CanFaultKind::stall;
  } else if (on_can && !is_gpio && !is_can) {
    if (b.kind != BoardFaultKind::drive_fault) {
      error = "--fault: " + kind + " is a Modbus fault; on --link can: heartbeat-loss, emcy, bus-off, enable-refused";
      return false;
    }
    is_can = true;  // a drive fault on CAN is the drive's EMCY
    c.kind = CanFaultKind::emcy;
  }
  if (is_can && !on_can) {
    error = "--fault: " + kind + " needs --link can";
    return false;
  }
  if (!is_gpio && !is_can && b.kind == BoardFaultKind::crc_error && !rtu) {
    error = "--fault: crc-error needs --link modbus-rtu (TCP frames carry no CRC)";
    return false;
  }
  if (at == std::string::npos) {
    error = "--fault: expected KIND@SECONDS[:DURATION], got " + io::quoted(text);
    return false;
  }
  const std::string rest = text.substr(at + 1);
  const std::size_t colon = rest.find(':');
  double t = 0.0, duration = 0.0;
  if (!io::parse_length("--fault", rest.substr(0, colon), true, t, error)) return false;
  if (colon != std::string::npos && !io::parse_length("--fault", rest.substr(colon + 1), false, duration, error))
    return false;
  if (is_gpio) {
    g.t_s = t;
    g.duration_s = duration;
    gpio.push_back(g);
  } else if (is_can) {
    c.at_s = t;
    can.push_back(c);
  } else {
    b.at_s = t;
    if (colon != std::string::npos) b.duration_s = duration;
    board.push_back(b);
  }
  return true;
}

bool write_or_say(const std::string& option, const std::string& path, bool written) {
  if (path.empty() || written) return true;
  std::fprintf(stderr, "kerf: %s: cannot write %s: %s\n", option.c_str(), path.c_str(), std::strerror(errno));
  return false;
}

bool write_or_say(const std::string& option, const std::string& path, const std::string& text) {
  return write_or_say(option, path, path.empty() || io::write_output(path, text));
}

// The plot keeps every servo sample of a run up to this many (65 simulated
// seconds at 1 kHz), then thins them (trace_recorder.hpp): about 4 MB.
constexpr std::size_t kPlotSamples = std::size_t{1} << 16;

}  // namespace

int run_sim(const SimOptions& given) {
  SimOptions opts = given;
  std::string error;
  config::Config cfg = config::defaults();
  if (!opts.config.empty() && !config::load(opts.config, cfg, error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return kExitUsage;
  }
  const bool demo = opts.file.empty();
  if (demo) {  // the embedded default: everything written next to the user
    if (opts.trace.empty()) opts.trace = "kerf-sim.csv";
    if (opts.plot.empty()) opts.plot = "kerf-sim.svg";
    if (opts.report.empty()) opts.report = "kerf-sim.json";
  }
  std::string link = opts.link.empty() ? config::to_string(cfg.link.kind) : opts.link;
  if (link != "modbus-tcp" && link != "modbus-rtu" && link != "can")
    return io::usage_error("--link: unknown link " + io::quoted(link) + " (expected modbus-tcp, modbus-rtu or can)");
  const bool rtu = link == "modbus-rtu", can = link == "can";
  if (!can && (!opts.axes.empty() || !opts.sync_ms.empty() || !opts.iface.empty()))
    return io::usage_error(std::string(!opts.axes.empty() ? "--axes" : !opts.sync_ms.empty() ? "--sync-ms" : "--iface") +
                           ": only with --link can");
  const std::optional<job::Criterion> criterion =
      opts.criterion.empty() ? cfg.fit.criterion : job::parse_criterion(opts.criterion);
  if (!criterion) return io::usage_error(job::unknown_criterion(opts.criterion));
  const std::optional<job::Numeric> numeric = opts.numeric.empty() ? cfg.fit.numeric : job::parse_numeric(opts.numeric);
  if (!numeric) return io::usage_error(job::unknown_numeric(opts.numeric));
  double tol = cfg.fit.tol, feed = cfg.cut.feed, speed = 0.0, link_timeout = cfg.link.timeout;
  if ((!opts.tol.empty() && !io::parse_length("--tol", opts.tol, false, tol, error)) ||
      (!opts.feed.empty() && !io::parse_length("--feed", opts.feed, false, feed, error)) ||
      !io::parse_length("--speed", opts.speed, true, speed, error) ||
      (!opts.link_timeout.empty() && !io::parse_length("--link-timeout", opts.link_timeout, false, link_timeout, error)))
    return io::usage_error(error);
  if (feed > cfg.machine.max_feed)
    return io::usage_error("--feed: " + opts.feed + " mm/min is above the machine's max_feed");
  if (opts.resume && opts.journal.empty()) return io::usage_error("--resume: needs --journal FILE");

  sim::ScriptedGpioOptions gopts;
  // The simulated machine has the config's limit switches, or X and Y ones.
  gopts.limit_count = cfg.gpio.limits.empty() ? 2 : cfg.gpio.limits.size();
  std::vector<sim::GpioEvent> events;
  std::vector<BoardFault> board_faults;
  std::vector<CanFault> can_faults;
  for (const std::string& text : opts.faults)
    if (!parse_fault(text, link, events, board_faults, can_faults, error)) return io::usage_error(error);
  CanMachineConfig can_cfg = can_machine_config(cfg);
  if (can) {
    double axes = 0.0, sync_ms = 0.0;
    if (!opts.axes.empty()) {
      if (!io::parse_length("--axes", opts.axes, false, axes, error)) return io::usage_error(error);
      if (axes != 2.0 && axes != 3.0) return io::usage_error("--axes: the CAN link drives 2 or 3 axes, got " + opts.axes);
      can_cfg.can.axes = static_cast<std::size_t>(axes);
      if (can_cfg.can.node_ids.size() != can_cfg.can.axes) can_cfg.can.node_ids.clear();  // 1..axes
    }
    if (!opts.sync_ms.empty()) {
      if (!io::parse_length("--sync-ms", opts.sync_ms, false, sync_ms, error)) return io::usage_error(error);
      if (sync_ms < 1.0 || sync_ms > 10.0 || sync_ms != std::floor(sync_ms))
        return io::usage_error("--sync-ms: a whole number of ms in 1..10, got " + opts.sync_ms);
      can_cfg.can.sync_ms = sync_ms;
    }
    can_cfg.can.iface = opts.iface;
    can_cfg.faults = can_faults;
  }
  if (!opts.gpio_script.empty() &&
      !sim::load_gpio_script(opts.gpio_script, gopts.limit_count, events, error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return kExitUsage;
  }

  SimJobSettings settings;
  settings.criterion = *criterion;
  settings.numeric = *numeric;
  settings.tol = tol;
  settings.feed = feed;
  settings.dry_run = opts.dry_run;
  settings.whole = opts.whole_job;
  std::unique_ptr<SimJob> job;
  if (const int rc = load_sim_job(opts.file, cfg, settings, job); rc != 0) return rc;

  // The controller reads the job through the watch: the trace, the progress
  // line, the time limit and the plot take what they need from it as the
  // run goes, never the whole job.
  PlotKeeper plot_keep(!opts.plot.empty());
  TimeBudget budget;
  budget.cut_feed_mm_min = feed;
  budget.rapid_mm_min = cfg.machine.rapid_feed;
  budget.arc_ok_timeout_s = cfg.cut.arc_ok_timeout;
  budget.pierce_delay_s = cfg.cut.pierce_delay;
  budget.operator_delay_s = cfg.sim.operator_delay;
  WatchedJobSource watch(job->source(), budget, [&plot_keep, &job](const PulledSegment& p) {
    if (!plot_keep.on()) return;
    Segment<double> piece = p.segment;  // the wire's, where the fitted piece is gone
    job->piece(p.job, piece);
    plot_keep.add_piece(piece, p.path);
  });

  std::unique_ptr<control::Journal> journal;
  control::ResumePoint from;
  if (!open_sim_journal(opts.journal, opts.resume, watch, job->first_pierce(), journal, from)) return kExitUsage;

  sim::ScriptedGpio gpio(gopts);
  if (!gpio.add(events, error)) return io::usage_error("--fault: " + error);

  control::ControllerConfig ccfg = control::controller_config(cfg);
  control::MemoryOutputs outputs;  // the program's outputs, recorded; its inputs stay low
  ccfg.outputs = &outputs;
  ccfg.operator_delay_s = cfg.sim.operator_delay;
  // A scripted reset press gives the simulated machine a reset button: a
  // stop then waits latched for it.
  ccfg.wait_for_reset = ccfg.wait_for_reset || gpio.has_reset();
  ccfg.link_timeout_s = link_timeout;
  ccfg.link_watchdog_s = link_timeout / 2.0;
  SimMachineConfig mcfg = sim_machine_config(cfg);
  mcfg.rtu = rtu;
  mcfg.speed = speed;
  mcfg.faults = board_faults;
  // Long enough for any run of this job: what has been read of it at the cut
  // feed, a rapid across its extent and a pierce per path, three times over.
  mcfg.time_limit = [&watch] { return watch.budget().limit_s(); };
  mcfg.keep_executed = can_cfg.keep_executed = false;  // counted only
  mcfg.source_behind = can_cfg.source_behind = [&watch] { return watch.take_behind(); };
  // The axes power up at the job's first pierce point, as if homed there; a
  // resumed run starts there too and travels to its resume point.
  mcfg.start = job->start();

  // The trace goes to its consumers as the run makes it: memory stays flat
  // however long the job runs.
  TraceRecorder trace([&job](std::size_t k, Segment<double>& out) { return job->piece(k, out); },
                      config::z_limits(cfg.machine).configured(), !opts.plot.empty(), kPlotSamples);
  if (!opts.trace.empty() && !trace.open_csv(opts.trace)) {
    write_or_say("--trace", opts.trace, false);
    return kExitFailure;
  }
  mcfg.trace_sink = [&trace](const sim::TraceSample& t) { trace.take(t); };
  SimProgressLine progress(
      [&watch](std::size_t k, std::size_t& path) {
        const PulledSegment* p = watch.recent(k);
        if (p != nullptr) path = p->path;
        return p != nullptr;
      },
      [&watch](std::size_t& paths, std::size_t& segments) {
        paths = watch.path_count();
        segments = watch.segment_count();
      });
  if (progress.on()) mcfg.progress = [&progress](const SimProgress& p) { progress.show(p); };
  can_cfg.trace_sink = mcfg.trace_sink;
  can_cfg.progress = mcfg.progress;
  SimMachineResult res;
  if (can) {
    can_cfg.can.start = mcfg.start;
    can_cfg.speed = speed;
    can_cfg.max_sim_s = mcfg.max_sim_s;
    can_cfg.time_limit = mcfg.time_limit;
    // The controller cycles in whole SYNC periods.
    const double sync_s = can_cfg.can.sync_ms / 1000.0;
    can_cfg.cycle_s = std::max(sync_s, std::round(mcfg.cycle_s / sync_s) * sync_s);
    res = run_can_sim_machine(watch, ccfg, can_cfg, gpio, journal.get(), from);
  } else {
    res = run_sim_machine(watch, ccfg, mcfg, gpio, journal.get(), from);
  }
  progress.clear();
  job->say_notes();
  if (!res.setup_error.empty()) {
    std::fprintf(stderr, "kerf: sim: %s\n", res.setup_error.c_str());
    return kExitFailure;
  }

  control::RunSummary sum = control::summarise_run(res.run, watch.path_count(), link, opts.resume, journal.get());
  // The board's truth: what it executed (with the link down it may run on
  // past what the controller saw and journaled).
  sum.executed = static_cast<std::size_t>(res.executed_count);
  sum.torch_on = gpio.torch();
  sum.board_duplicates = res.board.duplicates;
  sum.max_path_deviation_mm = trace.max_deviation();
  sum.duration_s = res.sim_s;
  sum.wall_s = res.wall_s;
  sum.rt = res.rt;
  sum.rt_histogram = res.rt_histogram;
  job->describe(sum);
  sum.dry_run_option = opts.dry_run;
  if (!journal) {  // no journal: count repeats in this run's own record
    sum.executed_total = res.executed_count;
    sum.duplicates = res.executed_repeats;
  }

  io::RunPlot plot;
  if (!opts.plot.empty()) {
    job->plot_points(plot_keep);
    plot = plot_keep.take("kerf sim: " + job->file() + " (" + sum.state + ")");
    plot.tol = tol;
    plot.trace = trace.plot_trace();
    for (const control::ActionEvent& a : res.run.actions)
      if (a.kind == job::CanonKind::dwell || a.kind == job::CanonKind::pause)
        plot.marks.push_back({a.at, a.kind == job::CanonKind::dwell ? "dwell" : "pause", a.what});
  }
  if (!write_or_say("--trace", opts.trace, trace.finish_csv()) ||
      !write_or_say("--report", opts.report, control::format_run_json(sum)) ||
      (!opts.plot.empty() && !write_or_say("--plot", opts.plot, io::format_run_svg(plot))))
    return kExitFailure;
  std::fputs(control::format_run_summary(sum).c_str(), stdout);
  if (!res.run.reset_refused.empty()) std::fprintf(stderr, "kerf: sim: %s\n", res.run.reset_refused.c_str());
  if (demo)
    std::printf("kerf sim: wrote %s, %s and %s\n", opts.trace.c_str(), opts.plot.c_str(), opts.report.c_str());
  if (res.run.state != control::State::done) {
    std::fprintf(stderr, "kerf: sim: stopped after segment %lld: %s\n", static_cast<long long>(sum.last_executed),
                 sum.reason.c_str());
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace kerf::simulated
