#include "kerf/sim/board_server.hpp"

#include <arpa/inet.h>
#include <modbus/modbus.h>
#include <netinet/in.h>
#include <poll.h>
#include <pty.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>

#include "kerf/hal/modbus/register_map.hpp"
#include "sim_frame.hpp"

namespace kerf::sim {

namespace map = hal::modbus_map;

namespace {
constexpr int kMaxAdu = 260;  // MODBUS_TCP_MAX_ADU_LENGTH, the larger of the two
int u16(const std::uint8_t* p) { return (p[0] << 8) | p[1]; }
void close_fd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}
}  // namespace

BoardServer::BoardServer(MotionBoard& board, const ServerConfig& cfg) : board_(board), cfg_(cfg) {}

double BoardServer::now() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::unique_ptr<BoardServer> BoardServer::start(MotionBoard& board, const ServerConfig& cfg,
                                                std::string& error) {
  std::unique_ptr<BoardServer> s(new BoardServer(board, cfg));
  auto fail = [&](const char* what) {
    error = std::string(what) + ": " + std::strerror(errno);
    return nullptr;
  };
  if (::pipe(s->stop_pipe_) != 0) return fail("pipe");
  if (::socketpair(AF_UNIX, SOCK_STREAM, 0, s->capture_pipe_) != 0) return fail("socketpair");
  if (cfg.transport == ServerConfig::Transport::tcp && cfg.in_process) {
    s->ctx_ = modbus_new_tcp("127.0.0.1", 0);  // builds the replies; never listens
    if (s->ctx_ == nullptr) return fail("modbus_new_tcp");
    modbus_set_slave(s->ctx_, cfg.unit);
    s->mapping_ = modbus_mapping_new(0, 0, map::kMapRegs, 0);
    if (s->mapping_ == nullptr) return fail("modbus_mapping_new");
    return s;
  }
  if (cfg.transport == ServerConfig::Transport::tcp) {
    s->ctx_ = modbus_new_tcp("127.0.0.1", cfg.port);  // port 0: the kernel picks a free one
    if (s->ctx_ == nullptr) return fail("modbus_new_tcp");
    s->listen_fd_ = modbus_tcp_listen(s->ctx_, 1);
    if (s->listen_fd_ < 0) return fail("modbus_tcp_listen");
    sockaddr_in addr{};
    socklen_t alen = sizeof addr;
    if (::getsockname(s->listen_fd_, reinterpret_cast<sockaddr*>(&addr), &alen) != 0)
      return fail("getsockname");
    s->port_ = ntohs(addr.sin_port);
  } else {
    char name[128] = {};
    if (::openpty(&s->pty_master_, &s->pty_slave_, name, nullptr, nullptr) != 0)
      return fail("openpty");
    // Raw before the host opens it: a cooked pty would echo replies back as requests.
    termios tio{};
    ::tcgetattr(s->pty_slave_, &tio);
    ::cfmakeraw(&tio);
    ::tcsetattr(s->pty_slave_, TCSANOW, &tio);
    s->device_ = name;
    s->ctx_ = modbus_new_rtu(name, 115200, 'N', 8, 1);
    if (s->ctx_ == nullptr) return fail("modbus_new_rtu");
    modbus_set_socket(s->ctx_, s->pty_master_);  // served on the master, never opened by path
  }
  modbus_set_slave(s->ctx_, cfg.unit);
  s->mapping_ = modbus_mapping_new(0, 0, map::kMapRegs, 0);
  if (s->mapping_ == nullptr) return fail("modbus_mapping_new");
  s->last_request_ = s->now();
  s->thread_ = std::thread([p = s.get()] { p->run(); });
  return s;
}

BoardServer::~BoardServer() {
  if (thread_.joinable()) {
    const char b = 1;
    (void)!::write(stop_pipe_[1], &b, 1);
    thread_.join();
  }
  if (mapping_ != nullptr) modbus_mapping_free(static_cast<modbus_mapping_t*>(mapping_));
  if (ctx_ != nullptr) modbus_free(ctx_);  // the fds below are ours, not the context's
  close_fd(client_fd_);
  close_fd(listen_fd_);
  close_fd(pty_master_);
  close_fd(pty_slave_);
  for (int* p : {stop_pipe_, capture_pipe_}) {
    close_fd(p[0]);
    close_fd(p[1]);
  }
}

