#include "tools/simulation/run_generator.hpp"

#include <cmath>
#include <memory>

#include "model/current_schedule.hpp"
#include "model/observer.hpp"
#include "sim/current_profile.hpp"
#include "sim/damper_plant.hpp"
#include "sim/displacement_profile.hpp"

namespace mrd::tools {

namespace {

constexpr std::array<std::pair<std::string_view, RunProfile>, 5> kProfiles = {{
    {"table4", RunProfile::kTable4},
    {"paper-sines", RunProfile::kPaperSines},
    {"sine", RunProfile::kSine},
    {"random", RunProfile::kRandom},
    {"telegraph", RunProfile::kTelegraph},
}};

const std::vector<double> kPaperFrequencies = {0.05, 0.1, 0.2, 0.5, 1.0};  // Section 4.2

bool is_sine(RunProfile p) { return p == RunProfile::kTable4 || p == RunProfile::kSine; }
bool is_random(RunProfile p) { return p == RunProfile::kRandom || p == RunProfile::kTelegraph; }
bool scheduled(RunProfile p) { return p == RunProfile::kTable4 || p == RunProfile::kPaperSines; }

// The rig's motion: one of the three displacement profiles.
sim::DisplacementProfile make_motion(const RunOptions& o) {
  if (is_sine(o.profile)) return sim::SineProfile{o.amplitude, o.frequency};
  if (o.profile == RunProfile::kPaperSines) return sim::SineSequenceProfile(o.amplitude, kPaperFrequencies, o.cycles);
  return sim::RandomProfile(o.amplitude, o.damper.random_low, o.damper.random_high, o.duration, 1.0 / o.rate,
                            o.seed + 17);
}

// The samples of one pass of the plant with `effects`.
std::vector<RunSample> run_plant(const RunOptions& o, const model::EffectSet& effects) {
  model::DamperModel truth = o.damper.model;
  truth.effects = effects;
  const double T = 1.0 / o.rate;
  sim::DamperPlant plant(truth, sim::PlantSettings{.sample_period = T,
                                                   .lvdt_noise_rms = o.lvdt_noise,
                                                   .force_noise_rms = o.force_noise,
                                                   .seed = static_cast<unsigned>(o.seed)});
  const sim::DisplacementProfile motion = make_motion(o);
  model::CurrentSchedule schedule(o.damper.schedule);
  sim::RandomTelegraph telegraph(0.0, o.current, o.dwell, T, o.seed + 29);
  const auto n = static_cast<std::size_t>(std::llround(o.duration * o.rate));
  std::vector<RunSample> samples;
  samples.reserve(n);
  double command = scheduled(o.profile) ? o.damper.schedule.currents[0] : o.current;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) * T;
    if (o.profile == RunProfile::kTelegraph) command = telegraph.step();
    const double x = motion.displacement(t);
    const sim::PlantReading r = plant.step({.displacement = x, .velocity = motion.velocity(t), .coil_current = command});
    samples.push_back({t, r.lvdt_displacement, r.sensor_velocity, command, r.measured_force, r.B,
                       r.temperature, x, r.force});
    // The schedule sees this period's reading; its current flows from the next period on.
    if (scheduled(o.profile)) command = schedule.update(r.lvdt_displacement);
  }
  return samples;
}

}  // namespace

std::optional<RunProfile> parse_run_profile(std::string_view name) {
  for (const auto& [text, profile] : kProfiles) {
    if (text == name) return profile;
  }
  return std::nullopt;
}

std::string_view to_string(RunProfile profile) {
  for (const auto& [text, p] : kProfiles) {
    if (p == profile) return text;
  }
  return "?";
}

RunOptions resolve(const RunOptions& options) {
  RunOptions o = options;
  const DamperClass& c = o.damper;
  if (!(o.amplitude > 0.0)) o.amplitude = c.amplitude;
  if (o.current < 0.0) o.current = o.profile == RunProfile::kTelegraph ? c.max_current : 0.5 * c.max_current;
  if (o.lvdt_noise < 0.0) o.lvdt_noise = c.lvdt_noise;
  if (o.force_noise < 0.0) o.force_noise = c.force_noise;
  if (!(o.duration > 0.0)) {
    if (is_sine(o.profile)) o.duration = 5.0 / o.frequency;
    if (is_random(o.profile)) o.duration = 30.0;
    if (o.profile == RunProfile::kPaperSines) o.duration = sim::SineSequenceProfile(1.0, kPaperFrequencies, o.cycles).duration();
  }
  return o;
}

std::string check(const RunOptions& o) {
  std::string problems;
  const auto need = [&](bool ok, const std::string& text) {
    if (!ok) problems += text + '\n';
  };
  need(o.rate >= 10.0 && o.rate <= 100000.0, "rate must be in 10..100000 Hz");
  need(std::isfinite(o.duration) && o.duration <= 86400.0, "duration must be at most a day");
  need(o.frequency > 0.0 && o.frequency <= 100.0, "frequency must be in (0, 100] Hz");
  need(std::isfinite(o.amplitude) && o.amplitude <= 1.0, "amplitude must be at most 1 m");
  need(std::isfinite(o.current) && o.current <= 10.0, "current must be at most 10 A");
  need(o.cycles >= 1, "cycles must be >= 1");
  need(o.dwell > 0.0 && std::isfinite(o.dwell), "dwell must be > 0 s");
  need(std::isfinite(o.lvdt_noise) && o.lvdt_noise <= 1e-2, "noise must be at most 1e-2 m");
  need(std::isfinite(o.force_noise) && o.force_noise <= 1e5, "force noise must be at most 1e5 N");
  for (std::size_t i = 0; i < o.effects.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      need(o.effects[i].name != o.effects[j].name, "effect " + o.effects[i].name + " is given twice");
    }
  }
  return problems;
}

SimulatedRun simulate_run(const RunOptions& options) {
  SimulatedRun run;
  run.options = resolve(options);
  const RunOptions& o = run.options;
  double dissipated = 0.0;
  for (const auto& request : o.effects) {
    const model::EffectInfo* info = model::find_effect(request.name);
    if (info == nullptr || !info->sized_by_dissipated_energy) continue;
    // Sized by the energy the clean run dissipates (damper_class.hpp): one clean run suffices.
    for (const auto& s : run_plant(o, {})) dissipated += std::max(s.true_force * s.velocity, 0.0) / o.rate;
    break;
  }
  for (const auto& request : o.effects) apply_effect(o.damper, request, dissipated, run.effects);
  run.samples = run_plant(o, run.effects);
  return run;
}

double model_residual(const SimulatedRun& run, const model::EffectSet& effects) {
  model::DamperModel damper = run.options.damper.model;
  damper.effects = effects;
  model::Observer observer(damper, {1.0 / run.options.rate});
  double sum = 0.0;
  for (const auto& s : run.samples) {
    const double e = observer.step({.displacement = s.displacement, .velocity = s.velocity, .coil_current = s.current}).force - s.force;
    sum += e * e;
  }
  return run.samples.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(run.samples.size()));
}

}  // namespace mrd::tools
