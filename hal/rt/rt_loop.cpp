// The Linux side of the real-time loop: scheduling, memory locking and the
// absolute-deadline sleep.
#include "kerf/hal/rt_loop.hpp"

#include <sched.h>
#include <sys/mman.h>
#include <time.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

#if defined(__SANITIZE_ADDRESS__)
#define KERF_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define KERF_ASAN 1
#endif
#endif

namespace kerf::hal {

namespace {

void add_warning(std::string& w, const char* text) {
  if (!w.empty()) w += "; ";
  w += text;
}

class MonotonicClock final : public RtClock {
 public:
  std::int64_t now_ns() override {
    timespec ts{};
    ::clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
  }
  void sleep_until_ns(std::int64_t deadline_ns) override {
    timespec ts{};
    ts.tv_sec = static_cast<time_t>(deadline_ns / 1'000'000'000);
    ts.tv_nsec = static_cast<long>(deadline_ns % 1'000'000'000);
    // An absolute deadline: a signal handler in between does not shift it.
    while (::clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
    }
  }
};

}  // namespace

RtClock& monotonic_clock() {
  static MonotonicClock clock;
  return clock;
}

double monotonic_s() { return static_cast<double>(monotonic_clock().now_ns()) * 1e-9; }

RtSetup rt_setup(int priority, bool lock_memory) {
  RtSetup r;
  char b[320];
  if (priority > 0) {
    // Per thread on Linux: call it from the thread that runs the loop.
    sched_param sp{};
    sp.sched_priority = priority;
    if (::sched_setscheduler(0, SCHED_FIFO, &sp) == 0) {
      r.fifo = true;
    } else if (errno == EPERM) {
      std::snprintf(b, sizeof b,
                    "rt: SCHED_FIFO priority %d not permitted (EPERM): running with normal "
                    "scheduling; run as root or give the user an rtprio limit (LimitRTPRIO= in "
                    "the systemd unit)",
                    priority);
      add_warning(r.warning, b);
    } else {
      const int err = errno;
      std::snprintf(b, sizeof b,
                    "rt: SCHED_FIFO priority %d refused (%s; valid %d..%d): running with normal "
                    "scheduling",
                    priority, std::strerror(err), ::sched_get_priority_min(SCHED_FIFO),
                    ::sched_get_priority_max(SCHED_FIFO));
      add_warning(r.warning, b);
    }
  }
  if (lock_memory) {
#ifdef KERF_ASAN
    // MCL_CURRENT would fault in AddressSanitizer's terabytes of shadow memory.
    add_warning(r.warning, "rt: mlockall skipped in an AddressSanitizer build");
#else
    if (::mlockall(MCL_CURRENT | MCL_FUTURE) == 0) {
      r.locked = true;
    } else {
      const int err = errno;
      std::snprintf(b, sizeof b,
                    "rt: mlockall failed (%s): memory may be paged out and stall the loop; run "
                    "as root or raise the memlock limit (LimitMEMLOCK=infinity in the systemd "
                    "unit)",
                    err == EPERM    ? "EPERM"
                    : err == ENOMEM ? "ENOMEM, over the memlock limit"
                                    : std::strerror(err));
      add_warning(r.warning, b);
    }
#endif
  }
  return r;
}

RtLoop::RtLoop(double period_s, RtClock& clock)
    : period_s_(period_s),
      period_ns_(period_s * 1e9 >= 1.0 ? std::llround(period_s * 1e9) : 1),
      clock_(&clock) {}

double RtLoop::wait_next() {
  const std::int64_t now = clock_->now_ns();
  if (next_ns_ == 0) {
    next_ns_ = now + period_ns_;
  } else {
    next_ns_ += period_ns_;
    if (now > next_ns_) {  // the last cycle's work ran past this deadline (and maybe more)
      const std::int64_t missed = (now - next_ns_) / period_ns_ + 1;
      next_ns_ += missed * period_ns_;
      stats_.overruns += static_cast<std::uint64_t>(missed);
    }
  }
  clock_->sleep_until_ns(next_ns_);
  stats_.record(static_cast<double>(clock_->now_ns() - next_ns_) * 1e-9);
  return static_cast<double>(next_ns_) * 1e-9;
}

}  // namespace kerf::hal
