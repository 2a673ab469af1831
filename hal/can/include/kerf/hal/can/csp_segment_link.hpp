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
//
// cycle() allocates nothing: the trace (one CspSample per SYNC) and the
// executed sequence numbers go to fixed-size rings (trace(), executed(): the
// last trace_capacity / executed_capacity of them) and, when sink_capacity > 0,
// also to a lock-free queue that a non-real-time thread drains (drain(), or
// run_sink()'s thread) to keep all of it. A full sink queue drops the record
// and counts it (sink_dropped()): the trace is a record, not the job.
#pragma once

#include <array>
#include <atomic>
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
#include "kerf/hal/rings.hpp"
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
  std::size_t trace_capacity = 1 << 16;    // samples kept (65 s at a 1 ms SYNC)
  std::size_t executed_capacity = 1 << 14; // sequence numbers kept
  std::size_t sink_capacity = 0;           // > 0: the sink queue (records), drained off the cycle
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

// What the sink queue carries: a sample each SYNC, an executed sequence number
// for each segment completed.
struct CspRecord {
  bool executed = false;  // true: `seq` completed; false: `sample`
  std::uint32_t seq = 0;
  CspSample sample;
};

class CspSegmentLink final : public SegmentLink {
 public:
  // `axes` must be enabled (bring_up + enable) and outlive the link.
  static std::unique_ptr<CspSegmentLink> create(AxisLink& axes, const CspConfig& cfg, std::string& error);
  ~CspSegmentLink() override;

  LinkError push(const SegmentCommand& seg, BoardStatus& status) override;
  LinkError status(BoardStatus& status) override;
  LinkError command(Command c) override;
  // CiA 402 homing mode on the axis's drive (AxisLink::home; z: the third
  // node, on a link with z), then the job starts from the drives' new position.
  LinkError home(const HomeCommand& h, const std::function<bool()>& stop) override;
  std::uint64_t resends() const override { return 0; }
  const char* last_error() const override;
  // The axes the drives report homed since their power-up (read at bring-up:
  // CanOpenMaster::homed_since_power_up), bit 0 x, bit 1 y, bit 2 z.
  void set_homed(std::uint8_t bits);

  // One SYNC period (tests drive the virtual clock with it).
  void cycle();
  // The clock thread. paced: the AxisLink waits for each SYNC itself.
  void run_clock(bool paced);
  void stop_clock();
  // Blocks until pred(status) holds or `timeout_s` of wall time pass.
  bool wait_until(const std::function<bool(const BoardStatus&)>& pred, double timeout_s);

  // The last trace_capacity samples and executed_capacity sequence numbers, oldest first.
  std::vector<CspSample> trace() const;
  std::vector<std::uint32_t> executed() const;
  std::uint64_t trace_total() const;  // samples taken since the link was made

  // The sink (sink_capacity > 0). drain(): from one non-real-time thread at a
  // time, hands every queued record to `fn`; returns how many. run_sink()
  // drains on its own thread every `period_s`; stop_sink() joins it after a
  // last drain. sink_dropped(): records refused because the queue was full.
  using SinkFn = std::function<void(const CspRecord&)>;
  std::size_t drain(const SinkFn& fn);
  void run_sink(SinkFn fn, double period_s = 0.01);
  void stop_sink();
  std::uint64_t sink_dropped() const { return sink_dropped_.load(std::memory_order_relaxed); }
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
  void record(const CspRecord& r);

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
  HistoryRing<CspSample> trace_;
  HistoryRing<std::uint32_t> executed_;
  std::unique_ptr<SpscQueue<CspRecord>> sink_;  // null without a sink
  std::atomic<std::uint64_t> sink_dropped_{0};
  std::thread sink_thread_;
  std::atomic<bool> sink_stop_{false};
  std::mutex drain_mu_;  // drain() has one consumer at a time
  char error_[240] = "";
  std::uint8_t homed_ = 0;
  HomingState homing_ = HomingState::none;

  std::thread clock_;
  bool clock_stop_ = false;
};

}  // namespace kerf::hal
