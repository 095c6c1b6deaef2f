#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace mrd::model {

// What an effect's descriptor holds (one struct per effect, next to its model: CoilLagEffect,
// GasSpringEffect, ...). The config, the observer's effect chain, the residual search, the
// simulator and the reports loop over the descriptors listed in effect_set.hpp: the code of an
// effect is its model file with its descriptor and one line in that list; the lists and documents
// that name every effect are in docs/ARCHITECTURE.md, "Adding an effect" (16 files in all). A
// descriptor derives from EffectTraitsBase and overrides what applies to it:
//   kName               the effect's name in configs ([damper.effects.<name>]), tools and reports
//   Params, Element     its parameters, and the run-time element the observer steps
//   kChangesInduction   whether it changes B for a given coil current (fits that hold B
//                       fixed cannot share a B trace with it)
//   kNamedCandidate     whether mrd-residual searches for it by name (learned terms: no)
//   kSeparatedBy, kTermForms
//                       the run that tells it apart, and the library terms it resembles
//                       (the ambiguity report and the discovery)
//   fields(p, v)        its TOML keys, v(key, field&) each, in file order
//   kSearch, apply, coordinates
//                       the parameters a run can identify, as search coordinates whose
//                       ranges follow the run's scales (RunScales)
//   kLinear, add_linear parameters that enter the force linearly (fitted by least squares)
//   kLinearNonNegative, linear_values
//                       which of them physics keeps >= 0, and their present values (the fit
//                       holds such a parameter at 0 rather than let it go negative)
//   scale_force         rescales its force-valued parameters with the damper's force scale
//   implausible         why a fitted instance is not a physical one, nullopt when it is
//   report(p, v)        the fitted values for reports, v(json_key_with_unit, value) each
//   nominal(c)          its parameters at size 1 on each damper class the simulator makes
//   resize, size_summary, kSizedByDissipatedEnergy
//                       what "size" means for runs the simulator makes (mrd-simulate-run)

// What a recorded run's scales say about the ranges worth searching.
struct RunScales {
  double sample_period = 0.0;      // [s]
  double duration = 0.0;           // of the longest run [s]
  double stroke = 0.0;             // 99.9th percentile of |x| [m]
  double speed = 0.0;              // 99th percentile of |v| [m/s]
  double dissipated_energy = 0.0;  // sum of max(F v, 0) dt over the longest run [J]
  bool measured_temperature = false;
};

// One search coordinate, in the units the search works in (often log10 of a parameter).
// kReversalThreshold: the coordinate is a stroke-end threshold over the stroke; the fitness
// is flat between two reversal amplitudes and jumps at each, so the search also scans them.
struct SearchCoordinate {
  enum class Kind { kContinuous, kReversalThreshold };
  std::string_view name;
  double (*lower)(const RunScales&);
  double (*upper)(const RunScales&);
  Kind kind = Kind::kContinuous;
};

// The damper classes the simulator makes runs of (tools/simulation/damper_class.cpp): the
// paper's 50 kN damper on its Table 4 rig, and a 1 kN damper of Dyke's and Spencer's size.
enum class DamperClassId { k50kN, k1kN };

// A column of the linear least-squares fit that an effect's parameter multiplies.
enum class LinearColumn { kConstant, kDisplacement };

template <typename P>
struct EffectTraitsBase {
  using Params = P;
  static constexpr bool kChangesInduction = false;
  // The simulator sizes it by the energy the clean run dissipates (resize's dissipated_energy).
  static constexpr bool kSizedByDissipatedEnergy = false;
  // A candidate of the residual search and an effect the simulator can carry.
  static constexpr bool kNamedCandidate = true;
  // A test run that tells this effect apart from the look-alikes the residual search can
  // confuse it with (reported when a run cannot decide between them).
  static constexpr std::string_view kSeparatedBy = "a run at other amplitudes and frequencies";
  // Terms of the discovery library (learned_terms.hpp) that are this effect's own physics: a
  // regression that explains the residual with them instead names the same thing, not a rival.
  static constexpr std::array<std::string_view, 0> kTermForms{};
  static constexpr std::array<SearchCoordinate, 0> kSearch{};
  static constexpr std::array<LinearColumn, 0> kLinear{};
  static constexpr std::array<bool, 0> kLinearNonNegative{};

  // Off, at its Params' defaults: an effect the simulator does not size by class.
  static P nominal(DamperClassId) { return P{}; }
  static void apply(P&, std::span<const double>, const RunScales&) {}
  static void coordinates(const P&, const RunScales&, std::span<double>) {}
  static void add_linear(P&, std::span<const double>) {}
  static void linear_values(const P&, std::span<double>) {}
  static void scale_force(P&, double) {}
  static std::optional<std::string> implausible(const P&, const RunScales&) { return std::nullopt; }
  template <typename Visitor>
  static void report(const P&, Visitor&&) {}
};

}  // namespace mrd::model
