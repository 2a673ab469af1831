// The machine configuration loader (firmware/config: toml++ and kerf's value
// checks) on arbitrary bytes. Either "FILE:LINE: KEY: reason" or a config
// whose values lie in the ranges config.hpp documents.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "config/config.hpp"
#include "fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  kerf::config::Config c;
  std::string error;
  if (!kerf::config::parse(text, "fuzz.toml", c, error)) {
    FUZZ_CHECK(error.rfind("fuzz.toml", 0) == 0, "an error that does not name the file");
    return 0;
  }
  const auto& m = c.machine;
  FUZZ_CHECK(m.axes.size() == 2 || m.axes.size() == 3, "2 or 3 axes");
  for (const auto& a : m.axes) FUZZ_CHECK(std::isfinite(a.counts_per_mm) && a.counts_per_mm > 0, "counts_per_mm");
  FUZZ_CHECK(m.max_feed > 0 && std::isfinite(m.max_feed), "max_feed");
  FUZZ_CHECK(m.rapid_feed > 0 && m.rapid_feed <= m.max_feed, "rapid_feed");
  FUZZ_CHECK(m.accel > 0 && std::isfinite(m.accel), "accel");
  FUZZ_CHECK(m.servo_period > 0 && m.servo_period <= 0.1, "servo_period");
  FUZZ_CHECK(m.cycle > 0 && m.cycle <= 0.1, "cycle");
  FUZZ_CHECK(c.fit.tol > 0 && std::isfinite(c.fit.tol), "fit.tol");
  FUZZ_CHECK(c.cut.feed > 0 && c.cut.feed <= m.max_feed, "cut.feed");
  FUZZ_CHECK(c.cut.pierce_delay >= 0 && std::isfinite(c.cut.pierce_delay), "pierce_delay");
  FUZZ_CHECK(c.link.timeout > 0 && std::isfinite(c.link.timeout), "link.timeout");
  FUZZ_CHECK(c.link.port >= 1 && c.link.port <= 65535, "link.port");
  FUZZ_CHECK(c.link.unit >= 1 && c.link.unit <= 247, "link.unit");
  if (c.link.kind == kerf::config::Link::Kind::can) {
    FUZZ_CHECK(c.link.node_ids.size() == m.axes.size(), "one can node id per axis");
    for (std::size_t i = 0; i < c.link.node_ids.size(); ++i) {
      FUZZ_CHECK(c.link.node_ids[i] >= 1 && c.link.node_ids[i] <= 127, "node id in 1..127");
      for (std::size_t j = 0; j < i; ++j) FUZZ_CHECK(c.link.node_ids[j] != c.link.node_ids[i], "distinct node ids");
    }
  }
  return 0;
}
