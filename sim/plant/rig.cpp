#include "sim/plant/rig.hpp"

#include "record/run_reader.hpp"

namespace mrd::plant {

ActiveFaults active_faults(const std::vector<Fault>& faults, double t) {
  ActiveFaults a;
  for (const Fault& f : faults) {
    if (!f.active(t)) continue;
    a.on[static_cast<std::size_t>(f.kind)] = true;
    a.value[static_cast<std::size_t>(f.kind)] = f.value;
  }
  return a;
}

Motion make_motion(const PlantConfig& config) {
  const ProfileConfig& p = config.profile;
  switch (p.kind) {
    case ProfileKind::kSine: return sim::SineProfile{p.amplitude, p.frequency};
    case ProfileKind::kSines:
      return sim::SineSequenceProfile(p.amplitude, {p.frequencies.begin(), p.frequencies.end()},
                                      p.cycles);
    case ProfileKind::kRandom:
      return sim::RandomProfile(p.amplitude, p.random_low, p.random_high, p.random_length,
                                config.period(), config.seed);
    case ProfileKind::kPlayback: {
      record::RecordedRun run = record::read_recorded_run(p.file);
      return sim::PlaybackProfile(std::move(run.time), std::move(run.displacement));
    }
  }
  return sim::SineProfile{};
}

double motion_length(const Motion& motion) {
  return std::visit(
      [](const auto& m) -> double {
        using M = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<M, sim::SineProfile>) {
          return 0.0;
        } else if constexpr (std::is_same_v<M, sim::RandomProfile>) {
          return 0.0;  // its span is in the config; it keeps moving past it
        } else {
          return m.duration();
        }
      },
      motion);
}

Rig::Rig(const PlantConfig& config, Motion motion)
    : motion_(std::move(motion)),
      plant_(config.truth(), sim::PlantSettings{.sample_period = config.period(),
                                                .lvdt_noise_rms = config.lvdt_noise,
                                                .force_noise_rms = config.force_noise,
                                                .seed = config.seed}),
      faults_(config.faults) {}

const RigSample& Rig::step(double t, double fault_t, double commanded) {
  const auto [x, v] = std::visit(
      [t](const auto& m) { return std::pair{m.displacement(t), m.velocity(t)}; }, motion_);
  last_.time = t;
  last_.commanded = commanded;
  last_.reading = plant_.step({.displacement = x, .velocity = v, .coil_current = commanded});
  last_.fault_time = fault_t;
  last_.faults = fault_t < 0.0 ? ActiveFaults{} : active_faults(faults_, fault_t);
  double lvdt = last_.reading.lvdt_displacement;
  if (last_.faults.has(FaultKind::kLvdtFrozen)) {
    if (!frozen_) frozen_ = last_.lvdt;  // the value it had when the fault began
    lvdt = *frozen_;
  } else {
    frozen_.reset();
  }
  if (last_.faults.has(FaultKind::kLvdtOutOfRange)) lvdt = last_.faults.value_of(FaultKind::kLvdtOutOfRange);
  last_.lvdt = lvdt;
  return last_;
}

}  // namespace mrd::plant
