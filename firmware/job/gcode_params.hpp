// The parameters of a running G-code program, with LinuxCNC's scoping:
// numbered #1..#4999 (an unset one reads 0; #1..#30 are a subroutine's
// arguments, saved and restored around each call), named locals `#<name>`
// (one set per call level; reading an unset one is an error) and globals
// `#<_name>`. `#<_hal[pin]>` reads a pin through the program's own
// callback. The system parameters (#5000 and up: probe, offsets, position)
// are refused: kerf keeps offsets in its machine state, not in parameters.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace kerf::job {

class GcodeParams {
 public:
  static constexpr int kMaxNumbered = 4999;
  static constexpr int kArgs = 30;
  static constexpr std::size_t kMaxCallDepth = 50;  // LinuxCNC's call stack length
  // Reads a pin: false with a reason for a pin kerf does not have.
  using HalRead = std::function<bool(std::string_view pin, double& value, std::string& reason)>;

  explicit GcodeParams(HalRead hal) : hal_(std::move(hal)), frames_(1) {}

  bool read(int n, double& v, std::string& reason) const;
  bool read(const std::string& name, double& v, std::string& reason) const;
  bool write(int n, double v, std::string& reason);
  void write(const std::string& name, double v);
  bool exists(const std::string& name) const;

  // A subroutine call: #1..#30 and the named locals of the caller are kept
  // aside; the callee's #1..#n are its arguments, the rest 0.
  bool push_call(const std::vector<double>& args, std::string& reason);
  void pop_call();
  std::size_t depth() const { return frames_.size() - 1; }

 private:
  struct Frame {
    std::array<double, kArgs> args{};  // the caller's #1..#30 while the callee runs
    std::map<std::string, double> locals;
  };
  HalRead hal_;
  std::array<double, kMaxNumbered + 1> numbered_{};
  std::map<std::string, double> globals_;
  std::vector<Frame> frames_;  // frames_.back().locals: the running level's named locals
};

}  // namespace kerf::job
