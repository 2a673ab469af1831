#include "kerf/hal/modbus/modbus_link.hpp"

#include <modbus/modbus.h>

#include <poll.h>
#include <sys/socket.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "kerf/hal/modbus/register_map.hpp"

namespace kerf::hal {

namespace map = modbus_map;

const char* to_string(LinkError e) {
  switch (e) {
    case LinkError::none: return "ok";
    case LinkError::timeout: return "timeout";
    case LinkError::exception: return "Modbus exception";
    case LinkError::malformed: return "malformed reply";
    case LinkError::disconnected: return "disconnected";
    case LinkError::rejected: return "rejected by the board";
    case LinkError::busy: return "board busy";
  }
  return "unknown";
}

namespace {

bool is_exception(int err) { return err >= EMBXILFUN && err <= EMBXGTAR; }
// Busy and acknowledge say "ask again"; every other exception is final.
bool is_transient_exception(int err) { return err == EMBXSBUSY || err == EMBXACK; }
bool is_malformed(int err) {
  return err == EMBBADCRC || err == EMBBADDATA || err == EMBBADEXC || err == EMBBADSLAVE ||
         err == EMBMDATA || err == EMBUNKEXC;
}

}  // namespace

ModbusSegmentLink::ModbusSegmentLink(const ModbusConfig& cfg) : cfg_(cfg) {}

ModbusSegmentLink::~ModbusSegmentLink() {
  if (ctx_ != nullptr) {
    modbus_close(ctx_);
    modbus_free(ctx_);
  }
}

std::unique_ptr<ModbusSegmentLink> ModbusSegmentLink::open(const ModbusConfig& cfg,
                                                           std::string& error) {
  if (cfg.unit < 1 || cfg.unit > 247 || cfg.retries < 0 || !(cfg.response_timeout_s > 0.0)) {
    error = "bad Modbus configuration (unit 1..247, retries >= 0, timeout > 0)";
    return nullptr;
  }
  std::unique_ptr<ModbusSegmentLink> link(new ModbusSegmentLink(cfg));
  link->ctx_ = cfg.transport == ModbusConfig::Transport::tcp
                   ? modbus_new_tcp(cfg.host.c_str(), cfg.port)
                   : modbus_new_rtu(cfg.device.c_str(), cfg.baud, 'N', 8, 1);
  if (link->ctx_ == nullptr) {
    error = std::string("cannot create the Modbus context: ") + modbus_strerror(errno);
    return nullptr;
  }
  modbus_set_slave(link->ctx_, cfg.unit);
  if (cfg.peer != nullptr && cfg.transport == ModbusConfig::Transport::tcp) {
    link->connected_ = true;  // in process: no socket to connect
    return link;
  }
  const auto us = static_cast<long>(cfg.response_timeout_s * 1e6);
  modbus_set_response_timeout(link->ctx_, static_cast<std::uint32_t>(us / 1000000),
                              static_cast<std::uint32_t>(us % 1000000));
  if (modbus_connect(link->ctx_) == -1) {
    error = std::string("cannot connect: ") + modbus_strerror(errno);
    return nullptr;
  }
  link->connected_ = true;
  return link;
}

LinkError ModbusSegmentLink::fail(LinkError e, const char* what, int err) {
  std::snprintf(error_, sizeof error_, "%s: %s (%s)", what, to_string(e),
                err != 0 ? modbus_strerror(err) : "reply content");
  return e;
}

namespace {
int u16(const std::uint8_t* p) { return (p[0] << 8) | p[1]; }
void put16(std::uint8_t* p, int v) {
  p[0] = static_cast<std::uint8_t>(v >> 8);
  p[1] = static_cast<std::uint8_t>(v & 0xFF);
}
int set_errno(int e) {
  errno = e;
  return -1;
}
}  // namespace

int ModbusSegmentLink::exchange(const std::uint8_t* pdu, int n, int nread, std::uint16_t* out) {
  const bool tcp = cfg_.transport == ModbusConfig::Transport::tcp;
  const int fc = pdu[0];
  if (tcp) {  // the MBAP header is ours so the transaction id is known
    std::uint8_t frame[MODBUS_TCP_MAX_ADU_LENGTH];
    tid_ = static_cast<std::uint16_t>(tid_ + 1);
    put16(frame, tid_);
    put16(frame + 2, 0);
    put16(frame + 4, n + 1);
    frame[6] = static_cast<std::uint8_t>(cfg_.unit);
    std::memcpy(frame + 7, pdu, static_cast<std::size_t>(n));
    const auto len = static_cast<ssize_t>(n + 7);
    if (cfg_.peer != nullptr) {  // in process: the same frames, no socket
      std::uint8_t r[MODBUS_TCP_MAX_ADU_LENGTH];
      return check_reply(r, cfg_.peer->answer(frame, n + 7, r, sizeof r), fc, pdu, nread, out);
    }
    if (::send(modbus_get_socket(ctx_), frame, static_cast<std::size_t>(len), MSG_NOSIGNAL) != len)
      return -1;
  } else {
    std::uint8_t raw[MODBUS_RTU_MAX_ADU_LENGTH];
    raw[0] = static_cast<std::uint8_t>(cfg_.unit);
    std::memcpy(raw + 1, pdu, static_cast<std::size_t>(n));
    if (modbus_send_raw_request(ctx_, raw, n + 1) == -1) return -1;
  }
  std::uint8_t r[MODBUS_TCP_MAX_ADU_LENGTH];
  int rn = 0;
  for (;;) {  // TCP: skip late replies to earlier requests, within the timeout
    rn = modbus_receive_confirmation(ctx_, r);
    if (rn == -1) return -1;
    if (rn == 0) return set_errno(EMBBADSLAVE);  // RTU: libmodbus ignored another unit's frame
    if (!tcp || u16(r) == tid_) break;
  }
  return check_reply(r, rn, fc, pdu, nread, out);
}

int ModbusSegmentLink::check_reply(const std::uint8_t* r, int rn, int fc, const std::uint8_t* pdu, int nread,
                                   std::uint16_t* out) {
  if (rn < 0) return -1;
  const bool tcp = cfg_.transport == ModbusConfig::Transport::tcp;
  if (tcp && (rn < 7 || u16(r) != tid_)) return set_errno(EMBBADDATA);
  const int h = tcp ? 7 : 1;
  const int tail = tcp ? 0 : 2;  // RTU CRC, already checked by libmodbus
  if (tcp && (u16(r + 2) != 0 || u16(r + 4) != rn - 6)) return set_errno(EMBBADDATA);
  if (r[h - 1] != cfg_.unit) return set_errno(EMBBADSLAVE);
  if (rn < h + 2 + tail) return set_errno(EMBBADDATA);
  if (r[h] == (fc | 0x80)) return set_errno(static_cast<int>(MODBUS_ENOBASE) + r[h + 1]);
  if (r[h] != fc) return set_errno(EMBBADDATA);
  if (nread > 0) {
    if (r[h + 1] != 2 * nread || rn != h + 2 + 2 * nread + tail) return set_errno(EMBBADDATA);
    for (int i = 0; i < nread; ++i) out[i] = static_cast<std::uint16_t>(u16(r + h + 2 + 2 * i));
    return nread;
  }
  // FC06 and FC16 echo the address and the value or count.
  if (rn != h + 5 + tail || std::memcmp(r + h + 1, pdu + 1, 4) != 0) return set_errno(EMBBADDATA);
  return 0;
}

void ModbusSegmentLink::drain() {
  if (cfg_.peer != nullptr) return;  // in process: nothing in flight
  const int fd = modbus_get_socket(ctx_);
  const int ms = static_cast<int>(cfg_.response_timeout_s * 1000.0) + 1;
  for (int i = 0; i < 16; ++i) {
    modbus_flush(ctx_);
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, ms) <= 0) return;
  }
}

