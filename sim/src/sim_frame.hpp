// Pieces of the board server that work on raw Modbus frames: queueing the
// segment slots of a write, and the reply mutations that fault injection uses.
#pragma once

#include <cstdint>

#include "kerf/sim/motion_board.hpp"

namespace kerf::sim {

// Queues the slots written at `addr` (nb registers, big-endian bytes).
// Returns 0 or the Modbus exception code to answer with.
int write_slots(MotionBoard& board, int addr, int nb, const std::uint8_t* data, int bytes);

enum class FrameKind : std::uint8_t { rtu, tcp };

std::uint16_t crc16(const std::uint8_t* p, int n);  // Modbus RTU CRC (poly 0xA001, init 0xFFFF)
// Each returns the new frame length.
int frame_wrong_unit(FrameKind kind, std::uint8_t* r, int n);
int frame_short(FrameKind kind, std::uint8_t* r, int n);  // read replies lose one register
int frame_bad_crc(std::uint8_t* r, int n);

}  // namespace kerf::sim
