#pragma once

#include <cmath>
#include <optional>
#include <span>
#include <string>

#include "common/validation_report.hpp"
#include "model/current_range.hpp"
#include "model/effects/effect_traits.hpp"

namespace mrd::model {

// The coil (and its driver) lag behind the commanded current: a first-order lag
//   tau di/dt = u - i,
// the L/R time constant of the coil and the driver's current loop lumped into one tau.
// Spencer et al. (1997) model the same lag for Dyke's damper as u' = -eta (u - v) with
// eta = 190 1/s, i.e. tau = 1/eta = 5.3 ms.
struct CoilLagParams {
  bool enabled = false;
  double time_constant = 5e-3;  // tau [s]; 0 means no lag

  bool operator==(const CoilLagParams&) const = default;
};

ValidationReport validate(const CoilLagParams& params);

// Exact zero-order-hold discretisation: a command held over one period T moves the current by
// (1 - exp(-T/tau)) of the distance to it, whatever T/tau is, so the lag is stable and exact at
// any sample rate. No heap, no exceptions.
class CoilLag {
 public:
  CoilLag(const CoilLagParams& params, double sample_period);

  // `command` [A] held over this period; returns the current at its end [A]. A non-finite
  // command holds the present current (the observer must not be poisoned by one bad value).
  double step(double command);
  [[nodiscard]] double current() const { return current_; }
  void reset(double current = 0.0) { current_ = current; }
  // The next steps' length [s], for samples taken unevenly (EffectChain::set_step).
  void set_step(double dt);

  // The lag inverted over one period `dt` [s]: the command that, held over dt, brings the
  // current from its present value to `target_current` [A] exactly,
  //   u = i + (target - i) / (1 - exp(-dt/tau)),
  // clamped to what the driver may command.
  [[nodiscard]] double command_for(double target_current, double dt, const CurrentRange& driver) const;
  // The currents that can flow at the end of `dt` for commands in `driver`: the lag's step
  // from the two ends (it is monotone in the command).
  [[nodiscard]] CurrentRange reachable(double dt, const CurrentRange& driver) const;

 private:
  [[nodiscard]] double gain_over(double dt) const;

  double time_constant_;  // tau [s]
  double period_;         // the period gain_ holds for [s]
  double gain_;           // 1 - exp(-T/tau)
  double current_ = 0.0;
};

// The descriptor (effect_traits.hpp): a lag from a tenth of a sample to half a second.
struct CoilLagEffect : EffectTraitsBase<CoilLagParams> {
  using Element = CoilLag;
  static constexpr std::string_view kName = "coil_lag";
  static constexpr std::string_view kSeparatedBy =
      "current steps at a held displacement or a slow motion (the lag shows at each switch)";
  static constexpr bool kChangesInduction = true;
  // Hook (effect_chain.hpp): the current that flows, from the one commanded.
  static double coil_current(Element& lag, double command) { return lag.step(command); }
  // Its inverse (EffectChain::reachable_current, command_for).
  static CurrentRange reachable_current(const Element& lag, double dt, const CurrentRange& commands) {
    return lag.reachable(dt, commands);
  }
  static double command_for(const Element& lag, double flowing, double dt, const CurrentRange& commands) {
    return lag.command_for(flowing, dt, commands);
  }

  template <typename Visitor>
  static void fields(Params& p, Visitor&& v) {
    v("enabled", p.enabled);
    v("time_constant", p.time_constant);
  }

  static constexpr std::array kSearch = {SearchCoordinate{
      "log10 time constant [s]", [](const RunScales& s) { return std::log10(0.5 * s.sample_period); },
      [](const RunScales&) { return std::log10(0.5); }}};
  static void apply(Params& p, std::span<const double> x, const RunScales&) { p = {true, std::pow(10.0, x[0])}; }
  static void coordinates(const Params& p, const RunScales&, std::span<double> x) {
    x[0] = std::log10(p.time_constant);
  }
  static std::optional<std::string> implausible(const Params& p, const RunScales& s);
  template <typename Visitor>
  static void report(const Params& p, Visitor&& v) {
    v("time_constant_s", p.time_constant);
  }
  static Params nominal(DamperClassId damper) {
    // A large coil's L/R is tens of ms; Spencer 1997 fitted 1/190 s on Dyke's damper.
    return {.enabled = false, .time_constant = damper == DamperClassId::k50kN ? 20e-3 : 1.0 / 190.0};
  }
  static void resize(Params& p, double size, double /*dissipated_energy*/) {
    p.enabled = true;
    p.time_constant *= size;
  }
  static std::string size_summary(const Params& p);
};

}  // namespace mrd::model
