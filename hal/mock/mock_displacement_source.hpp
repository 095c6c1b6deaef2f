#pragma once

#include <cstdint>
#include <optional>

#include "hal/clock.hpp"
#include "hal/displacement_source.hpp"
#include "hal/mock/fault_script.hpp"

namespace mrd::hal::mock {

// An LVDT that reports whatever the test or simulator says the truth is, with scripted faults
// on top. The plant lives elsewhere: hal knows no physics.
class MockDisplacementSource final : public DisplacementSource {
 public:
  MockDisplacementSource(const Clock& clock, const FaultScript& script)
      : clock_(clock), script_(script) {}

  void set_truth(double metres) { truth_ = metres; }
  [[nodiscard]] std::optional<DisplacementSample> latest() override;

  [[nodiscard]] std::uint64_t samples_dropped() const { return dropped_; }

 private:
  bool drop_this_sample(Timestamp now);

  const Clock& clock_;
  const FaultScript& script_;
  double truth_ = 0.0;
  std::optional<DisplacementSample> last_;
  std::optional<double> frozen_;  // the value a frozen sensor keeps
  std::uint32_t sequence_ = 0;
  std::uint64_t dropped_ = 0;
  std::uint64_t drop_phase_ = 0;
  bool gap_pending_ = false;
  bool jump_off_ = false;         // kDisplacementJump: this sample goes without the offset
};

}  // namespace mrd::hal::mock
