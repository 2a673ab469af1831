#include "control/segment_streamer.hpp"

#include <chrono>
#include <cstdio>
#include <thread>

namespace kerf::control {

namespace {

using clock = std::chrono::steady_clock;
double since(clock::time_point t) { return std::chrono::duration<double>(clock::now() - t).count(); }

bool transient(hal::LinkError e) {
  return e == hal::LinkError::timeout || e == hal::LinkError::disconnected ||
         e == hal::LinkError::malformed || e == hal::LinkError::busy;  // other exceptions are final
}

// Retries `op` while the link fails transiently, for at most link_timeout_s.
template <class Op>
bool with_link(hal::SegmentLink& link, const StreamConfig& cfg, StreamReport& rep, Op op) {
  const auto first = clock::now();
  for (;;) {
    const hal::LinkError e = op();
    if (e == hal::LinkError::none) return true;
    if (!transient(e)) {
      rep.fault = link.last_error();
      return false;
    }
    if (since(first) > cfg.link_timeout_s) {
      char msg[300];
      std::snprintf(msg, sizeof msg, "link down for more than %g s: %s", cfg.link_timeout_s,
                    link.last_error());
      rep.fault = msg;
      return false;
    }
    ++rep.resent;
  }
}

bool board_fault(const hal::BoardStatus& st, StreamReport& rep) {
  if (st.state != hal::BoardState::fault) return false;
  char msg[120];
  std::snprintf(msg, sizeof msg, "board fault (bits 0x%04x)", static_cast<unsigned>(st.faults));
  rep.fault = msg;
  return true;
}

}  // namespace

StreamReport stream_job(hal::SegmentLink& link, const std::vector<hal::SegmentCommand>& segs,
                        const StreamConfig& cfg,
                        const std::function<void(std::uint32_t)>& on_push) {
  StreamReport rep;
  rep.planned = static_cast<std::uint32_t>(segs.size());
  const std::uint64_t resends_before = link.resends();
  hal::BoardStatus& st = rep.board;
  auto finish = [&](bool ok) {
    rep.ok = ok;
    rep.resent += link.resends() - resends_before;
    return rep;
  };
  if (!with_link(link, cfg, rep, [&] { return link.status(st); })) return finish(false);
  if (board_fault(st, rep)) return finish(false);
  if (st.state == hal::BoardState::idle &&
      !with_link(link, cfg, rep, [&] { return link.command(hal::Command::start); }))
    return finish(false);
  const auto t0 = clock::now();
  std::size_t next = 0;
  while (next < segs.size()) {
    if (st.credit == 0) {  // wait for the board to free a slot
      if (cfg.poll_interval_s > 0.0)
        std::this_thread::sleep_for(std::chrono::duration<double>(cfg.poll_interval_s));
      if (!with_link(link, cfg, rep, [&] { return link.status(st); })) return finish(false);
    } else {
      if (!with_link(link, cfg, rep, [&] { return link.push(segs[next], st); }))
        return finish(false);
      ++next;
      rep.sent = static_cast<std::uint32_t>(next);
      if (on_push) on_push(segs[next - 1].seq);
    }
    if (board_fault(st, rep)) return finish(false);
    if (since(t0) > cfg.job_timeout_s) {
      rep.fault = "job timeout";
      return finish(false);
    }
  }
  if (!with_link(link, cfg, rep, [&] { return link.command(hal::Command::finish); }))
    return finish(false);
  while (st.state != hal::BoardState::done) {
    if (cfg.poll_interval_s > 0.0)
      std::this_thread::sleep_for(std::chrono::duration<double>(cfg.poll_interval_s));
    if (!with_link(link, cfg, rep, [&] { return link.status(st); })) return finish(false);
    if (board_fault(st, rep)) return finish(false);
    if (since(t0) > cfg.job_timeout_s) {
      rep.fault = "job timeout";
      return finish(false);
    }
  }
  return finish(true);
}

}  // namespace kerf::control
