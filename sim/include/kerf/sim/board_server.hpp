// The simulated motion board's Modbus side: a libmodbus server thread that
// implements kerf's register map (hal/modbus/REGISTERS.md) on top of a
// MotionBoard. It listens on an ephemeral 127.0.0.1 TCP port, or as RTU on
// the master side of a fresh pseudo-terminal whose slave path the host opens.
// Faults are injected through the methods below, never through register values.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "kerf/hal/modbus/modbus_link.hpp"
#include "kerf/sim/board_plant.hpp"
#include "kerf/sim/motion_board.hpp"

typedef struct _modbus modbus_t;  // NOLINT: libmodbus's own declaration

namespace kerf::sim {

struct ServerConfig {
  using Transport = hal::ModbusConfig::Transport;  // the same two as the host's link
  Transport transport = Transport::tcp;
  int unit = 17;
  int port = 0;  // TCP on 127.0.0.1; 0: a free port the kernel picks
  // The board stops safely (torch off, fault) when no request arrives for
  // this long while it runs; 0 disables the watchdog.
  double watchdog_s = 0.0;
  // Where the axes really are (registers 16..19); null: a board without
  // feedback, which reports its commanded position there.
  const BoardPlant* plant = nullptr;
  // TCP only: no listener and no thread; the host's link passes each request
  // ADU to answer() (a hal::ModbusFramePeer) and gets libmodbus's reply bytes.
  bool in_process = false;
  // In process: also build each reply with libmodbus (modbus_reply, through
  // a socket pair) and count the replies whose bytes differ (tests).
  bool check_replies = false;
};

class BoardServer final : public hal::ModbusFramePeer {
 public:
  // Starts the server thread; null with `error` set on failure. The returned
  // server is listening (TCP) or the pty exists (RTU) before this returns.
  static std::unique_ptr<BoardServer> start(MotionBoard& board, const ServerConfig& cfg,
                                            std::string& error);
  ~BoardServer() override;
  BoardServer(const BoardServer&) = delete;
  BoardServer& operator=(const BoardServer&) = delete;

  int port() const { return port_; }                    // TCP
  const std::string& device() const { return device_; } // RTU: the pty slave to open

  // Fault injection (wall-clock durations, counts of requests).
  void drop_link(double seconds);  // TCP: close the connection, accept none for a while; RTU: the line goes dead
  void stall(double seconds);      // read requests, answer none
  void exception_replies(int count, int code);  // answer the next requests with an exception
  void delay_replies(int count, double seconds);
  void corrupt_crc(int count);     // RTU: flip the CRC of the next replies
  void wrong_unit(int count);      // the next replies carry another unit id
  void short_replies(int count);   // the next read replies carry one register too few

  std::uint64_t requests() const { return requests_.load(); }
  // In process (ServerConfig::in_process): one request ADU in, its reply out.
  // -1 with errno ETIMEDOUT when the board answers nothing (a stall).
  int answer(const std::uint8_t* request, int n, std::uint8_t* reply, int capacity) override;
  std::uint64_t reply_mismatches() const { return reply_mismatches_; }

 private:
  BoardServer(MotionBoard& board, const ServerConfig& cfg);
  void run();
  void serve_one(int fd);
  // Serves one request: `code` 0 or the exception to answer with; false:
  // answer nothing (stopped during an injected delay).
  bool handle(const std::uint8_t* q, int len, int& code);
  // The TCP reply to q, built here without a socket; its length.
  int reply_frame(const std::uint8_t* q, int code, std::uint8_t* r) const;
  hal::BoardStatus board_status() const;
  // The home block (registers 40..51) and command 7; 0 or the exception code.
  int write_home_block(int nb, const std::uint8_t* data, int bytes);
  int start_homing();  // the board's, with the plant's actual position
  void send_reply(const std::uint8_t* q, int len, int fd, int exception_code);
  bool wait_or_stop(double seconds);  // false when asked to stop
  double now() const;

  MotionBoard& board_;
  ServerConfig cfg_;
  modbus_t* ctx_ = nullptr;
  void* mapping_ = nullptr;  // modbus_mapping_t
  int listen_fd_ = -1, client_fd_ = -1;
  int pty_master_ = -1, pty_slave_ = -1;
  int stop_pipe_[2] = {-1, -1};
  int capture_pipe_[2] = {-1, -1};  // reply bytes to mutate before sending
  int port_ = 0;
  std::string device_;
  std::thread thread_;
  std::atomic<std::uint64_t> requests_{0};
  std::uint64_t reply_mismatches_ = 0;
  std::atomic<bool> link_faults_{false};  // a drop or stall was ever asked for
  double last_request_ = 0.0;
  std::uint16_t home_block_[12] = {};
  bool home_block_set_ = false;

  std::mutex fault_mu_;
  double drop_until_ = 0.0, stall_until_ = 0.0;
  int exceptions_ = 0, exception_code_ = 0, delays_ = 0, crc_ = 0, wrong_unit_ = 0, short_ = 0;
  double delay_s_ = 0.0;
};

}  // namespace kerf::sim
