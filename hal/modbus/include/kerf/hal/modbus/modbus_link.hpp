// hal::SegmentLink over Modbus (libmodbus), TCP or RTU, speaking kerf's
// motion-board register map (REGISTERS.md). A push is one FC23 transaction:
// it writes the segment slot and reads back the status block, so credit comes
// with every write. Failed transactions are flushed, reconnected if the link
// dropped, and resent with the same sequence number: the board drops a
// number it already has, so a resend never runs a segment twice.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "kerf/hal/segment_link.hpp"

typedef struct _modbus modbus_t;  // NOLINT: libmodbus's own declaration

namespace kerf::hal {

// A Modbus TCP peer in this process (the simulator's board): it answers a
// request ADU (MBAP header and PDU, as a socket carries it) with the reply
// ADU. The link builds and checks the frames exactly as it does on a socket.
class ModbusFramePeer {
 public:
  virtual ~ModbusFramePeer() = default;
  // The reply's length in bytes, or -1 with errno set.
  virtual int answer(const std::uint8_t* request, int n, std::uint8_t* reply, int capacity) = 0;
};

struct ModbusConfig {
  enum class Transport : std::uint8_t { tcp, rtu };
  Transport transport = Transport::tcp;
  std::string host = "127.0.0.1";  // tcp
  int port = 502;                  // tcp
  std::string device;              // rtu: /dev/ttyUSB0, a pty ...
  int baud = 115200;               // rtu, 8N1
  int unit = 17;                   // the board's unit id
  double response_timeout_s = 0.2; // per transaction
  int retries = 3;                 // resends after the first attempt
  ModbusFramePeer* peer = nullptr; // tcp: frames go to this peer instead of host:port
};

class ModbusSegmentLink final : public SegmentLink {
 public:
  // Creates the libmodbus context (the only allocation) and connects. On
  // failure returns null with the reason in `error`.
  static std::unique_ptr<ModbusSegmentLink> open(const ModbusConfig& cfg, std::string& error);
  ~ModbusSegmentLink() override;
  ModbusSegmentLink(const ModbusSegmentLink&) = delete;
  ModbusSegmentLink& operator=(const ModbusSegmentLink&) = delete;

  LinkError push(const SegmentCommand& seg, BoardStatus& status) override;
  // Queues n <= modbus_map::kMaxSlotsPerWrite consecutive segments in one transaction.
  LinkError push_many(const SegmentCommand* segs, int n, BoardStatus& status);
  LinkError status(BoardStatus& status) override;
  LinkError command(Command c) override;
  // Writes the home block (FC16 at 40), then command 7.
  LinkError home(const HomeCommand& h, const std::function<bool()>& stop) override;
  const char* last_error() const override { return error_; }

  std::uint64_t resends() const override { return resends_; }
  std::uint64_t reconnects() const { return reconnects_; }

 private:
  explicit ModbusSegmentLink(const ModbusConfig& cfg);
  enum class Op : std::uint8_t { push, status, command, home };
  // Runs one transaction with retries; `attempt` returns libmodbus's rc.
  template <class F>
  LinkError transact(Op op, F&& attempt);
  LinkError fail(LinkError e, const char* what, int err);
  // One request/reply, built and checked here rather than by libmodbus so
  // that every reply is validated the same way on both transports: unit id,
  // TCP transaction id, function code, exception, byte count, echo. Reads
  // `nread` registers into `out` for FC03/FC23. Returns -1 with errno set.
  int exchange(const std::uint8_t* pdu, int n, int nread, std::uint16_t* out);
  // The checks on a reply of rn bytes (rn -1: none came, errno set).
  int check_reply(const std::uint8_t* r, int rn, int fc, const std::uint8_t* pdu, int nread, std::uint16_t* out);
  // After a timeout or a bad reply: discard bytes until the line has been
  // quiet for one response timeout, so a late reply cannot answer the resend.
  void drain();

  ModbusConfig cfg_;
  modbus_t* ctx_ = nullptr;
  bool connected_ = false;
  std::uint16_t tid_ = 0;  // TCP transaction id of the last request
  std::uint64_t resends_ = 0;
  std::uint64_t reconnects_ = 0;
  char error_[200] = {};
};

}  // namespace kerf::hal