bool BoardServer::wait_or_stop(double seconds) {
  pollfd p{stop_pipe_[0], POLLIN, 0};
  return ::poll(&p, 1, static_cast<int>(seconds * 1000.0 + 0.5)) == 0;
}

void BoardServer::run() {
  const bool tcp = cfg_.transport == ServerConfig::Transport::tcp;
  for (;;) {
    double drop_until = 0.0;
    {
      std::lock_guard<std::mutex> lock(fault_mu_);
      drop_until = drop_until_;
    }
    const double t = now();
    const bool dropped = t < drop_until;
    if (dropped && tcp) close_fd(client_fd_);
    pollfd fds[2] = {{stop_pipe_[0], POLLIN, 0}, {-1, POLLIN, 0}};
    if (!tcp) fds[1].fd = pty_master_;
    else if (client_fd_ >= 0) fds[1].fd = client_fd_;
    else if (!dropped) fds[1].fd = listen_fd_;
    int timeout_ms = 50;  // re-check the drop window and the watchdog
    if (dropped) timeout_ms = static_cast<int>((drop_until - t) * 1000.0) + 1;
    if (::poll(fds, 2, timeout_ms) < 0 && errno != EINTR) return;
    if (fds[0].revents != 0) return;
    if (cfg_.watchdog_s > 0.0 && now() - last_request_ > cfg_.watchdog_s) board_.link_lost();
    if (fds[1].revents == 0) continue;
    if (tcp && client_fd_ < 0) {
      client_fd_ = ::accept(listen_fd_, nullptr, nullptr);
      continue;
    }
    serve_one(fds[1].fd);
  }
}

void BoardServer::serve_one(int fd) {
  const bool tcp = cfg_.transport == ServerConfig::Transport::tcp;
  modbus_set_socket(ctx_, fd);
  std::uint8_t q[kMaxAdu];
  const int len = modbus_receive(ctx_, q);
  if (len < 0) {
    if (tcp) close_fd(client_fd_);  // the host closed or reset the connection
    else modbus_flush(ctx_);        // garbage on the line: resynchronise
    return;
  }
  if (len == 0) return;  // RTU: a request for another unit
  ++requests_;
  {
    std::lock_guard<std::mutex> lock(fault_mu_);
    const double t = now();
    if (t < drop_until_ || t < stall_until_) return;  // the request is lost: it feeds no watchdog
  }
  last_request_ = now();
  int code = 0;
  if (handle(q, len, code)) send_reply(q, len, fd, code);
}

int BoardServer::answer(const std::uint8_t* request, int n, std::uint8_t* reply, int capacity) {
  ++requests_;
  if (link_faults_.load(std::memory_order_relaxed)) {  // the clock only once a drop or stall was asked for
    std::lock_guard<std::mutex> lock(fault_mu_);
    const double t = now();
    if (t < drop_until_ || t < stall_until_) {  // lost: the host times out
      errno = ETIMEDOUT;
      return -1;
    }
  }
  int code = 0;
  if (n < 8 || capacity < kMaxAdu || !handle(request, n, code)) {
    errno = ETIMEDOUT;
    return -1;
  }
  int rn = reply_frame(request, code, reply);
  if (cfg_.check_replies) {  // libmodbus's own reply, through the socket pair: the same bytes?
    modbus_set_socket(ctx_, capture_pipe_[1]);
    if (code != 0) modbus_reply_exception(ctx_, request, static_cast<unsigned>(code));
    else modbus_reply(ctx_, request, n, static_cast<modbus_mapping_t*>(mapping_));
    std::uint8_t lib[kMaxAdu];
    const ssize_t got = ::recv(capture_pipe_[0], lib, sizeof lib, MSG_DONTWAIT);
    if (got != rn || std::memcmp(lib, reply, static_cast<std::size_t>(rn)) != 0) ++reply_mismatches_;
  }
  int unit = 0, shorten = 0;
  {
    std::lock_guard<std::mutex> lock(fault_mu_);
    if (wrong_unit_ > 0) unit = wrong_unit_--;
    if (short_ > 0) shorten = short_--;
  }
  if (unit != 0) rn = frame_wrong_unit(FrameKind::tcp, reply, rn);
  if (shorten != 0) rn = frame_short(FrameKind::tcp, reply, rn);
  return rn;
}

