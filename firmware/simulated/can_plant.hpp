// The CAN drives as a SimPlant (sim_plant.hpp), for run_sim_machine(...,
// SimPlant&, ...): the CSP link to simulated CiA 402 drives (can_sim_link.hpp),
// one tick per SYNC. BoardFault's drive_fault is an EMCY on the first drive;
// the CAN fault kinds go through inject_can().
#pragma once

#include <memory>
#include <string>

#include "simulated/can_sim_link.hpp"
#include "simulated/sim_plant.hpp"

namespace kerf::simulated {

class CanPlant final : public SimPlant {
 public:
  explicit CanPlant(std::unique_ptr<CanSimLink> link) : link_(std::move(link)) {}
  hal::SegmentLink& link() override { return *link_; }
  double tick_s() const override { return link_->sync_period_s(); }
  void tick() override { link_->tick(); }
  // The link runs on the host: its status is what the drives report.
  hal::BoardStatus truth() override;
  bool inject(const BoardFault& f) override;
  void inject_can(CanFaultKind k) { link_->inject(k); }
  CanSimLink& can() { return *link_; }

 private:
  std::unique_ptr<CanSimLink> link_;
};

// Null with the reason in `error` when the drives cannot be brought up.
std::unique_ptr<CanPlant> make_can_plant(const CanSimOptions& opts, std::string& error);

}  // namespace kerf::simulated
