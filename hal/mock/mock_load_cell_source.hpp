#pragma once

#include <cstdint>
#include <optional>

#include "hal/clock.hpp"
#include "hal/load_cell_source.hpp"

namespace mrd::hal::mock {

// A load cell as the test or the simulated rig sets it (set_force): one new sample per call,
// or none while silenced (set_silent), or an unusable one while set_faulty.
class MockLoadCellSource final : public LoadCellSource {
 public:
  explicit MockLoadCellSource(const Clock& clock) : clock_(clock) {}

  void set_force(double newtons) { force_ = newtons; }
  void set_silent(bool silent) { silent_ = silent; }
  void set_faulty(bool faulty) { faulty_ = faulty; }
  [[nodiscard]] std::optional<LoadCellSample> latest_load_cell() override {
    if (silent_) return std::nullopt;
    return LoadCellSample{force_, clock_.now(), ++sequence_,
                          static_cast<std::uint8_t>(kSampleValid | (faulty_ ? kSampleSensorFault : 0))};
  }

 private:
  const Clock& clock_;
  double force_ = 0.0;
  bool silent_ = false;
  bool faulty_ = false;
  std::uint32_t sequence_ = 0;
};

}  // namespace mrd::hal::mock
