#include "kerf/hal/modbus/modbus_link.hpp"

#include <modbus/modbus.h>

#include <cerrno>
#include <cstdio>

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

template <class F>
LinkError ModbusSegmentLink::transact(Op op, F&& attempt) {
  static constexpr const char* kWhat[] = {"push", "status", "command"};
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
      last = LinkError::exception;
      if (is_transient_exception(err)) continue;
      // The board's own refusals: a sequence gap, no credit, a bad value.
      if (err == EMBXILVAL || err == EMBXILADD) return fail(LinkError::rejected, what, err);
      return fail(LinkError::exception, what, err);
    }
    if (err == ETIMEDOUT || is_malformed(err)) {
      last = err == ETIMEDOUT ? LinkError::timeout : LinkError::malformed;
      modbus_flush(ctx_);  // a late or broken reply must not answer the resend
      continue;
    }
    last = LinkError::disconnected;  // reset, broken pipe, closed socket, EIO on a tty
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
  std::uint16_t slots[map::kSlotRegs * map::kMaxSlotsPerWrite];
  for (int k = 0; k < n; ++k) {
    if (!map::encode_slot(segs[k], slots + k * map::kSlotRegs)) {
      std::snprintf(error_, sizeof error_, "push: segment %u does not fit the register map",
                    static_cast<unsigned>(segs[k].seq));
      return LinkError::rejected;
    }
  }
  std::uint16_t regs[map::kStatusRegs];
  const LinkError e = transact(Op::push, [&] {
    return modbus_write_and_read_registers(ctx_, map::kSlotAddr, n * map::kSlotRegs, slots,
                                           map::kStatusAddr, map::kStatusRegs, regs);
  });
  if (e != LinkError::none) return e;
  if (!map::decode_status(regs, st)) return fail(LinkError::malformed, "push", 0);
  if (st.last_accepted < segs[n - 1].seq) {
    std::snprintf(error_, sizeof error_, "push: the board did not record segment %u",
                  static_cast<unsigned>(segs[n - 1].seq));
    return LinkError::malformed;
  }
  return LinkError::none;
}

LinkError ModbusSegmentLink::status(BoardStatus& st) {
  std::uint16_t regs[map::kStatusRegs];
  const LinkError e = transact(Op::status, [&] {
    return modbus_read_registers(ctx_, map::kStatusAddr, map::kStatusRegs, regs);
  });
  if (e != LinkError::none) return e;
  if (!map::decode_status(regs, st)) return fail(LinkError::malformed, "status", 0);
  return LinkError::none;
}

LinkError ModbusSegmentLink::command(Command c) {
  return transact(Op::command, [&] {
    return modbus_write_register(ctx_, map::kCommandAddr, static_cast<int>(c));
  });
}

}  // namespace kerf::hal
