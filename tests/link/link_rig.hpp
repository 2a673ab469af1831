// A simulated motion board served over real libmodbus (127.0.0.1 ephemeral
// port or a fresh pty), and a ModbusSegmentLink connected to it.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "kerf/hal/modbus/modbus_link.hpp"
#include "kerf/sim/board_server.hpp"
#include "kerf/sim/motion_board.hpp"

namespace kerf::test {

enum class Wire { tcp, rtu };

inline const char* wire_name(const ::testing::TestParamInfo<Wire>& info) {
  return info.param == Wire::tcp ? "tcp" : "rtu";
}

struct RigOptions {
  std::uint16_t capacity = 16;
  // Long enough that a loaded machine (or ASan) never times out by itself,
  // so tests that count resends exactly see only the injected faults.
  double response_timeout_s = 0.5;
  int retries = 3;
  double watchdog_s = 0.0;
  motion::AxisLimits<double> z{};  // a z axis (none by default)
};

// For tests whose faults must run into the response timeout; they only
// assert lower bounds on resends.
inline RigOptions fast_timeouts() {
  RigOptions o;
  o.response_timeout_s = 0.05;
  return o;
}

struct LinkRig {
  std::unique_ptr<sim::MotionBoard> board;
  std::unique_ptr<sim::BoardServer> server;
  std::unique_ptr<hal::ModbusSegmentLink> link;
  hal::ModbusConfig link_cfg;

  LinkRig(Wire wire, const RigOptions& opt = {}) {
    sim::BoardConfig bc;
    bc.capacity = opt.capacity;
    bc.z = opt.z;
    board = std::make_unique<sim::MotionBoard>(bc, std::make_unique<sim::EndpointExecutor>());
    sim::ServerConfig sc;
    sc.transport = wire == Wire::tcp ? sim::ServerConfig::Transport::tcp
                                     : sim::ServerConfig::Transport::rtu;
    sc.watchdog_s = opt.watchdog_s;
    std::string err;
    server = sim::BoardServer::start(*board, sc, err);
    if (!server) throw std::runtime_error("board server: " + err);
    link_cfg.transport = wire == Wire::tcp ? hal::ModbusConfig::Transport::tcp
                                           : hal::ModbusConfig::Transport::rtu;
    link_cfg.port = server->port();
    link_cfg.device = server->device();
    link_cfg.response_timeout_s = opt.response_timeout_s;
    link_cfg.retries = opt.retries;
    link = hal::ModbusSegmentLink::open(link_cfg, err);
    if (!link) throw std::runtime_error("link: " + err);
  }
};

// Line k ends at (k, k/2) mm: every end point differs, so the trace shows the order.
inline hal::SegmentCommand line_to(std::uint32_t seq) {
  hal::SegmentCommand s;
  s.seq = seq;
  s.kind = SegmentKind::line;
  s.end = {static_cast<double>(seq), static_cast<double>(seq) / 2.0};
  s.feed = 50.0;
  return s;
}

inline std::vector<hal::SegmentCommand> job(std::uint32_t n) {
  std::vector<hal::SegmentCommand> v;
  for (std::uint32_t k = 1; k <= n; ++k) v.push_back(line_to(k));
  return v;
}

inline std::vector<std::uint32_t> one_to(std::uint32_t n) {
  std::vector<std::uint32_t> v;
  for (std::uint32_t k = 1; k <= n; ++k) v.push_back(k);
  return v;
}

}  // namespace kerf::test
