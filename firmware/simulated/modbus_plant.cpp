// The Modbus plant: sim::MotionBoard behind sim::BoardServer, and
// hal::ModbusSegmentLink talking to it.
#include <modbus/modbus.h>

#include <algorithm>

#include "simulated/sim_machine.hpp"
#include "simulated/sim_plant.hpp"
#include "kerf/hal/modbus/modbus_link.hpp"
#include "kerf/sim/board_server.hpp"

namespace kerf::simulated {

namespace {

class ModbusPlant final : public SimPlant {
 public:
  ModbusPlant(const sim::BoardConfig& bc, std::unique_ptr<sim::SegmentExecutor> exec)
      : board_(bc, std::move(exec)), plant_(bc.start), tick_s_(bc.servo_period_s) {}

  bool open(const SimMachineConfig& cfg, double watchdog_s, std::string& error) {
    sim::ServerConfig sc;
    sc.transport = cfg.rtu ? sim::ServerConfig::Transport::rtu : sim::ServerConfig::Transport::tcp;
    sc.watchdog_s = watchdog_s;
    sc.plant = &plant_;
    // In process the link and the server trade the same frames without a
    // socket; the faults that need a socket keep it.
    const bool socket_faults = std::any_of(cfg.faults.begin(), cfg.faults.end(), [](const BoardFault& f) {
      return f.kind == BoardFaultKind::link_drop || f.kind == BoardFaultKind::link_stall;
    });
    sc.in_process = cfg.in_process && !cfg.rtu && !socket_faults;
    server_ = sim::BoardServer::start(board_, sc, error);
    if (!server_) return false;
    hal::ModbusConfig lc;
    lc.transport = cfg.rtu ? hal::ModbusConfig::Transport::rtu : hal::ModbusConfig::Transport::tcp;
    lc.port = server_->port();
    lc.device = server_->device();
    // The controller retries by cycling, so that it keeps reading its inputs
    // while the link is in trouble: one attempt per call, a short timeout.
    lc.retries = 0;
    lc.response_timeout_s = std::min(0.1, watchdog_s / 4.0);
    if (sc.in_process) lc.peer = server_.get();
    link_ = hal::ModbusSegmentLink::open(lc, error);
    return link_ != nullptr;
  }

  hal::SegmentLink& link() override { return *link_; }
  double tick_s() const override { return tick_s_; }
  void tick() override {
    board_.tick();
    plant_.step(board_.status().position, tick_s_);
  }
  hal::BoardStatus truth() override {
    hal::BoardStatus s = board_.status();
    s.actual = plant_.actual();
    return s;
  }
  bool inject(const BoardFault& f) override {
    switch (f.kind) {
      case BoardFaultKind::link_drop: server_->drop_link(f.duration_s); return true;
      case BoardFaultKind::link_stall: server_->stall(f.duration_s); return true;
      // Busy is transient: the controller sends the same request next cycle.
      case BoardFaultKind::modbus_exception:
        server_->exception_replies(3, MODBUS_EXCEPTION_SLAVE_OR_SERVER_BUSY);
        return true;
      case BoardFaultKind::crc_error: server_->corrupt_crc(3); return true;
      case BoardFaultKind::drive_fault: board_.inject_fault(hal::kFaultDrive); return true;
      case BoardFaultKind::stall: plant_.stall(0); return true;  // the x axis jams
      default: return false;  // the CAN bus's faults
    }
  }

 private:
  sim::MotionBoard board_;  // declared first: the server and the link go before it
  sim::BoardPlant plant_;   // the axes: the board's command through a lag
  double tick_s_;
  std::unique_ptr<sim::BoardServer> server_;
  std::unique_ptr<hal::ModbusSegmentLink> link_;
};

}  // namespace

std::unique_ptr<SimPlant> make_modbus_plant(const SimMachineConfig& cfg, double link_watchdog_s,
                                            std::string& error) {
  auto exec = sim::make_motion_executor(cfg.motion, error);
  if (!exec) return nullptr;
  sim::BoardConfig bc;
  bc.servo_period_s = cfg.motion.servo_period_s;
  bc.start = cfg.start;
  bc.z = cfg.z;
  bc.soft_limits = cfg.soft_limits;
  bc.keep_trace = false;  // run_sim_machine records the trace from truth()
  auto plant = std::make_unique<ModbusPlant>(bc, std::move(exec));
  if (!plant->open(cfg, link_watchdog_s, error)) return nullptr;
  return plant;
}

SimMachineResult run_sim_machine(const control::Job& job, const control::ControllerConfig& ccfg,
                                 const SimMachineConfig& mcfg, hal::Gpio& gpio, control::Journal* journal,
                                 const control::ResumePoint& from) {
  control::WholeJobSource source(job);
  return run_sim_machine(source, ccfg, mcfg, gpio, journal, from);
}

SimMachineResult run_sim_machine(control::JobSource& job, const control::ControllerConfig& ccfg,
                                 const SimMachineConfig& mcfg, hal::Gpio& gpio, control::Journal* journal,
                                 const control::ResumePoint& from) {
  SimMachineResult res;
  std::unique_ptr<SimPlant> plant = make_modbus_plant(mcfg, ccfg.link_watchdog_s, res.setup_error);
  if (!plant) return res;
  return run_sim_machine(job, ccfg, mcfg, *plant, gpio, journal, from);
}

}  // namespace kerf::simulated
