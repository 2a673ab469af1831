// The homing tests' bench: a simulated board (its home switches in the
// BoardConfig) served over TCP or RTU, and the Modbus link to it.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

#include "link_rig.hpp"

namespace kerf::test {

struct HomeBench {
  std::unique_ptr<sim::MotionBoard> board;
  std::unique_ptr<sim::BoardServer> server;
  std::unique_ptr<hal::ModbusSegmentLink> link;

  HomeBench(Wire wire, const sim::BoardConfig& bc, std::unique_ptr<sim::SegmentExecutor> exec) {
    board = std::make_unique<sim::MotionBoard>(bc, std::move(exec));
    sim::ServerConfig sc;
    sc.transport = wire == Wire::tcp ? sim::ServerConfig::Transport::tcp : sim::ServerConfig::Transport::rtu;
    std::string err;
    server = sim::BoardServer::start(*board, sc, err);
    if (!server) throw std::runtime_error(err);
    hal::ModbusConfig lc;
    lc.transport = wire == Wire::tcp ? hal::ModbusConfig::Transport::tcp : hal::ModbusConfig::Transport::rtu;
    lc.port = server->port();
    lc.device = server->device();
    lc.response_timeout_s = 0.5;
    link = hal::ModbusSegmentLink::open(lc, err);
    if (!link) throw std::runtime_error(err);
  }

  // Polls the board until its homing cycle is no longer searching, backing off or latching.
  hal::BoardStatus wait_homing_end() {
    hal::BoardStatus st;
    for (int i = 0; i < 2000; ++i) {
      EXPECT_EQ(link->status(st), hal::LinkError::none);
      if (st.homing != hal::HomingState::search && st.homing != hal::HomingState::backoff &&
          st.homing != hal::HomingState::latch)
        return st;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ADD_FAILURE() << "homing never ended";
    return st;
  }
};

}  // namespace kerf::test
