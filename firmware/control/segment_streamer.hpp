// Streams a planned job through a hal::SegmentLink: start the board, push
// while it has credit, then "finish" and wait for done or a fault. A link
// failure is retried with the same sequence number (the board drops
// duplicates) until the link has been down for link_timeout_s; then it stops
// and reports the last segment the board said it executed. The board's own
// watchdog puts the machine in its safe state when the host goes silent.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "kerf/hal/segment_link.hpp"

namespace kerf::control {

struct StreamConfig {
  double link_timeout_s = 1.0;  // how long the link may stay down before giving up
  double poll_interval_s = 0.0; // between status polls while waiting (0: as fast as the link)
  double job_timeout_s = 3600.0;
};

struct StreamReport {
  bool ok = false;            // board reported done
  std::string fault;          // empty when ok
  std::uint32_t planned = 0;
  std::uint32_t sent = 0;     // segments the board acknowledged
  std::uint64_t resent = 0;   // transactions sent again
  hal::BoardStatus board{};   // the last status read
};

// on_push(seq) runs after each acknowledged push (progress, fault scripts).
StreamReport stream_job(hal::SegmentLink& link, const std::vector<hal::SegmentCommand>& segs,
                        const StreamConfig& cfg,
                        const std::function<void(std::uint32_t)>& on_push = {});

}  // namespace kerf::control
