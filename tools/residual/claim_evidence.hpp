#pragma once

#include <string>
#include <vector>

#include "tools/residual/fit_series.hpp"

// When a richer model (an effect added) has earned its claim over a simpler one: paired block
// cross-validation on the held-out blocks, judged against the noise (docs/CLOSING-THE-LOOP.md,
// "Claims"). A fixed relative threshold is blind to how much of a fall the noise could make and
// how much of it is the model's form.
namespace mrd::tools {

// The pieces of the held-out blocks the paired comparison counts: each run's validation
// stretches (maximal spans without a fitting sample), a stretch of several adjacent blocks cut
// back into blocks of the run's shortest stretch, and each block into `pieces_per_block` pieces
// (none under 25 samples). An effect acts where its cause is (a reversal beyond a threshold, a
// switch of the current), so at any one phase of a periodic motion or not at all: a dozen
// blocks of a few cycles each differ too much for their spread to show how consistent a large
// fall is; pieces do. Where the residual is white, at the floor, where chance matters, the
// pieces are independent.
struct ValidationBlocks {
  std::vector<int> of_sample;  // per sample: its piece, or -1 for a fitting or excluded one
  int count = 0;
};

ValidationBlocks validation_blocks(const FitSeries& series, int pieces_per_block = 8);

struct ClaimCriterion {
  // Family-wise confidence over the comparisons one decision makes (a round's candidates), shared
  // by the two tests of significance below.
  double confidence = 0.95;
  // The least an effect must remove of the simpler model's validation mean square above the
  // white-noise floor: far above the floor the residual is mostly the model's form, which any
  // flexible effect soaks up in part (docs/CLOSING-THE-LOOP.md, "Claims": why a fifth).
  double excess_share = 0.2;
  // ... and never less than this share of the noise's variance (an effect of half the noise's
  // RMS): at the floor, what an accepted effect's fit leaves of its own shape is small but
  // systematic, so significant, and a flexible candidate soaks it up (a tenth let a thermal
  // drift in beside the stroke-end air of the detection study's 1 kN telegraph run).
  double noise_share = 0.25;
};

// The fall is significant when either test passes at half the family's risk:
//  - across the pieces: the fall's mean over them against its standard error from their spread
//    (Student's t): the fall is seen throughout the held-out run;
//  - against the noise: were the richer model's change of prediction d unrelated to the force,
//    the fall sum(r0^2 - r1^2) = sum(2 r0 d - d^2) would have mean -sum(d^2) and standard
//    deviation 2 sigma sqrt(sum(d^2)) for white noise of sigma; z is the fall over that
//    deviation (normal quantile). It credits an effect that acts at a few events only (a delay
//    at the reversals, a lag at the switches) with what it removes there, which the pieces'
//    spread would hide.
struct ClaimEvidence {
  int pieces = 0;
  double noise_floor = 0.0;     // [N] white-noise RMS the materiality is measured against
  double simpler_ms = 0.0;      // [N^2] validation mean square of the simpler model
  double reduction = 0.0;       // [N^2] of the validation mean square, richer against simpler
  double required = 0.0;        // [N^2] the materiality
  double standard_error = 0.0;  // [N^2] of the reduction, from its spread over the pieces
  double t = 0.0;
  double t_required = 0.0;
  double z = 0.0;  // against the noise
  double z_required = 0.0;
  [[nodiscard]] bool weighable() const { return pieces >= 2; }
  [[nodiscard]] bool significant() const { return weighable() && (t >= t_required || z >= z_required); }
  [[nodiscard]] bool material() const { return weighable() && reduction >= required; }
  [[nodiscard]] bool passes() const { return significant() && material(); }
  // How far the claim stands from failing, as the smaller of its significance (the better test's
  // statistic over its quantile) and its materiality (the fall over the one required): below 1 it
  // fails. What the set revision ranks its effects by.
  [[nodiscard]] double margin() const;
  // One clause with the figures: the fall against the one required, then t and z.
  [[nodiscard]] std::string describe() const;
};

// Whether the model that predicts `richer` has earned its claim over the one that predicts
// `simpler` (per sample of `series`), among `comparisons` >= 1 made at once. Under a robust loss
// (--robust-fit) the "mean squares" are means of the loss, and z errs on the cautious side
// (the loss grows more slowly than the square). A noise floor of 0 leaves t alone to decide.
ClaimEvidence weigh_claim(const FitSeries& series, const ValidationBlocks& pieces, const std::vector<double>& simpler,
                          const std::vector<double>& richer, double noise_floor, int comparisons,
                          const ClaimCriterion& criterion);

// Student's t quantile: the t with P(T <= t) = p for `dof` degrees of freedom (p in (0.5, 1)).
double student_t_quantile(double p, double dof);
// The standard normal's (p in (0.5, 1)).
double normal_quantile(double p);

}  // namespace mrd::tools
