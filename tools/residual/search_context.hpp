#pragma once

#include <atomic>
#include <cstdint>
#include <vector>

#include "model/bingham_damper.hpp"
#include "model/damper_model.hpp"
#include "model/effects/effect_set.hpp"
#include "tools/optimisation/worker_pool.hpp"
#include "tools/residual/candidate_effects.hpp"
#include "tools/residual/claim_evidence.hpp"
#include "tools/residual/fit_series.hpp"
#include "tools/residual/residual_result.hpp"

// The steps of find_missing_effects (residual_search.cpp), each in its own file; internal to
// tools/residual.
namespace mrd::tools::search {

using Effects = std::vector<const model::EffectInfo*>;

// What every step of the search shares: the series at its resolutions, the pool, the seed
// stream and the count of observer passes.
struct Search {
  Search(const FitSeries& series, const ResidualOptions& opts)
      : full(series),
        options(opts),
        fit_series(decimate(full, decimation_factor(full, opts.max_fit_samples), opts.min_fit_rate)),
        swarm_series(run_openings(fit_series, opts.max_swarm_samples)),
        scales(series_scales(fit_series)),
        blocks(validation_blocks(fit_series)),
        pool(opts.threads),
        seed(opts.seed) {}

  // The series as given: a copy, since the final step may time its current's steps within
  // their rows (switch_timing.hpp).
  FitSeries full;
  const ResidualOptions& options;
  FitSeries fit_series;    // what the fits run on; its loss is least squares unless --robust-fit
  FitSeries swarm_series;  // the runs' openings: where the swarms that move B explore
  const SeriesScales scales;
  const ValidationBlocks blocks;  // the fitting series' held-out pieces, for the claims
  // [N] the load cell's white noise as the base model's residual shows it: what a claim's
  // materiality is measured against. Set once the base is identified.
  double noise_floor = 0.0;
  WorkerPool pool;
  std::uint64_t seed;
  std::atomic<std::int64_t> evaluations{0};

  // The model's RMS error on the validation blocks of the fitting series [N].
  [[nodiscard]] double validation_rms(const model::DamperModel& m) const;
  // The model's force on the fitting series.
  [[nodiscard]] std::vector<double> predicted(const model::DamperModel& m) const;
  // The white noise of the kept samples' residual against `predicted` (on the fitting series:
  // from the sample-to-sample differences, which a model's smooth form error barely moves).
  [[nodiscard]] double white_noise_of(const std::vector<double>& predicted) const;
  // Whether the model predicting `richer` has earned its claim over the one predicting `simpler`
  // (on the fitting series), among `comparisons`.
  [[nodiscard]] ClaimEvidence weigh(const std::vector<double>& simpler, const std::vector<double>& richer,
                                    int comparisons) const {
    return weigh_claim(fit_series, blocks, simpler, richer, noise_floor, comparisons, options.claim);
  }
};

// The Bingham damper of the model's geometry and fluid: its viscous coefficient, and what the
// library of terms scales by.
inline model::BinghamDamper fluid_of(const model::DamperModel& m) {
  return model::BinghamDamper(m.geometry, m.fluid.viscosity, m.fluid.flow_index);
}

}  // namespace mrd::tools::search
