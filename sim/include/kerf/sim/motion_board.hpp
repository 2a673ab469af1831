// The simulated motion board: core/motion's board executor (the segment
// queue fed by sequence number, credit, the command state machine) over a
// SegmentExecutor, and around it what a simulator adds: a lock, a servo
// thread on simulated time, and the executed trace. The libmodbus side lives
// in board_server.hpp. Thread-safe: the server thread, the servo thread and
// test code all call in.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "kerf/hal/segment_link.hpp"
#include "kerf/motion/board_executor.hpp"
#include "kerf/motion/soft_limits.hpp"
#include "kerf/sim/board_homing.hpp"
#include "kerf/sim/segment_executor.hpp"

namespace kerf::sim {

struct TraceSample {
  double t_s;
  Vec2<double> pos;
  std::uint32_t seq;  // segment being executed, 0 when idle
  bool torch;
  bool thc_lock = true;  // the board's thc_lock this tick (speed below vad of the cut feed)
  double z = 0;          // mm (0 without a z axis)
};

struct BoardConfig {
  std::uint16_t capacity = 32;    // queue slots
  double servo_period_s = 0.001;  // simulated time per tick
  Vec2<double> start{};           // position at power-up (mm)
  std::size_t trace_reserve = 0;  // samples to reserve up front
  bool keep_trace = true;         // false: trace() holds only the power-up sample (the caller records its own)
  motion::AxisLimits<double> z{}; // the z axis (period 0: none; z moves are refused)
  double start_z = 0;             // mm
  motion::SoftLimits<double> soft_limits{};  // the executor refuses a segment outside (off: unlimited)
  // Home switches of x, y and z, in the board's power-up frame (mm); none:
  // homing that axis never finds a switch. The board powers up unhomed at
  // `start` (and `start_z`); z homes only on a board with a z axis.
  double home_switch_at[3] = {0, 0, 0};
  bool has_home_switch[3] = {false, false, false};
};

using Accept = motion::BoardAccept;

class MotionBoard {
 public:
  MotionBoard(const BoardConfig& cfg, std::unique_ptr<SegmentExecutor> executor);
  ~MotionBoard();
  MotionBoard(const MotionBoard&) = delete;
  MotionBoard& operator=(const MotionBoard&) = delete;

  // Protocol side.
  Accept accept(const hal::SegmentCommand& seg);
  bool command(std::uint16_t code);  // false: unknown code or not allowed now
  // Command 7: home one axis (x, y, or z on a board with one) from idle or
  // done; false when not allowed.
  bool home(const hal::HomeCommand& cmd);
  double last_latch() const;  // the last latch point, in the unhomed frame (tests)
  hal::BoardStatus status() const;
  void link_lost();                  // the server's watchdog: stop safely
  void inject_fault(std::uint16_t bit);  // a drive fault (hal::kFaultDrive ...) while running

  // Servo side: one tick by hand (tests), or a thread.
  void tick();
  // speed 0: as fast as possible; otherwise simulated seconds per wall second.
  void start_servo(double speed);
  void stop_servo();

  // Blocks until pred(status) holds or the wall-clock deadline passes.
  bool wait_until(const std::function<bool(const hal::BoardStatus&)>& pred, double timeout_s);

  // Blocks until simulated time reaches t_s, the board stops (done or fault)
  // or cancel() is called; true when t_s was reached.
  bool wait_sim_time(double t_s);
  void cancel_waits();

  std::vector<TraceSample> trace() const;
  std::vector<std::uint32_t> executed() const;  // sequence numbers, in execution order
  double sim_time() const;

 private:
  bool has_work_locked() const;
  double* homing_axis_locked(int axis);  // home_pos_.x, home_pos_.y or home_z_
  void home_tick_locked();
  void end_homing_locked(std::uint16_t fault_bits);
  void rebase_locked(Vec2<double> at);
  void tick_locked();
  void servo_loop(double speed);

  BoardConfig cfg_;
  std::unique_ptr<SegmentExecutor> motion_;
  std::vector<hal::SegmentCommand> ring_;  // the executor's queue
  motion::BoardExecutor<double, SegmentExecutor> exec_;
  mutable std::mutex mu_;
  std::condition_variable changed_;
  std::uint64_t ticks_ = 0;
  std::vector<TraceSample> trace_;
  std::vector<std::uint32_t> executed_;
  std::thread servo_;
  bool servo_stop_ = false;
  bool realtime_ = true;  // false: the servo thread runs as fast as possible
  bool cancel_waits_ = false;
  HomingCycle homing_;
  Vec2<double> home_pos_{};  // the axes while homing
  double home_z_ = 0;        // z while homing
  std::uint8_t homed_ = 0;
};

}  // namespace kerf::sim