namespace {
void put16(std::uint8_t* p, int v) {
  p[0] = static_cast<std::uint8_t>(v >> 8);
  p[1] = static_cast<std::uint8_t>(v & 0xFF);
}
}  // namespace

int BoardServer::reply_frame(const std::uint8_t* q, int code, std::uint8_t* r) const {
  // As libmodbus's modbus_reply and modbus_reply_exception build them for
  // the four function codes handle() serves (TCP: the request's MBAP header).
  constexpr int h = 7;
  std::memcpy(r, q, h);
  const int fc = q[h];
  int n = h;
  if (code != 0) {
    r[n++] = static_cast<std::uint8_t>(fc | 0x80);
    r[n++] = static_cast<std::uint8_t>(code);
  } else if (fc == MODBUS_FC_READ_HOLDING_REGISTERS || fc == MODBUS_FC_WRITE_AND_READ_REGISTERS) {
    const int addr = u16(q + h + 1), nb = u16(q + h + 3);
    const auto* regs = static_cast<const modbus_mapping_t*>(mapping_)->tab_registers;
    r[n++] = static_cast<std::uint8_t>(fc);
    r[n++] = static_cast<std::uint8_t>(2 * nb);
    for (int i = 0; i < nb; ++i, n += 2) put16(r + n, regs[addr + i]);
  } else {  // FC06 echoes address and value, FC16 address and count
    std::memcpy(r + n, q + h, 5);
    n += 5;
  }
  put16(r + 4, n - 6);
  return n;
}

hal::BoardStatus BoardServer::board_status() const {
  hal::BoardStatus st = board_.status();
  st.actual = cfg_.plant != nullptr ? cfg_.plant->actual() : st.position;
  return st;
}

bool BoardServer::handle(const std::uint8_t* q, int len, int& code) {
  int delays = 0;
  double delay_s = 0.0;
  int exc = 0;
  {
    std::lock_guard<std::mutex> lock(fault_mu_);
    if (delays_ > 0) {
      --delays_;
      delays = 1;
      delay_s = delay_s_;
    }
    if (exceptions_ > 0) {
      --exceptions_;
      exc = exception_code_;
    }
  }
  if (delays != 0 && !wait_or_stop(delay_s)) return false;
  if (exc != 0) {  // injected: the board does nothing with the request
    code = exc;
    return true;
  }
  const int h = modbus_get_header_length(ctx_);
  const int fc = q[h];
  auto* regs = static_cast<modbus_mapping_t*>(mapping_)->tab_registers;
  code = 0;
  switch (fc) {
    case MODBUS_FC_READ_HOLDING_REGISTERS:
      if (u16(q + h + 1) + u16(q + h + 3) > map::kStatusRegs) code = MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS;
      else hal::modbus_map::encode_status(board_status(), regs);
      break;
    case MODBUS_FC_WRITE_SINGLE_REGISTER:
      if (u16(q + h + 1) != map::kCommandAddr) code = MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS;
      else if (u16(q + h + 3) == map::kCommandHome) code = start_homing();
      else if (!board_.command(static_cast<std::uint16_t>(u16(q + h + 3))))
        code = MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE;
      break;
    case MODBUS_FC_WRITE_MULTIPLE_REGISTERS:
      if (u16(q + h + 1) == map::kHomeAddr) code = write_home_block(u16(q + h + 3), q + h + 6, len - h - 6);
      else code = write_slots(board_, u16(q + h + 1), u16(q + h + 3), q + h + 6, len - h - 6);
      break;
    case MODBUS_FC_WRITE_AND_READ_REGISTERS:
      if (u16(q + h + 1) + u16(q + h + 3) > map::kStatusRegs) {
        code = MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS;
        break;
      }
      code = write_slots(board_, u16(q + h + 5), u16(q + h + 7), q + h + 10, len - h - 10);
      if (code == 0) hal::modbus_map::encode_status(board_status(), regs);
      break;
    default: code = MODBUS_EXCEPTION_ILLEGAL_FUNCTION;
  }
  return true;
}

