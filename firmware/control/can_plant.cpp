#include "control/can_plant.hpp"

#include "control/sim_machine.hpp"

namespace kerf::control {

hal::BoardStatus CanPlant::truth() {
  hal::BoardStatus s;
  link_->status(s);
  return s;
}

bool CanPlant::inject(const BoardFault& f) {
  if (f.kind != BoardFaultKind::drive_fault) return false;  // Modbus link faults have no CAN meaning
  link_->inject(CanFaultKind::emcy);
  return true;
}

std::unique_ptr<CanPlant> make_can_plant(const CanSimOptions& opts, std::string& error) {
  auto link = make_can_sim_link(opts, error);
  if (!link) return nullptr;
  return std::make_unique<CanPlant>(std::move(link));
}

}  // namespace kerf::control
