// Runs every scenario in tests/scenarios (see scenario.hpp for the format) on
// the simulated machine and checks its expected outcome; scenarios that ask
// for it are then resumed from their journal and must finish the job with
// every segment cut exactly once.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include "control/fit_paths.hpp"
#include "control/machine_config.hpp"
#include "simulated/sim_machine.hpp"
#include "kerf/sim/scripted_gpio.hpp"
#include "scenario.hpp"

namespace kerf::test {
namespace {

std::vector<std::string> scenario_files() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(KERF_SCENARIO_DIR))
    if (e.path().extension() == ".toml") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

std::string torch_pattern(const std::vector<sim::TorchChange>& changes) {
  std::string s;
  for (const sim::TorchChange& c : changes) {
    if (!s.empty()) s += ' ';
    s += c.on ? "on" : "off";
  }
  return s;
}

bool parse_board_fault(const std::string& text, simulated::BoardFault& f) {
  const std::size_t at = text.find('@');
  if (at == std::string::npos) return false;
  const std::string kind = text.substr(0, at);
  if (kind == "drive-fault") f.kind = simulated::BoardFaultKind::drive_fault;
  else if (kind == "link-stall") f.kind = simulated::BoardFaultKind::link_stall;
  else if (kind == "link-drop") f.kind = simulated::BoardFaultKind::link_drop;
  else return false;
  const std::string rest = text.substr(at + 1);
  const std::size_t colon = rest.find(':');
  f.at_s = std::stod(rest.substr(0, colon));
  if (colon != std::string::npos) f.duration_s = std::stod(rest.substr(colon + 1));
  return true;
}

struct Rig {
  config::Config cfg;
  control::FittedJob fitted;
  std::string journal;
};

void prepare(const Scenario& sc, Rig& rig) {
  std::string error;
  ASSERT_TRUE(config::load(sc.config, rig.cfg, error)) << error;
  const io::PointFile in = io::read_points(sc.job);
  ASSERT_TRUE(in.ok) << io::describe_error(in);
  Status st = Status::ok;
  ASSERT_TRUE(control::fit_paths(in, rig.cfg.fit.criterion, sc.tol.value_or(rig.cfg.fit.tol), rig.cfg.cut.feed / 60.0,
                             rig.fitted, error, st))
      << error;
  rig.journal = ::testing::TempDir() + "kerf_scenario_" + std::to_string(::getpid()) + "_" +
                std::filesystem::path(sc.file).stem().string() + ".journal";
}

// The index of the first trace sample at or after t.
std::size_t sample_at(const simulated::SimMachineResult& r, double t) {
  std::size_t i = 0;
  while (i + 1 < r.trace.size() && r.trace[i].t_s < t) ++i;
  return i;
}

class ScenarioTest : public ::testing::TestWithParam<std::string> {};

TEST_P(ScenarioTest, OutcomeAsExpected) {
  Scenario sc;
  std::string error;
  ASSERT_TRUE(load_scenario(GetParam(), KERF_EXAMPLES_DIR, sc, error)) << error;
  SCOPED_TRACE(sc.file + ": " + sc.description);
  Rig rig;
  prepare(sc, rig);
  if (HasFatalFailure()) return;
  const control::Job& job = rig.fitted.job;

  sim::ScriptedGpioOptions gopts;
  gopts.limit_count = 2;
  sim::ScriptedGpio gpio(gopts);
  std::vector<sim::GpioEvent> events;
  ASSERT_TRUE(sim::parse_gpio_script(sc.gpio_script, sc.file + " [gpio]", 2, events, error)) << error;
  ASSERT_TRUE(gpio.add(events, error)) << error;
  simulated::SimMachineConfig m = simulated::sim_machine_config(rig.cfg);
  m.start = job.paths.front().start;
  for (const std::string& f : sc.faults) {
    simulated::BoardFault bf;
    ASSERT_TRUE(parse_board_fault(f, bf)) << f;
    m.faults.push_back(bf);
  }
  auto journal = control::Journal::create(rig.journal, job.id(), error);
  ASSERT_TRUE(journal) << error;
  control::ResumePoint from;
  from.from = job.paths.front().start;
  const control::ControllerConfig ccfg = control::controller_config(rig.cfg);
  const auto r = simulated::run_sim_machine(job, ccfg, m, gpio, journal.get(), from);
  ASSERT_EQ(r.setup_error, "");

  EXPECT_EQ(control::to_string(r.run.state), sc.expect.state) << r.run.reason;
  if (!sc.expect.reason.empty()) {
    EXPECT_NE(r.run.reason.find(sc.expect.reason), std::string::npos) << r.run.reason;
  }
  if (!sc.expect.torch.empty()) {
    EXPECT_EQ(torch_pattern(gpio.torch_timeline()), sc.expect.torch);
  }
  if (sc.expect.pierces) {
    EXPECT_EQ(r.run.pierces, static_cast<std::uint32_t>(*sc.expect.pierces));
  }
  // Each segment at most once, in order; whole paths counted.
  for (std::size_t i = 1; i < r.executed.size(); ++i) EXPECT_EQ(r.executed[i], r.executed[i - 1] + 1);
  EXPECT_EQ(journal->state().duplicates, 0u);
  // The journal has what the controller saw complete: everything, unless the
  // link went down and the board ran on blind until its watchdog stopped it.
  const bool link_fault = std::any_of(sc.faults.begin(), sc.faults.end(),
                                      [](const std::string& f) { return f.rfind("link-", 0) == 0; });
  if (link_fault) {
    EXPECT_LE(journal->state().executed_total, r.executed.size());
  } else {
    EXPECT_EQ(journal->state().executed_total, r.executed.size());
  }
  if (sc.expect.paths_completed) {
    long complete = 0;
    std::size_t k = 0;
    for (const control::CutPath& p : job.paths) {
      k += p.segments.size();
      if (static_cast<std::int64_t>(k) - 1 <= r.run.last_completed) ++complete;
    }
    EXPECT_EQ(complete, *sc.expect.paths_completed);
  }
  EXPECT_FALSE(gpio.torch());
  if (sc.expect.safe_stop_at) {
    const double t = *sc.expect.safe_stop_at;
    const auto& tl = gpio.torch_timeline();
    ASSERT_FALSE(tl.empty());
    EXPECT_FALSE(tl.back().on);
    EXPECT_GE(tl.back().t_s, t);
    // Same cycle: the controller reads the input and drives the torch in one cycle.
    const double within = sc.expect.torch_off_by.value_or(m.cycle_s + 1e-9);
    EXPECT_LE(tl.back().t_s, t + within) << "torch off too late";
    // Braking distance at the cut feed, plus the cycle in which the fault is seen.
    const double v = rig.cfg.cut.feed / 60.0, a = rig.cfg.machine.accel;
    const Vec2<double> at_fault = r.trace[sample_at(r, t)].pos;
    EXPECT_LE(distance(at_fault, r.run.stopped_at), v * v / (2 * a) + v * std::max(m.cycle_s, within) + 1e-3);
    EXPECT_EQ(r.trace.back().pos, r.trace[r.trace.size() - 2].pos) << "still moving at the end";
  }

  if (!sc.expect.resume) return;
  journal.reset();
  auto again = control::Journal::resume(rig.journal, job.id(), error);
  ASSERT_TRUE(again) << error;
  const control::ResumePoint rp = control::resume_point(job, again->state());
  ASSERT_FALSE(rp.done);
  sim::ScriptedGpio fresh(gopts);
  simulated::SimMachineConfig m2 = simulated::sim_machine_config(rig.cfg);
  m2.start = job.paths.front().start;  // powered up again at home
  const auto r2 = simulated::run_sim_machine(job, ccfg, m2, fresh, again.get(), rp);
  ASSERT_EQ(r2.setup_error, "");
  EXPECT_EQ(r2.run.state, control::State::done) << r2.run.reason;
  EXPECT_EQ(again->state().executed_total, job.segment_count());
  EXPECT_EQ(again->state().duplicates, 0u);
  EXPECT_TRUE(again->state().finished);
  ASSERT_FALSE(r2.executed.empty());
  EXPECT_EQ(r2.executed.front(), r.run.last_completed + 1);
  // The torch comes back on exactly where it went off (or where the first
  // uncut segment starts): nothing is cut twice, nothing is skipped.
  ASSERT_FALSE(fresh.torch_timeline().empty());
  const Vec2<double> pierce = r2.trace[sample_at(r2, fresh.torch_timeline().front().t_s)].pos;
  const Vec2<double> want = r.run.has_cut_to ? r.run.cut_to.at : job.segment_start(static_cast<std::size_t>(r.run.last_completed + 1));
  EXPECT_LE(distance(pierce, want), 1.5e-3) << "resumed at (" << pierce.x << ", " << pierce.y << ")";
  std::remove(rig.journal.c_str());
}

std::string scenario_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = std::filesystem::path(info.param).stem().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Scenarios, ScenarioTest, ::testing::ValuesIn(scenario_files()), scenario_name);

}  // namespace
}  // namespace kerf::test