template <class F>
LinkError ModbusSegmentLink::transact(Op op, F&& attempt) {
  static constexpr const char* kWhat[] = {"push", "status", "command", "home"};
  const char* what = kWhat[static_cast<int>(op)];
  LinkError last = LinkError::timeout;
  int last_err = ETIMEDOUT;
  for (int i = 0; i <= cfg_.retries; ++i) {
    if (i > 0 && op == Op::push) ++resends_;
    if (!connected_) {
      if (modbus_connect(ctx_) == -1) {
        last = LinkError::disconnected;
        last_err = errno;
        continue;
      }
      connected_ = true;
      ++reconnects_;
    }
    if (attempt() != -1) return LinkError::none;
    const int err = errno;
    last_err = err;
    if (is_exception(err)) {
      last = LinkError::busy;
      if (is_transient_exception(err)) continue;
      // The board's own refusals: a sequence gap, no credit, a bad value.
      if (err == EMBXILVAL || err == EMBXILADD) return fail(LinkError::rejected, what, err);
      return fail(LinkError::exception, what, err);
    }
    if (err == ETIMEDOUT || is_malformed(err)) {
      last = err == ETIMEDOUT ? LinkError::timeout : LinkError::malformed;
      drain();
      continue;
    }
    last = LinkError::disconnected;  // reset, broken pipe, closed socket, EIO on a tty
    if (cfg_.peer != nullptr) continue;  // in process: no connection to renew
    modbus_close(ctx_);
    connected_ = false;
  }
  return fail(last, what, last_err);
}

