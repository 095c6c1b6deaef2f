#include "tools/residual/candidate_effects.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tools/residual/residual_structure.hpp"

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
  const auto [lo, hi] = std::minmax_element(s.current.begin(), s.current.end());
  out.current_varies = largest > 0.0 && (*hi - *lo) > 0.05 * largest;
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

ParameterSpace base_space(const model::DamperModel& origin, const model::DamperModel& start,
                          const SeriesScales& scales, FieldGain gain) {
  ParameterSpace space;
  space.name = "base";
  space.origin = origin;
  const double v_lo = std::log10(1e-3 * scales.speed);
  const double v_hi = std::log10(0.5 * scales.speed);
  if (scales.current_varies && gain == FieldGain::kFitted) {
    const auto g = field_gain_range(start);
    space.parameters = {"log10 field gain [turns/m]", "log10 sign velocity [m/s]"};
    space.bounds = make_bounds({g, {v_lo, v_hi}});
    space.edit = [](model::DamperModel m, const Point& p) {
      set_field_gain(m, p[0]);
      m.geometry.sign_velocity_scale = std::pow(10.0, p[1]);
      return m;
    };
  } else {
    space.parameters = {"log10 sign velocity [m/s]"};
    space.bounds = make_bounds({{v_lo, v_hi}});
    space.edit = [](model::DamperModel m, const Point& p) {
      m.geometry.sign_velocity_scale = std::pow(10.0, p[0]);
      return m;
    };
  }
  return space;
}

Point base_coordinates(const model::DamperModel& m, const SeriesScales& scales, FieldGain gain) {
  const double v = std::log10(m.geometry.sign_velocity_scale);
  if (!scales.current_varies || gain == FieldGain::kKept) return Point::Constant(1, v);
  Point p(2);
  p << std::log10(m.circuit.turns / m.circuit.effective_length), v;
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
