#include "tools/residual/candidate_effects.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "model/typical_ranges.hpp"
#include "tools/residual/residual_structure.hpp"
#include "tools/text_format.hpp"

namespace mrd::tools {

namespace {

Bounds make_bounds(std::initializer_list<std::pair<double, double>> ranges) {
  Bounds b{Point(static_cast<Eigen::Index>(ranges.size())), Point(static_cast<Eigen::Index>(ranges.size()))};
  Eigen::Index i = 0;
  for (const auto& [lo, hi] : ranges) {
    b.lower[i] = lo;
    b.upper[i] = hi;
    ++i;
  }
  return b;
}

// log10 of the field gain [turns/m]: within 1.5 decades of the starting coil's.
std::pair<double, double> field_gain_range(const model::DamperModel& start) {
  const double g = std::log10(start.circuit.turns / start.circuit.effective_length);
  return {g - 1.5, g + 1.5};
}

void set_field_gain(model::DamperModel& m, double log10_gain) {
  m.circuit.turns = std::pow(10.0, log10_gain) * m.circuit.effective_length;
}

}  // namespace

SeriesScales series_scales(const FitSeries& s) {
  SeriesScales out;
  out.sample_period = s.sample_period;
  out.stroke = std::max(percentile_abs(s.displacement, 0.999), 1e-6);
  out.speed = std::max(percentile_abs(s.velocity, 0.99), 1e-6);
  out.measured_temperature = !s.temperature.empty();
  const double largest = percentile_abs(s.current, 1.0);
  out.current_varies = current_varies(s);
  std::size_t steps = 0;
  for (std::size_t r = 0; r < s.run_starts.size(); ++r) {
    const std::size_t from = s.run_starts[r];
    const std::size_t to = r + 1 < s.run_starts.size() ? s.run_starts[r + 1] : s.size();
    double energy = 0.0;
    for (std::size_t i = from; i < to; ++i) {
      energy += std::max(s.force[i] * s.velocity[i], 0.0) * s.run_periods[r];
      if (i > from && std::fabs(s.current[i] - s.current[i - 1]) > 0.02 * largest) ++steps;
    }
    const double duration = static_cast<double>(to - from) * s.run_periods[r];
    if (duration > out.duration) {
      out.duration = duration;
      out.dissipated_energy = energy;
    }
  }
  out.current_steps = steps > 0;
  return out;
}

namespace {

// One base coordinate: its name for reports, its physical range in search units, and where it
// lives in the model.
struct BaseCoordinate {
  std::string name;
  std::pair<double, double> range;
  double (*get)(const model::DamperModel&);
  void (*set)(model::DamperModel&, double);
  // Edges that are a physical member of the family (atan and the knee of the sign shape, no mean
  // field): reported, but no reason to refuse the model.
  bool lower_is_physical = false;
  bool upper_is_physical = false;
};

double k_over_a(const model::DamperModel& m) { return std::log10(m.jiles_atherton.k / m.jiles_atherton.a); }

std::vector<BaseCoordinate> base_coordinate_table(const model::DamperModel& start, const SeriesScales& scales,
                                                  Magnetics magnetics) {
  std::vector<BaseCoordinate> out;
  magnetics = free_magnetics(scales, magnetics);
  if (magnetics != Magnetics::kKept) {
    out.push_back({"log10 field gain [turns/m]", field_gain_range(start),
                   [](const model::DamperModel& m) { return std::log10(m.circuit.turns / m.circuit.effective_length); },
                   [](model::DamperModel& m, double v) { set_field_gain(m, v); }});
  }
  if (magnetics == Magnetics::kMaterial) {
    // Soft irons to hard steels (model/typical_ranges.hpp): k / a, c over its whole meaning, and the
    // mean field short of the anhysteretic's fold (alpha Ms / 3a < 1, docs/MODEL.md).
    out.push_back({"log10 J-A k/a",
                   {std::log10(model::kTypicalPinningOverShape.lo), std::log10(model::kTypicalPinningOverShape.hi)}, k_over_a,
                   [](model::DamperModel& m, double v) { m.jiles_atherton.k = m.jiles_atherton.a * std::pow(10.0, v); }});
    out.push_back({"J-A c", {model::kTypicalReversibility.lo, model::kTypicalReversibility.hi},
                   [](const model::DamperModel& m) { return m.jiles_atherton.c; },
                   [](model::DamperModel& m, double v) { m.jiles_atherton.c = v; }});
    out.push_back({"J-A alpha Ms/3a", {model::kTypicalMeanFieldGain.lo, model::kTypicalMeanFieldGain.hi},
                   [](const model::DamperModel& m) { return m.jiles_atherton.mean_field_gain(); },
                   [](model::DamperModel& m, double v) {
                     m.jiles_atherton.alpha = v * 3.0 * m.jiles_atherton.a / m.jiles_atherton.Ms;
                   },
                   true, false});
  }
  if (scales.current_varies) {
    // Power laws of MR fluids' yield stress in B run from about 0.3 to 1.2 (Eq. 13: 0.5811).
    out.push_back({"yield exponent of B", {model::kTypicalFieldExponent.lo, model::kTypicalFieldExponent.hi},
                   [](const model::DamperModel& m) { return m.fluid.field_exponent; },
                   [](model::DamperModel& m, double v) { m.fluid.field_exponent = v; }});
    // The yield stress's ceiling, from 0.05 T (it bends early: a force record fixes B only up to
    // the scale that a and Ms share) to the top, 30 T, which is none (Eq. 13's plain power law).
    out.push_back({"log10 yield saturation B_s [T]", {std::log10(0.05), std::log10(30.0)},
                   [](const model::DamperModel& m) {
                     return m.fluid.saturation_induction > 0.0 ? std::log10(m.fluid.saturation_induction) : std::log10(30.0);
                   },
                   [](model::DamperModel& m, double v) {
                     // The top of the range is no saturation at all, so the paper's law is a point of it.
                     m.fluid.saturation_induction = v >= std::log10(30.0) - 1e-9 ? 0.0 : std::pow(10.0, v);
                   }});
    // Past 1 the knee sharpens towards a hard cap: a power law that stops at the particles' saturation.
    out.push_back({"yield saturation shape (-1 slow, 0 tanh, 1 knee, 2 corner)", {-1.0, 2.0},
                   [](const model::DamperModel& m) { return m.fluid.saturation_shape; },
                   [](model::DamperModel& m, double v) { m.fluid.saturation_shape = v; }, true, true});
  }
  // The sign velocity: from 0.1 % of the run's speed to 15 % of it and at most 50 mm/s, so that
  // the yield term cannot take the viscous term's place (a v_s near the speed makes s(v) linear).
  // A slow run still reaches 10 mm/s or half its speed: dampers smooth their sign over up to
  // that whatever the motion (on a run at 24 mm/s, 15 % stopped a damper's 4 mm/s short).
  const double v_lo = std::log10(std::max(1e-3 * scales.speed, 1e-6));
  const double v_top = std::max(0.15 * scales.speed, std::min(0.01, 0.5 * scales.speed));
  const double v_hi = std::log10(std::max(std::min(v_top, model::kTypicalSignVelocity.hi), 2e-6));
  out.push_back({"log10 sign velocity [m/s]", {v_lo, v_hi},
                 [](const model::DamperModel& m) { return std::log10(m.geometry.sign_velocity_scale); },
                 [](model::DamperModel& m, double v) { m.geometry.sign_velocity_scale = std::pow(10.0, v); }});
  out.push_back({"sign shape (-1 atan, 0 tanh, 1 knee)", {-1.0, 1.0},
                 [](const model::DamperModel& m) { return m.geometry.sign_shape; },
                 [](model::DamperModel& m, double v) { m.geometry.sign_shape = v; }, true, true});
  out.push_back({"flow index n", {model::kTypicalFlowIndex.lo, model::kTypicalFlowIndex.hi},
                 [](const model::DamperModel& m) { return m.fluid.flow_index; },
                 [](model::DamperModel& m, double v) { m.fluid.flow_index = v; }});
  return out;
}

}  // namespace

std::vector<std::string> base_coordinates_at_edge(const model::DamperModel& model, const model::DamperModel& start,
                                                  const SeriesScales& scales, Magnetics magnetics, bool unphysical_only) {
  std::vector<std::string> out;
  for (const BaseCoordinate& c : base_coordinate_table(start, scales, magnetics)) {
    const auto [lo, hi] = c.range;
    const double v = c.get(model);
    const double margin = 1e-3 * (hi - lo);
    const bool none_at_top = c.name.starts_with("log10 yield saturation");
    const bool at_lower = !(v > lo + margin) && !(unphysical_only && c.lower_is_physical);
    const bool at_upper = !none_at_top && !(v < hi - margin) && !(unphysical_only && c.upper_is_physical);
    if (at_lower || at_upper) {
      out.push_back(format("%s at the edge of its physical range [%.3g, %.3g]", c.name.c_str(), lo, hi));
    }
  }
  return out;
}

Magnetics free_magnetics(const SeriesScales& scales, Magnetics wanted) {
  return scales.current_varies ? wanted : Magnetics::kKept;
}

ParameterSpace base_space(const model::DamperModel& origin, const model::DamperModel& start,
                          const SeriesScales& scales, Magnetics magnetics) {
  const std::vector<BaseCoordinate> table = base_coordinate_table(start, scales, magnetics);
  ParameterSpace space;
  space.name = "base";
  space.origin = origin;
  const auto n = static_cast<Eigen::Index>(table.size());
  space.bounds = Bounds{Point(n), Point(n)};
  std::vector<void (*)(model::DamperModel&, double)> setters;
  for (Eigen::Index i = 0; i < n; ++i) {
    const BaseCoordinate& c = table[static_cast<std::size_t>(i)];
    space.parameters.push_back(c.name);
    space.bounds.lower[i] = c.range.first;
    space.bounds.upper[i] = c.range.second;
    setters.push_back(c.set);
  }
  space.edit = [setters](model::DamperModel m, const Point& p) {
    for (std::size_t i = 0; i < setters.size(); ++i) setters[i](m, p[static_cast<Eigen::Index>(i)]);
    return m;
  };
  return space;
}

Point base_coordinates(const model::DamperModel& m, const model::DamperModel& start, const SeriesScales& scales,
                       Magnetics magnetics) {
  const std::vector<BaseCoordinate> table = base_coordinate_table(start, scales, magnetics);
  Point p(static_cast<Eigen::Index>(table.size()));
  for (std::size_t i = 0; i < table.size(); ++i) {
    // A model outside a range (a config's prior) starts on its edge.
    const double v = table[i].get(m);
    p[static_cast<Eigen::Index>(i)] = std::clamp(v, table[i].range.first, table[i].range.second);
  }
  return p;
}

ParameterSpace field_gain_space(const model::DamperModel& origin, const model::DamperModel& start) {
  ParameterSpace space;
  space.name = "field gain";
  space.origin = origin;
  space.parameters = {"log10 field gain [turns/m]"};
  space.bounds = make_bounds({field_gain_range(start)});
  for (const model::EffectInfo& e : model::effect_infos()) {
    if (!e.linear.empty() && e.enabled(origin.effects)) space.linear.push_back(&e);
  }
  space.edit = [](model::DamperModel m, const Point& p) {
    set_field_gain(m, p[0]);
    return m;
  };
  return space;
}

ParameterSpace effect_space(const model::EffectInfo& effect, const model::DamperModel& model,
                            const SeriesScales& scales) {
  ParameterSpace space;
  space.name = effect.name;
  space.origin = model;
  const auto n = static_cast<Eigen::Index>(effect.search.size());
  space.bounds = Bounds{Point(n), Point(n)};
  for (Eigen::Index i = 0; i < n; ++i) {
    const model::SearchCoordinate& c = effect.search[static_cast<std::size_t>(i)];
    space.parameters.emplace_back(c.name);
    space.bounds.lower[i] = c.lower(scales);
    space.bounds.upper[i] = c.upper(scales);
  }
  if (!effect.linear.empty()) space.linear.push_back(&effect);
  const model::RunScales run = scales;
  space.edit = [&effect, run](model::DamperModel m, const Point& p) {
    effect.apply(m.effects, std::span<const double>(p.data(), static_cast<std::size_t>(p.size())), run);
    return m;
  };
  return space;
}

Point effect_coordinates(const model::EffectInfo& effect, const model::DamperModel& m, const SeriesScales& scales) {
  Point p(static_cast<Eigen::Index>(effect.search.size()));
  effect.coordinates(m.effects, scales, std::span<double>(p.data(), static_cast<std::size_t>(p.size())));
  return p;
}

std::vector<double> reversal_amplitudes(const FitSeries& s, const SeriesScales& scales) {
  std::vector<double> amplitudes;
  const double travel_back = 0.01 * scales.stroke;
  for (std::size_t r = 0; r < s.run_starts.size(); ++r) {
    const std::size_t from = s.run_starts[r];
    const std::size_t to = r + 1 < s.run_starts.size() ? s.run_starts[r + 1] : s.size();
    double extreme = s.displacement[from];
    int direction = 0;
    for (std::size_t i = from + 1; i < to; ++i) {
      const double x = s.displacement[i];
      if (direction >= 0 && x > extreme) {
        extreme = x;
        direction = 1;
      } else if (direction <= 0 && x < extreme) {
        extreme = x;
        direction = -1;
      } else if (std::fabs(x - extreme) > travel_back) {
        amplitudes.push_back(std::fabs(extreme));
        direction = -direction;
        extreme = x;
      }
    }
  }
  std::sort(amplitudes.begin(), amplitudes.end());
  return amplitudes;
}

std::vector<Point> reversal_threshold_trials(const FitSeries& s, const SeriesScales& scales, const Point& fit,
                                             Eigen::Index index, double lower, double upper, std::size_t count) {
  std::vector<double> amplitudes = reversal_amplitudes(s, scales);
  std::erase_if(amplitudes, [&](double a) {
    const double threshold = 0.995 * a / scales.stroke;
    return threshold < std::max(lower, 0.3) || threshold > std::min(upper, 0.98);
  });
  amplitudes.erase(std::unique(amplitudes.begin(), amplitudes.end()), amplitudes.end());
  std::vector<Point> trials{fit};
  if (amplitudes.empty()) return trials;
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = k * (amplitudes.size() - 1) / std::max<std::size_t>(count - 1, 1);
    Point p = fit;
    p[index] = std::clamp(0.995 * amplitudes[i] / scales.stroke, 0.3, 0.98);
    if (std::none_of(trials.begin(), trials.end(), [&](const Point& q) { return q[index] == p[index]; })) {
      trials.push_back(p);
    }
  }
  return trials;
}

