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

// Nominal heating of the lumped thermal model: the fluid warms this much over the run, and the
// fitted coefficients say what that does to viscosity and yield.
constexpr double kNominalRise = 20.0;  // [K]

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
  space.with_spring = origin.effects.gas_spring.enabled;
  space.edit = [](model::DamperModel m, const Point& p) {
    set_field_gain(m, p[0]);
    return m;
  };
  return space;
}

bool changes_induction(std::string_view effect) { return effect == "coil_lag"; }

ParameterSpace effect_space(const std::string& name, const model::DamperModel& model,
                            const SeriesScales& scales) {
  ParameterSpace space;
  space.name = name;
  space.origin = model;
  const double T = scales.sample_period;
  if (name == "coil_lag") {
    space.parameters = {"log10 time constant [s]"};
    space.bounds = make_bounds({{std::log10(0.5 * T), std::log10(0.5)}});
    space.edit = [](model::DamperModel m, const Point& p) {
      m.effects.coil_lag = {true, std::pow(10.0, p[0])};
      return m;
    };
  } else if (name == "sensor_delay") {
    const double longest = std::min(model::kMaxSensorDelay, 0.05 * scales.duration);
    // Logarithmic, so that a delay below one sample is as easy to find as one of 50 ms.
    space.parameters = {"log10 delay [s]"};
    space.bounds = make_bounds({{std::log10(0.1 * T), std::log10(std::max(longest, 2.0 * T))}});
    space.edit = [](model::DamperModel m, const Point& p) {
      m.effects.sensor_delay = {true, std::min(std::pow(10.0, p[0]), model::kMaxSensorDelay)};
      return m;
    };
  } else if (name == "thermal_drift") {
    const bool measured = scales.measured_temperature;
    const double energy = std::max(scales.dissipated_energy, 1e-9);
    space.parameters = measured ? std::vector<std::string>{"viscosity coefficient [1/K]", "yield coefficient [1/K]"}
                                : std::vector<std::string>{"viscous drop over the run", "yield drop over the run"};
    space.bounds = measured ? make_bounds({{0.0, 0.1}, {0.0, 0.05}}) : make_bounds({{0.0, 2.0}, {0.0, 0.9}});
    space.edit = [measured, energy](model::DamperModel m, const Point& p) {
      auto& t = m.effects.thermal_drift;
      t = model::ThermalDriftParams{};
      t.enabled = true;
      t.viscosity_law = model::TemperatureLaw::kExponential;
      t.yield_law = model::TemperatureLaw::kLinear;
      if (measured) {
        t.viscosity_coefficient = p[0];
        t.yield_coefficient = p[1];
      } else {
        // The drops are those of the nominal rise: C sized so the run's energy gives it.
        t.heat_capacity = energy / kNominalRise;
        t.viscosity_coefficient = p[0] / kNominalRise;
        t.yield_coefficient = p[1] / kNominalRise;
      }
      return m;
    };
  } else if (name == "preyield_hysteresis") {
    space.parameters = {"yield fraction w", "log10 z_max [m]"};
    space.bounds = make_bounds({{0.0, 1.0},
                                {std::log10(std::max(1e-6, 2e-3 * scales.stroke)), std::log10(0.2 * scales.stroke)}});
    space.edit = [](model::DamperModel m, const Point& p) {
      auto& h = m.effects.preyield_hysteresis;
      const double z_max = std::pow(10.0, p[1]);
      h.enabled = true;
      h.A = 1.0;
      h.n = 2.0;
      h.beta = h.gamma = 1.0 / (2.0 * z_max * z_max);
      h.stiffness = 0.0;
      h.yield_fraction = p[0];
      return m;
    };
  } else if (name == "stroke_end_air") {
    const double stroke = scales.stroke;
    space.parameters = {"threshold / stroke", "depth", "log10 length / stroke"};
    space.bounds = make_bounds({{0.3, 0.98}, {0.0, 0.95}, {-2.5, -0.5}});
    space.edit = [stroke](model::DamperModel m, const Point& p) {
      auto& a = m.effects.stroke_end_air;
      a.enabled = true;
      a.threshold = p[0] * stroke;
      a.depth = p[1];
      a.length = std::pow(10.0, p[2]) * stroke;
      a.reversal_travel = std::min(1e-4, 0.01 * stroke);
      return m;
    };
  } else if (name == "gas_spring") {
    space.parameters = {};
    space.bounds = Bounds{Point(0), Point(0)};
    space.with_spring = true;
    space.edit = [](model::DamperModel m, const Point&) { return m; };
  } else {
    throw std::invalid_argument("unknown effect: " + name);
  }
  return space;
}

