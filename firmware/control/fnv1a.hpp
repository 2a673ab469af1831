// FNV-1a, 64 bits: the journal's job ids (a whole job's, control/job.hpp,
// and a streamed file's, control/streamed_job.hpp). Not a cryptographic
// hash: it tells jobs apart, it does not resist a forger.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace kerf::control {

struct Fnv1a {
  std::uint64_t h = 14695981039346656037ull;
  void bytes(const void* data, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  }
  // The value's bytes as they lie in memory (a double's bits).
  template <class T>
  void value(T v) {
    bytes(&v, sizeof v);
  }
  void text(const std::string& s) {
    value(s.size());
    bytes(s.data(), s.size());
  }
};

}  // namespace kerf::control
