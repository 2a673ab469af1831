// An in-process CAN bus with N simulated CiA 402 drives and the CANopen
// master on it, on the bus's virtual clock: every test is deterministic.
#pragma once

#include <gtest/gtest.h>

#include <climits>
#include <memory>
#include <stdexcept>
#include <string>

#include "kerf/hal/can/canopen_master.hpp"
#include "kerf/hal/can/csp_segment_link.hpp"
#include "kerf/hal/canopen.hpp"
#include "kerf/sim/can/virtual_can_bus.hpp"

namespace kerf::test {

struct CanRig {
  sim::VirtualCanBus bus;
  std::unique_ptr<hal::CanOpenMaster> master;

  explicit CanRig(std::size_t axes = 2, std::uint32_t sync_us = 1000, std::int32_t start = 0,
                  std::int32_t start_y = INT32_MIN, double lag_alpha = 1.0) {
    hal::CanOpenConfig cfg;
    cfg.nodes.clear();
    for (std::size_t i = 0; i < axes; ++i) {
      sim::DriveConfig d;
      d.node = static_cast<std::uint8_t>(i + 1);
      d.start = i == 1 && start_y != INT32_MIN ? start_y : start;
      d.lag_alpha = lag_alpha;
      d.following_window = 100000;
      bus.add_drive(d);
      cfg.nodes.push_back(d.node);
    }
    cfg.sync_us = sync_us;
    std::string err;
    master = hal::CanOpenMaster::create(bus.master(), cfg, err);
    if (!master) throw std::runtime_error(err);
  }
  void up() {
    ASSERT_EQ(master->bring_up(), hal::AxisError::none) << master->last_error();
    ASSERT_EQ(master->enable(), hal::AxisError::none) << master->last_error();
  }
};

// The CSP link on top of a rig that is up.
struct CspRig : CanRig {
  std::unique_ptr<hal::CspSegmentLink> link;
  explicit CspRig(std::size_t axes = 2, std::uint32_t sync_us = 1000, std::int32_t start = 0,
                  std::int32_t start_y = INT32_MIN, double lag_alpha = 1.0)
      : CanRig(axes, sync_us, start, start_y, lag_alpha) {
    up();
    std::string err;
    hal::CspConfig c;
    link = hal::CspSegmentLink::create(*master, c, err);
    if (!link) throw std::runtime_error(err);
  }
  template <class P>
  bool run_until(P pred, int max_cycles) {
    hal::BoardStatus st;
    for (int i = 0; i < max_cycles; ++i) {
      link->status(st);
      if (pred(st)) return true;
      link->cycle();
    }
    link->status(st);
    return pred(st);
  }
};

inline bool is_sdo_request(const sim::LoggedFrame& l) { return l.from_master && (l.frame.id & 0x780) == 0x600; }

}  // namespace kerf::test
