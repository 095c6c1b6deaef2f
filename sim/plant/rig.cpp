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

Rig::Rig(const PlantConfig& config, Motion motion)
    : motion_(std::move(motion)),
      plant_(config.truth(), sim::PlantSettings{.sample_period = config.period(),
                                                .lvdt_noise_rms = config.lvdt_noise,
                                                .force_noise_rms = config.force_noise,
                                                .seed = config.seed}),
      faults_(config.faults) {}

const RigSample& Rig::step(const RigInput& in) {
  last_.time = in.t;
  last_.commanded = in.commanded;
  last_.reading = plant_.step(
      {.displacement = motion_.displacement(in.t), .velocity = motion_.velocity(in.t), .coil_current = in.commanded});
  last_.fault_time = in.fault_t;
  last_.faults = in.fault_t < 0.0 ? ActiveFaults{} : active_faults(faults_, in.fault_t);
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
