#include "kerf/hal/can/socket_can_bus.hpp"

#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <poll.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace kerf::hal {

std::unique_ptr<SocketCanBus> SocketCanBus::open(const std::string& iface,
                                                 const std::vector<CanFilter>& filters,
                                                 std::string& error) {
  if (iface.empty() || iface.size() >= IFNAMSIZ) {
    error = "SocketCAN: bad interface name '" + iface + "'";
    return nullptr;
  }
  const int fd = ::socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
  if (fd < 0) {
    error = "SocketCAN: socket(PF_CAN): " + std::string(std::strerror(errno)) +
            " (no CAN support in this kernel?)";
    return nullptr;
  }
  auto fail = [&](const std::string& what) {
    error = "SocketCAN " + iface + ": " + what + ": " + std::strerror(errno);
    ::close(fd);
    return nullptr;
  };
  const unsigned index = ::if_nametoindex(iface.c_str());
  if (index == 0) return fail("no such interface");
  if (!filters.empty()) {
    std::vector<can_filter> kf(filters.size());
    for (std::size_t i = 0; i < filters.size(); ++i) {
      // CAN_EFF_FLAG in the mask: extended frames never match a standard id.
      kf[i].can_id = filters[i].id & CAN_SFF_MASK;
      kf[i].can_mask = (filters[i].mask & CAN_SFF_MASK) | CAN_EFF_FLAG | CAN_RTR_FLAG;
    }
    if (::setsockopt(fd, SOL_CAN_RAW, CAN_RAW_FILTER, kf.data(),
                     static_cast<socklen_t>(kf.size() * sizeof(can_filter))) != 0)
      return fail("CAN_RAW_FILTER");
  }
  const can_err_mask_t err_mask = CAN_ERR_BUSOFF | CAN_ERR_CRTL | CAN_ERR_RESTARTED | CAN_ERR_TX_TIMEOUT;
  if (::setsockopt(fd, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &err_mask, sizeof err_mask) != 0)
    return fail("CAN_RAW_ERR_FILTER");
  sockaddr_can addr{};
  addr.can_family = AF_CAN;
  addr.can_ifindex = static_cast<int>(index);
  if (::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) return fail("bind");
  return std::unique_ptr<SocketCanBus>(new SocketCanBus(fd));
}

SocketCanBus::~SocketCanBus() {
  if (fd_ >= 0) ::close(fd_);
}

std::uint64_t SocketCanBus::now_us() {
  timespec ts{};
  ::clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::uint64_t>(ts.tv_sec) * 1000000u + static_cast<std::uint64_t>(ts.tv_nsec) / 1000u;
}

CanResult SocketCanBus::send(const CanFrame& f) {
  if (state_ == BusState::bus_off) {
    ++counters_.send_refused;
    std::snprintf(error_, sizeof error_, "send refused: the controller is bus-off");
    return CanResult::bus_off;
  }
  if (f.dlc > 8 || f.id > CAN_SFF_MASK) {
    std::snprintf(error_, sizeof error_, "send refused: id 0x%X dlc %u is not a standard frame",
                  static_cast<unsigned>(f.id), static_cast<unsigned>(f.dlc));
    return CanResult::io_error;
  }
  can_frame k{};
  k.can_id = f.id;
  k.can_dlc = f.dlc;
  std::memcpy(k.data, f.data, 8);
  const ssize_t n = ::write(fd_, &k, sizeof k);
  if (n == static_cast<ssize_t>(sizeof k)) {
    ++counters_.sent;
    return CanResult::ok;
  }
  ++counters_.send_refused;
  if (n < 0 && (errno == ENOBUFS || errno == EAGAIN)) {
    std::snprintf(error_, sizeof error_, "send queue full (%s)", std::strerror(errno));
    return CanResult::queue_full;
  }
  std::snprintf(error_, sizeof error_, "write: %s", n < 0 ? std::strerror(errno) : "short write");
  return CanResult::io_error;
}

void SocketCanBus::on_error_frame(std::uint32_t id, const std::uint8_t* data) {
  ++counters_.error_frames;
  if (id & CAN_ERR_BUSOFF) {
    state_ = BusState::bus_off;
  } else if (id & CAN_ERR_RESTARTED) {
    state_ = BusState::active;
  } else if (id & CAN_ERR_CRTL) {
    const std::uint8_t c = data[1];
    if (c & (CAN_ERR_CRTL_RX_PASSIVE | CAN_ERR_CRTL_TX_PASSIVE)) state_ = BusState::passive;
    else if (c & (CAN_ERR_CRTL_RX_WARNING | CAN_ERR_CRTL_TX_WARNING)) state_ = BusState::warning;
    else if (c & CAN_ERR_CRTL_ACTIVE) state_ = BusState::active;
  }
}

CanResult SocketCanBus::receive(CanFrame& f, std::uint64_t until_us) {
  for (;;) {
    can_frame k{};
    const ssize_t n = ::read(fd_, &k, sizeof k);
    if (n == static_cast<ssize_t>(sizeof k)) {
      if (k.can_id & CAN_ERR_FLAG) {
        on_error_frame(k.can_id & CAN_ERR_MASK, k.data);
        continue;
      }
      if (k.can_id & (CAN_EFF_FLAG | CAN_RTR_FLAG)) continue;  // the filters keep these out
      f.id = k.can_id & CAN_SFF_MASK;
      f.dlc = k.can_dlc;
      std::memcpy(f.data, k.data, 8);
      ++counters_.received;
      return CanResult::ok;
    }
    if (n >= 0 || (errno != EAGAIN && errno != EINTR)) {
      std::snprintf(error_, sizeof error_, "read: %s", n < 0 ? std::strerror(errno) : "short frame");
      return CanResult::io_error;
    }
    const std::uint64_t now = now_us();
    if (now >= until_us) return CanResult::timeout;
    pollfd p{fd_, POLLIN, 0};
    timespec ts{static_cast<time_t>((until_us - now) / 1000000u),
                static_cast<long>(((until_us - now) % 1000000u) * 1000u)};
    if (::ppoll(&p, 1, &ts, nullptr) < 0 && errno != EINTR) {
      std::snprintf(error_, sizeof error_, "poll: %s", std::strerror(errno));
      return CanResult::io_error;
    }
  }
}

// Recovery is the kernel's (ip link set can0 type can restart-ms N): its
// CAN_ERR_RESTARTED frame, read by receive(), brings the state back.
bool SocketCanBus::recovered() { return state_ != BusState::bus_off; }

}  // namespace kerf::hal
