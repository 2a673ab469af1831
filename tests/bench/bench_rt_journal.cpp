// The real-time loop's lateness under load, with the journal written in the
// cycle (the old way: fdatasync for each completed segment, journal_inline)
// and through the journal writer thread (queued). Each mode runs `kerf run`'s
// loop (hal::RtLoop at the period, Controller::cycle) for S seconds on a job
// of short segments (one completes every few cycles) against the simulated
// board over loopback Modbus, with N busy threads (or stress-ng's CPU load
// when installed, --stress-ng). Prints, per mode: cycles, overruns, wake-up
// lateness p50/p99/max and the cycle's own time p50/p99/max (exact, from
// every cycle), the cycles that took longer than the period, and the
// segments journaled. A figure for the notes; it asserts nothing.
//
// usage: kerf_bench_rt_journal [--seconds S] [--period-ms P] [--busy N] [--dir D] [--stress-ng]
#include <pthread.h>
#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "control/controller.hpp"
#include "kerf/hal/rt_loop.hpp"
#include "simulated/sim_machine.hpp"
#include "simulated/sim_plant.hpp"

namespace {

using namespace kerf;

struct Figures {
  std::vector<double> late_us, body_us;
  std::uint64_t overruns = 0;
  std::int64_t journaled = 0;
  std::string stop;
};

class QuietGpio final : public hal::Gpio {
 public:
  bool read(double now_s, hal::GpioInputs& in) override {
    now_ = now_s;
    in = hal::GpioInputs{};
    in.arc_ok = torch_ && now_s >= on_t_ + 0.02;
    return true;
  }
  bool set_torch(bool on) override {
    if (on && !torch_) on_t_ = now_;
    torch_ = on;
    return true;
  }
  const char* last_error() const override { return ""; }

 private:
  double now_ = 0, on_t_ = 0;
  bool torch_ = false;
};

// One straight path of 0.25 mm segments at 100 mm/s (one completes every
// 2.5 ms), long enough for `seconds`.
control::Job straight(double seconds) {
  control::Job job;
  control::CutPath p;
  const std::size_t n = static_cast<std::size_t>(seconds * 100.0 / 0.25 * 1.5) + 10;
  for (std::size_t k = 1; k <= n; ++k) {
    hal::SegmentCommand s;
    s.kind = SegmentKind::line;
    s.end = {0.25 * static_cast<double>(k), 0.0};
    s.feed = 100.0;
    p.segments.push_back(s);
  }
  job.paths.push_back(p);
  return job;
}

double pct(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())))];
}

