// Segments per second streamed to the simulated board over real libmodbus:
// TCP on 127.0.0.1 against a raw FC16 (16 registers) measured in the same
// run, and RTU on a pty against the 115200-baud wire limit computed in
// hal/modbus/REGISTERS.md. The board runs EndpointExecutor (no motion
// profile): this measures the link, not the motion.
#include <arpa/inet.h>
#include <modbus/modbus.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "control/segment_streamer.hpp"
#include "kerf/hal/modbus/modbus_link.hpp"
#include "kerf/sim/board_server.hpp"

namespace {

using namespace kerf;
using clock_type = std::chrono::steady_clock;

double seconds_since(clock_type::time_point t) {
  return std::chrono::duration<double>(clock_type::now() - t).count();
}

std::vector<hal::SegmentCommand> make_job(std::uint32_t n) {
  std::vector<hal::SegmentCommand> v(n);
  for (std::uint32_t k = 0; k < n; ++k) {
    v[k].seq = k + 1;
    v[k].end = {static_cast<double>(k % 1000), static_cast<double>(k / 1000)};
    v[k].feed = 100.0;
  }
  return v;
}

// Streams n segments, `batch` slots per transaction; returns segments/s or -1.
double stream_rate(sim::ServerConfig::Transport t, std::uint32_t n, int batch) {
  sim::BoardConfig bc;
  bc.capacity = 64;
  sim::MotionBoard board(bc, std::make_unique<sim::EndpointExecutor>());
  sim::ServerConfig sc;
  sc.transport = t;
  std::string err;
  auto server = sim::BoardServer::start(board, sc, err);
  hal::ModbusConfig lc;
  lc.transport = t == sim::ServerConfig::Transport::tcp ? hal::ModbusConfig::Transport::tcp
                                                        : hal::ModbusConfig::Transport::rtu;
  lc.port = server ? server->port() : 0;
  lc.device = server ? server->device() : "";
  auto link = server ? hal::ModbusSegmentLink::open(lc, err) : nullptr;
  if (!link) {
    std::fprintf(stderr, "bench_modbus: %s\n", err.c_str());
    return -1.0;
  }
  board.start_servo(0.0);
  const auto job = make_job(n);
  const auto t0 = clock_type::now();
  bool ok = true;
  if (batch == 1) {
    control::StreamConfig cfg;
    const auto rep = control::stream_job(*link, job, cfg);
    ok = rep.ok;
  } else {
    hal::BoardStatus st;
    ok = link->command(hal::Command::start) == hal::LinkError::none;
    for (std::uint32_t next = 0; ok && next < n;) {
      if (st.credit < batch) {
        ok = link->status(st) == hal::LinkError::none;
        continue;
      }
      const int k = static_cast<int>(std::min<std::uint32_t>(static_cast<std::uint32_t>(batch), n - next));
      ok = link->push_many(job.data() + next, k, st) == hal::LinkError::none;
      next += static_cast<std::uint32_t>(k);
    }
  }
  const double dt = seconds_since(t0);
  board.stop_servo();
  if (!ok || board.status().last_accepted != n) {
    std::fprintf(stderr, "bench_modbus: stream failed: %s\n", link->last_error());
    return -1.0;
  }
  return n / dt;
}

// A bare libmodbus server (mapping + modbus_reply) and client doing FC16 of
// 16 registers: the transport's own rate on this machine, for the ratio.
double raw_fc16_rate(int n) {
  modbus_t* srv = modbus_new_tcp("127.0.0.1", 0);
  const int lfd = modbus_tcp_listen(srv, 1);
  sockaddr_in addr{};
  socklen_t alen = sizeof addr;
  ::getsockname(lfd, reinterpret_cast<sockaddr*>(&addr), &alen);
  modbus_mapping_t* mapping = modbus_mapping_new(0, 0, 64, 0);
  std::thread server([&] {
    int fd = lfd;
    if (modbus_tcp_accept(srv, &fd) < 0) return;
    std::uint8_t q[MODBUS_TCP_MAX_ADU_LENGTH];
    for (;;) {
      const int len = modbus_receive(srv, q);
      if (len < 0) break;
      if (len > 0) modbus_reply(srv, q, len, mapping);
    }
  });
  modbus_t* cli = modbus_new_tcp("127.0.0.1", ntohs(addr.sin_port));
  double rate = -1.0;
  if (modbus_connect(cli) == 0) {
    std::uint16_t regs[16] = {};
    const auto t0 = clock_type::now();
    int done = 0;
    for (; done < n; ++done) {
      regs[0] = static_cast<std::uint16_t>(done);
      if (modbus_write_registers(cli, 0, 16, regs) != 16) break;
    }
    rate = done == n ? n / seconds_since(t0) : -1.0;
    modbus_close(cli);  // ends the server's receive loop
  }
  server.join();
  modbus_free(cli);
  modbus_mapping_free(mapping);
  modbus_close(srv);
  modbus_free(srv);
  return rate;
}

}  // namespace

int main(int argc, char** argv) {
  const std::uint32_t n = argc > 1 ? static_cast<std::uint32_t>(std::strtoul(argv[1], nullptr, 10)) : 50000;
  constexpr double kRtuWireLimit1 = 94.2;   // segments/s, 1 slot per FC23 (REGISTERS.md)
  constexpr double kRtuWireLimit7 = 256.6;  // 7 slots per FC23
  const double raw = raw_fc16_rate(static_cast<int>(n));
  const double tcp1 = stream_rate(sim::ServerConfig::Transport::tcp, n, 1);
  const double tcp7 = stream_rate(sim::ServerConfig::Transport::tcp, n, 7);
  const double rtu1 = stream_rate(sim::ServerConfig::Transport::rtu, n / 5, 1);
  const double rtu7 = stream_rate(sim::ServerConfig::Transport::rtu, n / 5, 7);
  if (raw < 0 || tcp1 < 0 || tcp7 < 0 || rtu1 < 0 || rtu7 < 0) return 1;
  std::printf("raw libmodbus FC16 x16 regs, TCP loopback : %9.0f transactions/s\n", raw);
  std::printf("kerf push, TCP, 1 segment/transaction     : %9.0f segments/s  (%.2f x raw FC16; target >= 0.50)\n",
              tcp1, tcp1 / raw);
  std::printf("kerf push, TCP, 7 segments/transaction    : %9.0f segments/s  (%.2f x raw FC16)\n", tcp7,
              tcp7 / raw);
  std::printf("kerf push, RTU on a pty, 1 segment/trans. : %9.0f segments/s  (115200-baud wire limit %.1f: pty is %.0f x faster)\n",
              rtu1, kRtuWireLimit1, rtu1 / kRtuWireLimit1);
  std::printf("kerf push, RTU on a pty, 7 segments/trans.: %9.0f segments/s  (115200-baud wire limit %.1f: pty is %.0f x faster)\n",
              rtu7, kRtuWireLimit7, rtu7 / kRtuWireLimit7);
  return 0;
}