LinkError ModbusSegmentLink::push(const SegmentCommand& seg, BoardStatus& st) {
  return push_many(&seg, 1, st);
}

LinkError ModbusSegmentLink::push_many(const SegmentCommand* segs, int n, BoardStatus& st) {
  if (n < 1 || n > map::kMaxSlotsPerWrite) return fail(LinkError::rejected, "push", EINVAL);
  // FC23: read the status block, write n slots; the board writes first.
  std::uint8_t pdu[10 + 2 * map::kSlotRegs * map::kMaxSlotsPerWrite];
  const int nregs = n * map::kSlotRegs;
  pdu[0] = MODBUS_FC_WRITE_AND_READ_REGISTERS;
  put16(pdu + 1, map::kStatusAddr);
  put16(pdu + 3, map::kStatusRegs);
  put16(pdu + 5, map::kSlotAddr);
  put16(pdu + 7, nregs);
  pdu[9] = static_cast<std::uint8_t>(2 * nregs);
  for (int k = 0; k < n; ++k) {
    std::uint16_t slot[map::kSlotRegs];
    if (!map::encode_slot(segs[k], slot)) {
      std::snprintf(error_, sizeof error_, "push: segment %u does not fit the register map",
                    static_cast<unsigned>(segs[k].seq));
      return LinkError::rejected;
    }
    for (int i = 0; i < map::kSlotRegs; ++i) put16(pdu + 10 + 2 * (k * map::kSlotRegs + i), slot[i]);
  }
  std::uint16_t regs[map::kStatusRegs];
  // RTU has no transaction id: a late reply to an earlier request looks valid.
  // The status it carries must show this push's last sequence number, or the
  // reply is not ours: drain and resend (the board drops what it already has).
  const LinkError e = transact(Op::push, [&] {
    if (exchange(pdu, 10 + 2 * nregs, map::kStatusRegs, regs) == -1) return -1;
    if (!map::decode_status(regs, st) || st.last_accepted < segs[n - 1].seq)
      return set_errno(EMBBADDATA);
    return 0;
  });
  return e;
}

LinkError ModbusSegmentLink::status(BoardStatus& st) {
  std::uint8_t pdu[5] = {MODBUS_FC_READ_HOLDING_REGISTERS, 0, 0, 0, 0};
  put16(pdu + 1, map::kStatusAddr);
  put16(pdu + 3, map::kStatusRegs);
  std::uint16_t regs[map::kStatusRegs];
  return transact(Op::status, [&] {
    if (exchange(pdu, 5, map::kStatusRegs, regs) == -1) return -1;
    return map::decode_status(regs, st) ? 0 : set_errno(EMBBADDATA);
  });
}

LinkError ModbusSegmentLink::command(Command c) {
  std::uint8_t pdu[5] = {MODBUS_FC_WRITE_SINGLE_REGISTER, 0, 0, 0, 0};
  put16(pdu + 1, map::kCommandAddr);
  put16(pdu + 3, static_cast<int>(c));
  return transact(Op::command, [&] { return exchange(pdu, 5, 0, nullptr); });
}

LinkError ModbusSegmentLink::home(const HomeCommand& h, const std::function<bool()>&) {
  std::uint16_t block[map::kHomeRegs];
  if (!map::encode_home(h, block)) return fail(LinkError::rejected, "home", EINVAL);
  std::uint8_t pdu[6 + 2 * map::kHomeRegs];
  pdu[0] = MODBUS_FC_WRITE_MULTIPLE_REGISTERS;
  put16(pdu + 1, map::kHomeAddr);
  put16(pdu + 3, map::kHomeRegs);
  pdu[5] = static_cast<std::uint8_t>(2 * map::kHomeRegs);
  for (int i = 0; i < map::kHomeRegs; ++i) put16(pdu + 6 + 2 * i, block[i]);
  const LinkError e = transact(Op::home, [&] { return exchange(pdu, 6 + 2 * map::kHomeRegs, 0, nullptr); });
  if (e != LinkError::none) return e;
  std::uint8_t cmd[5] = {MODBUS_FC_WRITE_SINGLE_REGISTER, 0, 0, 0, 0};
  put16(cmd + 1, map::kCommandAddr);
  put16(cmd + 3, map::kCommandHome);
  return transact(Op::home, [&] { return exchange(cmd, 5, 0, nullptr); });
}

}  // namespace kerf::hal
