// Status codes and Result<T>: how core reports what can happen at run time.
// Contract violations (what must never happen) go through KERF_ASSERT instead.
#pragma once

#include <cstdint>

namespace kerf {

enum class Status : std::uint8_t {
  ok = 0,
  invalid_argument,   // caller passed a tolerance <= 0, a NaN, fewer than two points...
  collinear,          // three points do not define a circle
  degenerate,         // coincident points where distinct ones are required
  capacity_exceeded,  // caller-provided storage is too small; nothing was truncated
  infeasible,         // no solution within the constraints (e.g. too few pieces)
};

constexpr const char* to_string(Status s) {
  switch (s) {
    case Status::ok: return "ok";
    case Status::invalid_argument: return "invalid argument";
    case Status::collinear: return "collinear points";
    case Status::degenerate: return "degenerate geometry";
    case Status::capacity_exceeded: return "capacity exceeded";
    case Status::infeasible: return "infeasible";
  }
  return "unknown";
}

// A value or the reason there is none. T must be default-constructible.
template <class T>
class Result {
 public:
  constexpr Result(T value) : value_(value), status_(Status::ok) {}  // NOLINT: implicit by design
  constexpr Result(Status s) : value_(), status_(s) {}               // NOLINT: implicit by design

  constexpr bool ok() const { return status_ == Status::ok; }
  constexpr Status status() const { return status_; }
  constexpr const T& value() const { return value_; }
  constexpr T& value() { return value_; }

 private:
  T value_;
  Status status_;
};

}  // namespace kerf
