#include "kerf/hal/can_bus.hpp"

namespace kerf::hal {

const char* to_string(CanResult r) {
  switch (r) {
    case CanResult::ok: return "ok";
    case CanResult::timeout: return "timeout";
    case CanResult::queue_full: return "send queue full";
    case CanResult::bus_off: return "bus-off";
    case CanResult::io_error: return "I/O error";
  }
  return "?";
}

const char* to_string(BusState s) {
  switch (s) {
    case BusState::active: return "error-active";
    case BusState::warning: return "error-warning";
    case BusState::passive: return "error-passive";
    case BusState::bus_off: return "bus-off";
  }
  return "?";
}

}  // namespace kerf::hal
