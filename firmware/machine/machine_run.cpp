#include "machine/machine_run.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <string>

#include "control/controller.hpp"
#include "control/machine_config.hpp"
#include "control/program_job.hpp"
#include "control/run_report.hpp"
#include "io/options.hpp"
#include "io/output_file.hpp"
#include "kerf/hal/rt_loop.hpp"
#include "machine/homing.hpp"
#include "machine/machine_factory.hpp"

namespace kerf::machine {

using namespace control;

namespace {

volatile std::sig_atomic_t g_signal = 0;
extern "C" void on_signal(int sig) { g_signal = sig; }

}  // namespace

int run_on_machine(const Job& job, const config::Config& cfg, hal::SegmentLink& link, hal::Gpio& gpio,
                   Journal* journal, const ResumePoint& from, bool resumed, const std::string& report,
                   bool reset_at_start, const job::GcodeProgram* program,
                   const std::vector<CutRuleNote>* cut_rules, bool dry_run, const char* homed) {
  WholeJobSource source(job);
  const JobFacts facts = [&](RunSummary& sum) {
    sum.paths = job.paths.size();
    if (program != nullptr) control::describe_program(*program, sum);
    if (cut_rules != nullptr) sum.cut_rules = *cut_rules;
    sum.forced_commits = job.forced_commits;
  };
  return run_on_machine(source, facts, cfg, link, gpio, journal, from, resumed, report, reset_at_start, dry_run, homed);
}

int run_on_machine(JobSource& job, const JobFacts& facts, const config::Config& cfg, hal::SegmentLink& link,
                   hal::Gpio& gpio, Journal* journal, const ResumePoint& from, bool resumed, const std::string& report,
                   bool reset_at_start, bool dry_run, const char* homed) {
  using io::kExitFailure;
  using io::kExitOk;
  const hal::RtSetup rt = hal::rt_setup(cfg.rt.priority, cfg.rt.lock_memory);
  if (!rt.warning.empty()) std::fprintf(stderr, "kerf: run: %s\n", rt.warning.c_str());
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);

  // The state file says homed (kerf home): the board must still say so.
  if (homed != nullptr && std::strcmp(homed, kHomedByKerfHome) == 0) {
    job::MachineState state;
    std::string error;
    if (!job::load_machine_state(cfg.machine.state, state, error) || !check_board_homed(state, link, error)) {
      std::fprintf(stderr, "kerf: run: %s\n", error.c_str());
      return kExitFailure;
    }
  }
  control::ControllerConfig ccfg = control::controller_config(cfg);
  ccfg.reset_at_start = reset_at_start;
  control::GpioOutputs outputs(gpio);  // [[gpio.output]] / [[gpio.input]]: the program's lines
  ccfg.outputs = &outputs;
  const std::unique_ptr<Controller> made = make_controller(job, ccfg, link, gpio, journal);
  Controller& ctl = *made;
  ctl.start(from);
  const char* const bench = cfg.bench.enabled ? "BENCH, " : "";
  hal::RtLoop loop(cfg.machine.cycle);
  double t0 = -1.0, next_status = 1.0, now = 0.0;
  std::uint32_t resets = 0;
  std::string refused;
  while (!ctl.finished()) {
    const double due = loop.wait_next();
    if (t0 < 0.0) t0 = due;
    if (g_signal != 0) ctl.request_stop(g_signal == SIGINT ? "stopped by SIGINT" : "stopped by SIGTERM");
    now = due - t0;
    ctl.cycle(now);
    if (ctl.report().resets != resets || ctl.report().reset_refused != refused) {  // the operator sees each reset's fate
      resets = ctl.report().resets;
      refused = ctl.report().reset_refused;
      if (!refused.empty()) std::fprintf(stderr, "kerf: run: %s\n", refused.c_str());
    }
    if (now >= next_status) {  // the operator's status line, once a second
      next_status += 1.0;
      const std::size_t n = job.segment_count();  // a stream's is known at its end
      std::fprintf(stderr, "kerf: run: %st %.0f s, %s, segment %lld of %s; %s\n", bench, now,
                   to_string(ctl.state()), static_cast<long long>(ctl.report().last_completed + 1),
                   n == JobSource::kUnknownCount ? "?" : std::to_string(n).c_str(), loop.stats().describe().c_str());
    }
  }
  const RunReport& r = ctl.report();
  RunSummary sum =
      summarise_run(r, 0, config::to_string(cfg.link.kind), resumed,
                    ctl.journal_settled() ? journal : nullptr);  // a stalled writer still owns it
  sum.simulated = false;
  facts(sum);
  sum.dry_run_option = dry_run;
  sum.torch_on = ctl.torch();
  sum.duration_s = now;  // on the loop's clock: overrun cycles are skipped, not counted
  sum.rt = loop.stats().describe();
  sum.rt_histogram = loop.stats().histogram();
  std::string json = format_run_json(sum);
  json.insert(json.find('\n') + 1, cfg.bench.enabled ? "  \"bench\": true,\n" : "  \"bench\": false,\n");
  if (homed != nullptr) json.insert(json.find('\n') + 1, std::string("  \"homed\": \"") + homed + "\",\n");
  if (!report.empty() && !io::write_output(report, json)) {
    std::fprintf(stderr, "kerf: --report: cannot write %s: %s\n", report.c_str(), std::strerror(errno));
    return kExitFailure;
  }
  std::fprintf(stdout, "%s%s", cfg.bench.enabled ? "BENCH " : "", format_run_summary(sum).c_str());
  std::fprintf(stdout, "kerf run: %s; wake-up lateness:\n%s", sum.rt.c_str(), sum.rt_histogram.c_str());
  if (r.state != State::done) {
    std::fprintf(stderr, "kerf: run: stopped after segment %lld: %s\n", static_cast<long long>(sum.last_executed),
                 r.reason.c_str());
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace kerf::machine
