#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace mrd::tools {

// Velocity [m/s] from displacement [m] for offline analysis: a second-order Butterworth
// low-pass at `cutoff` [Hz], run forwards and then backwards (no phase lag, unlike the
// controller's causal filter), then central differences. Each end is padded by its odd
// reflection, so a record that starts or ends in motion keeps its velocity there (filtfilt's
// padding). Non-causal: for tools that see the whole run, never for the control loop.
[[nodiscard]] std::vector<double> zero_phase_velocity(std::span<const double> displacement,
                                                      double sample_rate, double cutoff);

// The same across logging gaps and spans set aside (record::fill_gaps's `filled`, one flag per
// sample). A gap of up to 1.5 periods of the cutoff with a quarter period of measured motion on
// both sides is bridged by the quintic that meets each side's value, slope and curvature, and
// filtered through; any other gap under a tenth of the cutoff's period is filtered through on its
// recorded bridge; the rest split the record into stretches, each padded at its ends like a
// record, and take their chord's slope.
[[nodiscard]] std::vector<double> zero_phase_velocity_by_stretch(std::span<const double> displacement,
                                                                 std::span<const double> time, double sample_rate,
                                                                 double cutoff, const std::vector<std::uint8_t>& filled);

// The same for samples taken unevenly about the even grid of `sample_rate` (`time` their own
// times): the displacement interpolated linearly onto the grid (a grid sample unmeasured when
// either recorded neighbour is), filtered there, and the velocity interpolated back to each
// sample's time. A motion is smooth at the grid's scale, so both interpolations cost little.
[[nodiscard]] std::vector<double> zero_phase_velocity_at_times(std::span<const double> displacement,
                                                               std::span<const double> time, double sample_rate,
                                                               double cutoff, const std::vector<std::uint8_t>& filled);

// A cutoff [Hz] for zero_phase_velocity from the motion itself: five times the frequency below
// which 99 % of the displacement's power lies (its |H|^2 is 0.9984 there), within
// [2 Hz, 0.2 x the sample rate].
[[nodiscard]] double motion_velocity_cutoff(const std::vector<double>& displacement, double sample_rate);

}  // namespace mrd::tools
