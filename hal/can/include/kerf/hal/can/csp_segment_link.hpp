// hal::CspSegmentLink: hal::SegmentLink for drives that take cyclic
// positions (CiA 402 CSP). The motion board's job runs on the host, in the
// same executor a motion board runs (core/motion/board_executor.hpp: queue,
// sequence numbers, credit, state machine) over core/motion's interpolator;
// each SYNC period its setpoint goes out through a hal::AxisLink (axis 0 = x,
// 1 = y, 2 = z when CspConfig::z is set: the executor's z moves; further
// axes hold their position). status() reports like the
// board, with actual the drives' 0x6064 from their TPDO and position the
// setpoint of the SYNC that feedback was sampled at; done waits until the
// drives hold the last setpoint.
//
// Time: cycle() runs one SYNC period. Tests call it by hand (virtual time);
// run_clock() runs it on a thread, either as fast as the job allows (only
// while the queue is full or finished, so host latency cannot starve it) or
// paced by the AxisLink itself (SocketCAN: wall-clock SYNC).
#pragma once

#include <array>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "kerf/hal/axis_link.hpp"
#include "kerf/hal/segment_link.hpp"
#include "kerf/motion/board_executor.hpp"
#include "kerf/motion/interpolator_motion.hpp"
#include "kerf/motion/soft_limits.hpp"

namespace kerf::hal {

struct CspConfig {
  Vec2<double> counts_per_mm{1000.0, 1000.0};  // x, y
  double accel_mm_s2 = 2000.0;     // along the path
  double corner_angle_rad = 0.05;  // tangent turns above this are corners
  double vad = 0.9;                // thc_lock below this fraction of the cut feed
  std::size_t queue_slots = 32;    // the credit the host sees, and the look-ahead behind it
  std::size_t trace_reserve = 0;
  // A z axis (axis 2): its limits and resolution; period 0 (the default): none.
  motion::AxisLimits<double> z{};
  double z_counts_per_mm = 1000.0;
  motion::SoftLimits<double> soft_limits{};  // the executor refuses a segment outside (off: unlimited)
};

struct CspSample {
  std::uint64_t cycle = 0;
  std::uint32_t seq = 0;            // segment being executed, 0 when none
  std::int64_t target[2]{};         // counts sent this SYNC
  std::int32_t actual[2]{};         // counts the drives reported
  std::int64_t target_z = 0;        // counts sent to the z drive (0 without one)
  bool torch = false;
};

class CspSegmentLink final : public SegmentLink {
 public:
  // `axes` must be enabled (bring_up + enable) and outlive the link.
  static std::unique_ptr<CspSegmentLink> create(AxisLink& axes, const CspConfig& cfg, std::string& error);
  ~CspSegmentLink() override;

  LinkError push(const SegmentCommand& seg, BoardStatus& status) override;
  LinkError status(BoardStatus& status) override;
  LinkError command(Command c) override;
  // CiA 402 homing mode on the axis's drive (AxisLink::home), then the job
  // starts from the drive's new position.
  LinkError home(const HomeCommand& h, const std::function<bool()>& stop) override;
  std::uint64_t resends() const override { return 0; }
  const char* last_error() const override;
  // The axes the drives report homed since their power-up (read at bring-up:
  // CanOpenMaster::homed_since_power_up), bit 0 x, bit 1 y.
  void set_homed(std::uint8_t bits);

  // One SYNC period (tests drive the virtual clock with it).
  void cycle();
  // The clock thread. paced: the AxisLink waits for each SYNC itself.
  void run_clock(bool paced);
  void stop_clock();
  // Blocks until pred(status) holds or `timeout_s` of wall time pass.
  bool wait_until(const std::function<bool(const BoardStatus&)>& pred, double timeout_s);

  std::vector<CspSample> trace() const;
  std::vector<std::uint32_t> executed() const;
  AxisLink& axes() { return axes_; }

 private:
  CspSegmentLink(AxisLink& axes, const CspConfig& cfg);
  bool configure(std::string& error);
  bool has_z() const { return cfg_.z.configured(); }
  std::int32_t z_counts() const;
  bool has_work_locked() const;
  void fault_locked(std::uint16_t bit, const char* why);
  BoardStatus status_locked() const;
  void clock_loop(bool paced);

  AxisLink& axes_;
  CspConfig cfg_;
  std::vector<motion::QueuedSegment<double>> storage_;  // the interpolator's look-ahead
  motion::InterpolatorMotion<double> motion_;
  std::vector<SegmentCommand> ring_;  // the executor's queue: the credit
  std::optional<motion::BoardExecutor<double, motion::InterpolatorMotion<double>>> exec_;

  mutable std::mutex mu_;
  std::condition_variable changed_;
  bool moving_ = false;      // the head travelled last period
  bool settled_ = true;      // the drives' actual positions equal the last setpoint
  bool reset_axes_ = false;  // fault reset: the drives are reset by the next cycle
  std::int64_t target_[2]{};
  Vec2<double> position_{};  // mm: the setpoint of the SYNC the feedback is from
  Vec2<double> actual_{};    // mm: the drives' reported positions (0x6064)
  std::array<std::array<std::int32_t, 2>, 4> sent_{};  // setpoints by SYNC cycle, modulo 4
  std::vector<CspSample> trace_;
  std::vector<std::uint32_t> executed_;
  char error_[240] = "";
  std::uint8_t homed_ = 0;
  HomingState homing_ = HomingState::none;

  std::thread clock_;
  bool clock_stop_ = false;
};

}  // namespace kerf::hal