Point effect_coordinates(const std::string& name, const model::DamperModel& m, const SeriesScales& scales) {
  const model::EffectSet& e = m.effects;
  const auto point = [](std::initializer_list<double> values) {
    Point p(static_cast<Eigen::Index>(values.size()));
    Eigen::Index i = 0;
    for (const double v : values) p[i++] = v;
    return p;
  };
  if (name == "coil_lag") return point({std::log10(e.coil_lag.time_constant)});
  if (name == "sensor_delay") return point({std::log10(e.sensor_delay.delay)});
  if (name == "thermal_drift") {
    const auto& t = e.thermal_drift;
    if (scales.measured_temperature) return point({t.viscosity_coefficient, t.yield_coefficient});
    return point({t.viscosity_coefficient * kNominalRise, t.yield_coefficient * kNominalRise});
  }
  if (name == "preyield_hysteresis")
    return point({e.preyield_hysteresis.yield_fraction, std::log10(e.preyield_hysteresis.z_max())});
  if (name == "stroke_end_air") {
    const auto& a = e.stroke_end_air;
    return point({a.threshold / scales.stroke, a.depth, std::log10(a.length / scales.stroke)});
  }
  return Point(0);
}

std::vector<Point> stroke_threshold_trials(const FitSeries& s, const SeriesScales& scales, const Point& fit,
                                           double lower, double upper, std::size_t count) {
  // Reversal amplitudes: the extreme |x| of each stretch of travel in one direction that ends
  // with a travel back of at least 1 % of the stroke (the noise cannot make one).
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
    p[0] = std::clamp(0.995 * amplitudes[i] / scales.stroke, 0.3, 0.98);
    if (std::none_of(trials.begin(), trials.end(), [&](const Point& q) { return q[0] == p[0]; })) trials.push_back(p);
  }
  return trials;
}

FittedModel scan_stroke_threshold(const ParameterSpace& space, const FitSeries& series, const SeriesScales& scales,
                                  const Point& theta, std::int64_t& evaluations) {
  const auto coarse = stroke_threshold_trials(series, scales, theta);
  const FittedModel best = best_of(space, series, coarse);
  double lower = 0.0, upper = 1.0;
  for (const Point& p : coarse) {
    if (p[0] < best.theta[0]) lower = std::max(lower, p[0]);
    if (p[0] > best.theta[0]) upper = std::min(upper, p[0]);
  }
  FittedModel fine = best_of(space, series, stroke_threshold_trials(series, scales, best.theta, lower, upper, 32));
  evaluations += best.evaluations + fine.evaluations;
  return fine;
}

std::optional<std::string> implausible(const std::string& name, const FittedModel& fit,
                                       const SeriesScales& scales) {
  const model::EffectSet& e = fit.model.effects;
  const double T = scales.sample_period;
  if (name == "coil_lag" && e.coil_lag.time_constant < T)
    return "time constant below one sample";
  if (name == "sensor_delay" && e.sensor_delay.delay < 0.25 * T) return "delay below a quarter sample";
  if (name == "thermal_drift" && fit.theta.size() == 2 && fit.theta[0] + fit.theta[1] < 0.01)
    return "drops below 1 %";
  if (name == "preyield_hysteresis" && e.preyield_hysteresis.yield_fraction < 0.02)
    return "yield fraction below 2 %";
  if (name == "stroke_end_air" && e.stroke_end_air.depth < 0.05) return "depth below 5 %";
  if (name == "gas_spring" && e.gas_spring.stiffness < 0.0)
    return "negative stiffness (a gas spring stiffens as it compresses)";
  return std::nullopt;
}

std::vector<std::pair<std::string, double>> effect_parameters(const std::string& name,
                                                              const model::EffectSet& e) {
  if (name == "coil_lag") return {{"time_constant_s", e.coil_lag.time_constant}};
  if (name == "sensor_delay") return {{"delay_s", e.sensor_delay.delay}};
  if (name == "thermal_drift") {
    const auto& t = e.thermal_drift;
    return {{"heat_capacity_J_K", t.heat_capacity},
            {"viscosity_coefficient_1_K", t.viscosity_coefficient},
            {"yield_coefficient_1_K", t.yield_coefficient}};
  }
  if (name == "preyield_hysteresis") {
    const auto& h = e.preyield_hysteresis;
    return {{"yield_fraction", h.yield_fraction}, {"z_max_m", h.z_max()}};
  }
  if (name == "stroke_end_air") {
    const auto& a = e.stroke_end_air;
    return {{"threshold_m", a.threshold}, {"depth", a.depth}, {"length_m", a.length}};
  }
  if (name == "gas_spring") return {{"preload_N", e.gas_spring.preload}, {"stiffness_N_m", e.gas_spring.stiffness}};
  return {};
}

}  // namespace mrd::tools
