#include "simulated/can_plant.hpp"

#include "simulated/sim_machine.hpp"

namespace kerf::simulated {

hal::BoardStatus CanPlant::truth() {
  hal::BoardStatus s;
  link_->status(s);
  return s;
}

bool CanPlant::inject(const BoardFault& f) {
  switch (f.kind) {
    case BoardFaultKind::drive_fault:  // a drive's fault reaches the master as its EMCY
    case BoardFaultKind::emcy: link_->inject(CanFaultKind::emcy); return true;
    case BoardFaultKind::heartbeat_loss: link_->inject(CanFaultKind::heartbeat_loss); return true;
    case BoardFaultKind::bus_off: link_->inject(CanFaultKind::bus_off); return true;
    case BoardFaultKind::enable_refused: link_->inject(CanFaultKind::enable_refused); return true;
    case BoardFaultKind::stall: link_->inject(CanFaultKind::stall); return true;
    default: return false;  // Modbus link faults have no CAN meaning
  }
}

std::unique_ptr<CanPlant> make_can_plant(const CanSimOptions& opts, std::string& error) {
  auto link = make_can_sim_link(opts, error);
  if (!link) return nullptr;
  return std::make_unique<CanPlant>(std::move(link));
}

}  // namespace kerf::simulated