bool has_reversal_threshold(const model::EffectInfo& effect) {
  return std::ranges::any_of(effect.search, [](const model::SearchCoordinate& c) {
    return c.kind == model::SearchCoordinate::Kind::kReversalThreshold;
  });
}

FittedModel scan_reversal_thresholds(const model::EffectInfo& effect, const ParameterSpace& space,
                                     const FitSeries& series, const SeriesScales& scales, const Point& theta,
                                     std::int64_t& evaluations) {
  FittedModel fit;
  fit.theta = theta;
  for (std::size_t k = 0; k < effect.search.size(); ++k) {
    if (effect.search[k].kind != model::SearchCoordinate::Kind::kReversalThreshold) continue;
    const auto i = static_cast<Eigen::Index>(k);
    const auto coarse = reversal_threshold_trials(series, scales, fit.theta, i);
    const FittedModel best = best_of(space, series, coarse);
    double lower = 0.0, upper = 1.0;
    for (const Point& p : coarse) {
      if (p[i] < best.theta[i]) lower = std::max(lower, p[i]);
      if (p[i] > best.theta[i]) upper = std::min(upper, p[i]);
    }
    fit = best_of(space, series, reversal_threshold_trials(series, scales, best.theta, i, lower, upper, 32));
    evaluations += best.evaluations + fit.evaluations;
  }
  return fit;
}

}  // namespace mrd::tools
