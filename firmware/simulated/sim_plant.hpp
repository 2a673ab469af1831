// What the controller drives in the simulator: a link and the simulated
// machine behind it, stepped one tick at a time on the simulated clock.
// run_sim_machine() runs the controller against any plant; the Modbus board
// is one (make_modbus_plant), the CAN drives another.
#pragma once

#include <memory>
#include <string>

#include "kerf/hal/segment_link.hpp"

namespace kerf::simulated {

struct BoardFault;
struct SimMachineConfig;

class SimPlant {
 public:
  virtual ~SimPlant() = default;
  virtual hal::SegmentLink& link() = 0;
  virtual double tick_s() const = 0;  // simulated time per tick()
  virtual void tick() = 0;
  // What the machine really did (read beside the link, which may be down).
  virtual hal::BoardStatus truth() = 0;
  // False when this plant has no such fault.
  virtual bool inject(const BoardFault& f) = 0;
};

// The simulated motion board (core/motion's interpolator) behind its Modbus
// server, TCP on 127.0.0.1 or RTU on a fresh pty, and the host's link to it.
// link_watchdog_s: the board stops by itself after that long without a request.
std::unique_ptr<SimPlant> make_modbus_plant(const SimMachineConfig& cfg, double link_watchdog_s,
                                            std::string& error);

}  // namespace kerf::simulated
