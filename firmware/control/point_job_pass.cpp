#include "control/point_job_pass.hpp"

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <thread>

namespace kerf::control {

namespace {

struct Fnv {
  std::uint64_t h = 14695981039346656037ull;
  void bytes(const void* data, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  }
  template <class T>
  void value(T v) {
    bytes(&v, sizeof v);
  }
};

bool hash_file(const std::string& file, const JobStreamSetup& setup, std::uint64_t& out, std::string& error) {
  std::FILE* f = std::fopen(file.c_str(), "rb");
  if (f == nullptr) {
    error = file + ": " + std::strerror(errno);
    return false;
  }
  Fnv fnv;
  fnv.value(std::uint64_t{0x5354524d});  // a streamed point job: never a whole job's id
  fnv.value(static_cast<std::uint32_t>(setup.criterion));
  fnv.value(setup.tol);
  fnv.value(setup.feed_mm_s);
  fnv.value(setup.window);
  char buf[1 << 16];
  std::size_t got = 0;
  while ((got = std::fread(buf, 1, sizeof buf, f)) > 0) fnv.bytes(buf, got);
  const bool ok = std::ferror(f) == 0;
  if (!ok) error = file + ": read error";
  std::fclose(f);
  out = fnv.h;
  return ok;
}

}  // namespace

bool first_pass(const std::string& file, const JobStreamSetup& setup, JobSummary& out, std::string& error) {
  std::uint64_t hash = 0;
  if (!hash_file(file, setup, hash, error)) return false;
  auto ring = std::make_unique<JobRing>();
  PointFileProducer producer;
  if (!producer.start(file, setup, *ring, error)) return false;
  std::size_t segments = 0;
  StreamItem item;
  for (;;) {
    if (!ring->try_pop(item)) {
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      continue;
    }
    if (item.kind != StreamItem::Kind::segment) break;
    ++segments;
  }
  producer.join();
  if (item.kind == StreamItem::Kind::error) {
    error = producer.error();
    return false;
  }
  out.segments = segments;
  out.id = {hash, static_cast<std::uint32_t>(segments)};
  return true;
}

}  // namespace kerf::control
