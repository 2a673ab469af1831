// The one place a machine is made from its configuration, for `kerf run`
// and, with the simulator's link and lines passed in, for `kerf-sim`: the
// safety rules on the configured lines, the real link (Modbus TCP or RTU,
// CANopen CiA 402 on SocketCAN), the real lines (libgpiod), and the
// controller. It knows no simulator.
#pragma once

#include <memory>
#include <string>

#include "config/config.hpp"
#include "control/controller.hpp"
#include "kerf/hal/gpio.hpp"
#include "kerf/hal/segment_link.hpp"

namespace kerf::machine {

// What a configuration must hold before `kerf run` touches any device
// (checked before the link is opened): an E-stop line, always. On a machine,
// the torch and arc-OK lines; on a bench ([bench] enabled), no torch (or
// gas) output at all. False with "FILE: KEY: reason".
bool check_lines(const config::Config& cfg, std::string& error);

// The configured link, connected (and, for CAN, brought up and enabled).
// Null with the reason when it cannot be made or this build has no backend.
std::unique_ptr<hal::SegmentLink> open_link(const config::Config& cfg, std::string& error);

// The configured lines (libgpiod).
// Null with the reason when a line cannot be had or this build has no libgpiod.
std::unique_ptr<hal::Gpio> open_lines(const config::Config& cfg, std::string& error);

// The controller every command runs, with the settings of `cfg`
// (control::controller_config) or the caller's `ccfg`.
std::unique_ptr<control::Controller> make_controller(const control::Job& job, const control::ControllerConfig& ccfg,
                                                     hal::SegmentLink& link, hal::Gpio& gpio,
                                                     control::Journal* journal);
// The job as it streams (control/job_source.hpp; not owned).
std::unique_ptr<control::Controller> make_controller(control::JobSource& job, const control::ControllerConfig& ccfg,
                                                     hal::SegmentLink& link, hal::Gpio& gpio,
                                                     control::Journal* journal);
std::unique_ptr<control::Controller> make_controller(const control::Job& job, const config::Config& cfg,
                                                     hal::SegmentLink& link, hal::Gpio& gpio,
                                                     control::Journal* journal);

}  // namespace kerf::machine