int BoardServer::write_home_block(int nb, const std::uint8_t* data, int bytes) {
  if (nb != map::kHomeRegs) return MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS;
  if (bytes < 2 * nb) return MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE;
  for (int i = 0; i < nb; ++i) home_block_[i] = static_cast<std::uint16_t>(u16(data + 2 * i));
  home_block_set_ = true;
  return 0;
}

int BoardServer::start_homing() {
  hal::HomeCommand cmd;
  const char* reason = nullptr;
  if (!home_block_set_ || !map::decode_home(home_block_, cmd, reason) || !board_.home(cmd))
    return MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE;
  return 0;
}

void BoardServer::send_reply(const std::uint8_t* q, int len, int fd, int exception_code) {
  const bool tcp = cfg_.transport == ServerConfig::Transport::tcp;
  int crc = 0, unit = 0, shorten = 0;
  {
    std::lock_guard<std::mutex> lock(fault_mu_);
    if (crc_ > 0 && !tcp) crc = crc_--;
    if (wrong_unit_ > 0) unit = wrong_unit_--;
    if (short_ > 0) shorten = short_--;
  }
  const bool mutate = crc != 0 || unit != 0 || shorten != 0;
  // A reply to mutate is built by libmodbus into a socket pair, then sent by hand.
  modbus_set_socket(ctx_, mutate ? capture_pipe_[1] : fd);
  if (exception_code != 0) modbus_reply_exception(ctx_, q, static_cast<unsigned>(exception_code));
  else modbus_reply(ctx_, q, len, static_cast<modbus_mapping_t*>(mapping_));
  modbus_set_socket(ctx_, fd);
  if (!mutate) return;
  std::uint8_t r[kMaxAdu];
  const ssize_t n = ::recv(capture_pipe_[0], r, sizeof r, MSG_DONTWAIT);
  if (n <= 0) return;
  FrameKind kind = tcp ? FrameKind::tcp : FrameKind::rtu;
  int rn = static_cast<int>(n);
  if (unit != 0) rn = frame_wrong_unit(kind, r, rn);
  if (shorten != 0) rn = frame_short(kind, r, rn);
  if (crc != 0) rn = frame_bad_crc(r, rn);
  if (tcp) (void)!::send(fd, r, static_cast<std::size_t>(rn), MSG_NOSIGNAL);
  else (void)!::write(fd, r, static_cast<std::size_t>(rn));
}

void BoardServer::drop_link(double seconds) {
  link_faults_ = true;
  std::lock_guard<std::mutex> lock(fault_mu_);
  drop_until_ = now() + seconds;
}
void BoardServer::stall(double seconds) {
  link_faults_ = true;
  std::lock_guard<std::mutex> lock(fault_mu_);
  stall_until_ = now() + seconds;
}
void BoardServer::exception_replies(int count, int code) {
  std::lock_guard<std::mutex> lock(fault_mu_);
  exceptions_ = count;
  exception_code_ = code;
}
void BoardServer::delay_replies(int count, double seconds) {
  std::lock_guard<std::mutex> lock(fault_mu_);
  delays_ = count;
  delay_s_ = seconds;
}
void BoardServer::corrupt_crc(int count) {
  std::lock_guard<std::mutex> lock(fault_mu_);
  crc_ = count;
}
void BoardServer::wrong_unit(int count) {
  std::lock_guard<std::mutex> lock(fault_mu_);
  wrong_unit_ = count;
}
void BoardServer::short_replies(int count) {
  std::lock_guard<std::mutex> lock(fault_mu_);
  short_ = count;
}

}  // namespace kerf::sim