Figures run_mode(bool inline_journal, double seconds, double period_s, const std::string& dir) {
  Figures f;
  const control::Job job = straight(seconds);
  const std::string path = dir + "/kerf_bench_rt_journal_" + std::to_string(::getpid()) + ".journal";
  std::string err;
  auto journal = control::Journal::create(path, job.id(), err);
  if (!journal) {
    std::fprintf(stderr, "kerf_bench_rt_journal: %s\n", err.c_str());
    std::exit(1);
  }
  simulated::SimMachineConfig m;
  m.cycle_s = period_s;
  control::ControllerConfig cfg;
  cfg.pierce_delay_s = 0.05;
  cfg.journal_inline = inline_journal;
  auto plant = simulated::make_modbus_plant(m, cfg.link_watchdog_s, err);
  if (!plant) {
    std::fprintf(stderr, "kerf_bench_rt_journal: %s\n", err.c_str());
    std::exit(1);
  }
  QuietGpio gpio;
  control::Controller ctl(job, cfg, plant->link(), gpio, journal.get());
  ctl.start({});
  const long ticks = std::max(1L, std::lround(period_s / plant->tick_s()));
  const std::size_t expected = static_cast<std::size_t>(seconds / period_s) + 1000;
  f.late_us.reserve(expected);
  f.body_us.reserve(expected);
  hal::RtLoop loop(period_s);
  double t0 = -1;
  while (!ctl.finished()) {
    const double due = loop.wait_next();
    f.late_us.push_back((hal::monotonic_s() - due) * 1e6);
    if (t0 < 0) t0 = due;
    if (due - t0 > seconds) ctl.request_stop("the benchmark's time is up");
    const double b0 = hal::monotonic_s();
    ctl.cycle(due - t0);
    f.body_us.push_back((hal::monotonic_s() - b0) * 1e6);
    for (long i = 0; i < ticks; ++i) plant->tick();
  }
  f.overruns = loop.stats().overruns;
  f.journaled = ctl.report().last_completed + 1;
  f.stop = ctl.report().reason;
  std::remove(path.c_str());
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  double seconds = 5.0, period_ms = 1.0;
  int busy = 2;
  bool stress = false;
  std::string dir = "/tmp";
  for (int i = 1; i < argc; ++i) {
    const bool has = i + 1 < argc;
    if (std::strcmp(argv[i], "--seconds") == 0 && has) seconds = std::atof(argv[++i]);
    else if (std::strcmp(argv[i], "--period-ms") == 0 && has) period_ms = std::atof(argv[++i]);
    else if (std::strcmp(argv[i], "--busy") == 0 && has) busy = std::atoi(argv[++i]);
    else if (std::strcmp(argv[i], "--dir") == 0 && has) dir = argv[++i];
    else if (std::strcmp(argv[i], "--stress-ng") == 0) stress = true;
    else {
      std::fprintf(stderr, "usage: %s [--seconds S] [--period-ms P] [--busy N] [--dir D] [--stress-ng]\n", argv[0]);
      return 2;
    }
  }
  if (!(seconds > 0) || !(period_ms > 0) || busy < 0) {
    std::fprintf(stderr, "kerf_bench_rt_journal: seconds and period must be > 0, busy >= 0\n");
    return 2;
  }
  const hal::RtSetup setup = hal::rt_setup(80, true);
  if (!setup.warning.empty()) std::fprintf(stderr, "%s\n", setup.warning.c_str());
  // The load: stress-ng's CPU workers, or busy threads.
  std::atomic<bool> stop{false};
  std::vector<std::thread> load;
  pid_t stress_pid = -1;
  if (stress) {
    stress_pid = ::fork();
    if (stress_pid == 0) {
      const std::string n = std::to_string(busy);
      ::execlp("stress-ng", "stress-ng", "--cpu", n.c_str(), "--quiet", static_cast<char*>(nullptr));
      ::_exit(127);
    }
  } else {
    for (int i = 0; i < busy; ++i)
      load.emplace_back([&stop] {
        sched_param sp{};  // ordinary load: not the SCHED_FIFO policy this thread inherits
        pthread_setschedparam(pthread_self(), SCHED_OTHER, &sp);
        volatile std::uint64_t x = 0;
        while (!stop.load(std::memory_order_relaxed)) x = x + 1;
      });
  }
  std::printf("rt journal bench: period %.3f ms, %.1f s per mode, load %d %s, SCHED_FIFO %s, memory %s, journal in %s\n",
              period_ms, seconds, busy, stress ? "stress-ng --cpu workers" : "busy threads", setup.fifo ? "yes" : "no",
              setup.locked ? "locked" : "not locked", dir.c_str());
  std::printf("%-24s %7s %8s %22s %22s %9s %9s\n", "journal", "cycles", "overruns", "late p50/p99/max us",
              "cycle p50/p99/max us", "cycle>P", "segments");
  std::fflush(stdout);
  for (const bool inline_journal : {true, false}) {
    const Figures f = run_mode(inline_journal, seconds, period_ms * 1e-3, dir);
    char late[64], body[64];
    std::snprintf(late, sizeof late, "%.0f / %.0f / %.0f", pct(f.late_us, 0.5), pct(f.late_us, 0.99),
                  pct(f.late_us, 1.0));
    std::snprintf(body, sizeof body, "%.0f / %.0f / %.0f", pct(f.body_us, 0.5), pct(f.body_us, 0.99),
                  pct(f.body_us, 1.0));
    const auto over = std::count_if(f.body_us.begin(), f.body_us.end(), [&](double b) { return b > period_ms * 1e3; });
    std::printf("%-24s %7zu %8llu %22s %22s %9ld %9lld\n",
                inline_journal ? "inline fdatasync (old)" : "writer thread (queued)", f.late_us.size(),
                static_cast<unsigned long long>(f.overruns), late, body, static_cast<long>(over),
                static_cast<long long>(f.journaled));
    std::fflush(stdout);
  }
  stop.store(true);
  for (auto& t : load) t.join();
  if (stress_pid > 0) {
    ::kill(stress_pid, SIGTERM);
    ::waitpid(stress_pid, nullptr, 0);
  }
  return 0;
}
