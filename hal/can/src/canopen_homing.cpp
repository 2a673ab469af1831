// CanOpenMaster::home: CiA 402 homing mode on one drive (canopen_master.hpp).
#include <algorithm>
#include <cstdlib>

#include "kerf/hal/can/canopen_master.hpp"
#include "kerf/hal/canopen.hpp"

namespace kerf::hal {

using namespace canopen;

AxisError CanOpenMaster::homed_since_power_up(std::size_t axis, bool& homed) {
  homed = false;
  std::uint32_t sw = 0;
  if (const AxisError e = sdo_write(axis, kModeOfOperation, 0, static_cast<std::uint8_t>(kModeHoming), 1);
      e != AxisError::none)
    return e;
  const AxisError read = sdo_read(axis, kStatusword, 0, sw);
  // Left in mode 6 the drive would not run CSP: never an abort the caller may pass over.
  if (const AxisError e = sdo_write(axis, kModeOfOperation, 0, static_cast<std::uint8_t>(kModeCsp), 1);
      e != AxisError::none)
    return e == AxisError::sdo_abort ? AxisError::drive_fault : e;
  homed = read == AxisError::none && (sw & kSwHomingAttained) != 0;
  return read;
}

AxisError CanOpenMaster::home(std::size_t axis, const DriveHoming& h, DriveHomingResult& result,
                              const std::function<bool()>& stop) {
  result = DriveHomingResult::drive_error;
  if (!enabled_) return fail(AxisError::not_enabled, axis, "home before enable");
  struct Write {
    std::uint16_t index;
    std::uint8_t sub;
    std::uint32_t value;
    std::uint8_t size;
  };
  const Write setup[] = {
      {kHomingMethod, 0, static_cast<std::uint8_t>(h.method), 1},
      {kHomingSpeeds, 1, h.search_speed, 4},
      {kHomingSpeeds, 2, h.latch_speed, 4},
      {kHomeOffset, 0, static_cast<std::uint32_t>(h.home_offset), 4},
      {kModeOfOperation, 0, static_cast<std::uint8_t>(kModeHoming), 1},
  };
  for (const Write& w : setup)
    if (const AxisError e = sdo_write(axis, w.index, w.sub, w.value, w.size); e != AxisError::none) return e;
  const AxisError run = homing_cycles(axis, h, result, stop);
  // Back to CSP wherever it ended, the target at the drive's position.
  Node& n = nodes_[axis];
  n.st.controlword = kCwEnableOperation;
  if (const AxisError e = cycle(); e != AxisError::none) return e;
  if (const AxisError e = cycle(); e != AxisError::none) return e;
  for (Node& m : nodes_) m.st.target = m.st.actual;
  if (const AxisError e = sdo_write(axis, kModeOfOperation, 0, static_cast<std::uint8_t>(kModeCsp), 1);
      e != AxisError::none)
    return e;
  return run;
}

AxisError CanOpenMaster::homing_cycles(std::size_t axis, const DriveHoming& h, DriveHomingResult& result,
                                       const std::function<bool()>& stop) {
  Node& n = nodes_[axis];
  // Bit 4 low for a cycle, then high: homing starts on the rising edge.
  n.st.controlword = kCwEnableOperation;
  if (const AxisError e = cycle(); e != AxisError::none) return e;
  if (const AxisError e = cycle(); e != AxisError::none) return e;
  const std::int32_t start = n.st.actual;
  n.st.controlword = kCwEnableOperation | kCwHomingStart;
  // The longest a cycle may take: the search, then off the switch at the latch speed, and margin.
  const double period = period_s();
  const double limit_s = static_cast<double>(h.max_travel) / h.search_speed + 1000.0 / h.latch_speed + 2.0;
  const auto max_cycles = static_cast<std::uint64_t>(limit_s / period);
  bool started = false;
  for (std::uint64_t k = 0; k < max_cycles; ++k) {
    for (Node& m : nodes_) m.st.target = m.st.actual;  // the other axes hold
    if (const AxisError e = cycle(); e != AxisError::none) return e;
    const std::uint16_t sw = n.st.statusword;
    const bool fresh = n.st.feedback_cycle + 1 >= counters_.cycles;
    if (fresh && (sw & kSwTargetReached) == 0) started = true;
    const bool halt = stop && stop();
    // Halted before the travel could pass max_travel: the feedback is a
    // period old or more (homing_lead_syncs; older still when no TPDO came)
    // and the halt takes effect a period later.
    const std::uint64_t age = counters_.cycles > n.st.feedback_cycle ? counters_.cycles - n.st.feedback_cycle : 0;
    const std::uint64_t lead = std::max<std::uint64_t>(age + 1, cfg_.homing_lead_syncs);
    const double ahead = static_cast<double>(lead) * h.search_speed * period;
    const bool too_far =
        static_cast<double>(std::llabs(std::int64_t{n.st.actual} - start)) + ahead > static_cast<double>(h.max_travel);
    if (halt || too_far) {
      n.st.controlword = kCwEnableOperation | kCwHalt;
      result = halt ? DriveHomingResult::aborted : DriveHomingResult::no_switch;
      return cycle();
    }
    if (!started || !fresh) continue;
    if ((sw & kSwHomingError) != 0) return AxisError::none;  // drive_error
    if ((sw & kSwHomingAttained) != 0 && (sw & kSwTargetReached) != 0) {
      result = DriveHomingResult::attained;
      return AxisError::none;
    }
  }
  n.st.controlword = kCwEnableOperation | kCwHalt;
  result = DriveHomingResult::no_switch;
  return cycle();
}

}  // namespace kerf::hal
