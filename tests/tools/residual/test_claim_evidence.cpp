// The claim criterion: Student's quantile against printed tables, the held-out blocks as the
// series' roles lay them out, and the paired comparison on noise drawn here (Gaussian, of known
// sigma): figures worked by hand, an effect of 0.6 sigma named and one of 0.4 not, chance and a
// trade-off not significant, far above the floor an effect must take its share of the form
// error, and one that acts at a few events credited against the noise.
#include "tools/residual/claim_evidence.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace claim_evidence_tests {

using namespace mrd::tools;

// Student's t quantiles as printed in the usual tables (6 figures).
TEST(StudentT, QuantilesMatchThePrintedTables) {
  EXPECT_NEAR(student_t_quantile(0.975, 1.0), 12.7062, 1e-4);
  EXPECT_NEAR(student_t_quantile(0.975, 10.0), 2.22814, 1e-5);
  EXPECT_NEAR(student_t_quantile(0.995, 5.0), 4.03214, 1e-5);
  EXPECT_NEAR(student_t_quantile(0.999, 11.0), 4.02470, 1e-5);
  EXPECT_NEAR(student_t_quantile(0.9995, 30.0), 3.64596, 1e-5);
  EXPECT_NEAR(student_t_quantile(0.95, 1000.0), 1.64638, 1e-5);
}

// One run of `blocks` blocks of `per_block` samples, the roles given per block ('f' fitting,
// 'v' validation).
FitSeries laid_out(const std::string& roles, std::size_t per_block) {
  FitSeries s;
  s.run_starts = {0};
  for (const char r : roles)
    for (std::size_t i = 0; i < per_block; ++i) {
      s.role.push_back(r == 'v' ? SampleRole::kValidation : SampleRole::kFitting);
      s.force.push_back(0.0);
      s.displacement.push_back(0.0);
    }
  return s;
}

TEST(ValidationBlocks, AdjacentHeldOutBlocksAreCutBackToOneBlockEach) {
  FitSeries s = laid_out("fvvfvfvvvf", 100);
  s.role[450] = SampleRole::kExcluded;  // inside the lone block: it neither ends nor joins it
  const ValidationBlocks b = validation_blocks(s, 1);
  EXPECT_EQ(b.count, 6);
  EXPECT_EQ(b.of_sample[0], -1);
  EXPECT_EQ(b.of_sample[100], 0);
  EXPECT_EQ(b.of_sample[199], 0);
  EXPECT_EQ(b.of_sample[200], 1);
  EXPECT_EQ(b.of_sample[299], 1);
  EXPECT_EQ(b.of_sample[300], -1);
  EXPECT_EQ(b.of_sample[450], -1);
  EXPECT_EQ(b.of_sample[499], 2);
  EXPECT_EQ(b.of_sample[600], 3);
  EXPECT_EQ(b.of_sample[750], 4);
  EXPECT_EQ(b.of_sample[899], 5);
  EXPECT_EQ(b.of_sample[900], -1);
  // Each block in pieces of at least 25 samples: four of the 100.
  const ValidationBlocks pieces = validation_blocks(s, 8);
  EXPECT_EQ(pieces.count, 24);
  EXPECT_EQ(pieces.of_sample[124], 0);
  EXPECT_EQ(pieces.of_sample[125], 1);
  EXPECT_EQ(pieces.of_sample[299], 7);
  EXPECT_EQ(validation_blocks(s, 2).count, 12);
}

TEST(ValidationBlocks, EachRunNumbersOnFromTheOneBefore) {
  FitSeries s = laid_out("fvfv", 50);
  const FitSeries second = laid_out("vvff", 50);
  s.run_starts.push_back(s.role.size());
  s.role.insert(s.role.end(), second.role.begin(), second.role.end());
  s.force.insert(s.force.end(), second.force.begin(), second.force.end());
  s.displacement.insert(s.displacement.end(), second.displacement.begin(), second.displacement.end());
  const ValidationBlocks b = validation_blocks(s, 1);
  EXPECT_EQ(b.count, 3);  // the second run's stretch is its own shortest: one block
  EXPECT_EQ(b.of_sample[200], 2);
  EXPECT_EQ(b.of_sample[299], 2);
}

// Paired data: a force of `form(t)` plus Gaussian noise of 1 N on 24 blocks of 1,000 samples,
// every other block held out; the simpler model predicts `simpler(t)`, the richer `richer(t)`.
template <class Form, class Simpler, class Richer>
ClaimEvidence weighed(Form form, Simpler simpler, Richer richer, std::uint32_t seed = 11, int comparisons = 10) {
  std::string roles;
  for (int b = 0; b < 24; ++b) roles += b % 2 ? 'v' : 'f';
  FitSeries s = laid_out(roles, 1000);
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> p0(s.size()), p1(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double t = 1e-3 * static_cast<double>(i);
    s.force[i] = form(t) + noise(rng);
    p0[i] = simpler(t);
    p1[i] = richer(t);
  }
  return weigh_claim(s, validation_blocks(s), p0, p1, 1.0, comparisons, {});
}

const auto kZero = [](double) { return 0.0; };

double wave(double t, double rms) { return rms * std::numbers::sqrt2 * std::sin(2.0 * std::numbers::pi * 1.3 * t); }

// Figures worked by hand. One run of four 50-sample blocks, the second and fourth held out (two
// pieces of 25 each); the force is 3 N on every held-out sample, the simpler model predicts 0
// and the richer 3, 3, 2 and 1 N on the four pieces; the noise floor is 2 N. Per piece the mean
// square falls by 9, 9, 8 and 5 N^2: mean 7.75, sample variance 10.75/3, standard error
// sqrt(10.75/3)/2 = 0.94648, t = 8.1882. The whole fall is 25 (9 + 9 + 8 + 5) = 775 N^2 against
// sum(d^2) = 25 (9 + 9 + 4 + 1) = 575 N^2: z = 775 / (2 x 2 x sqrt(575)) = 8.0799. The simpler
// model's mean square 9 N^2 is 5 over the floor's 4, a fifth of that 1 N^2; a quarter of the
// noise's 4 N^2 is 1 N^2 as well: 1 N^2 is needed.
TEST(ClaimCriterion, FiguresWorkedByHand) {
  FitSeries s = laid_out("fvfv", 50);
  const double richer_by_piece[] = {3.0, 3.0, 2.0, 1.0};
  std::vector<double> simpler(s.size(), 0.0), richer(s.size(), 0.0);
  int piece = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.role[i] != SampleRole::kValidation) continue;
    s.force[i] = 3.0;
    richer[i] = richer_by_piece[piece];
    if ((i + 1) % 25 == 0) ++piece;
  }
  const ClaimEvidence e = weigh_claim(s, validation_blocks(s), simpler, richer, 2.0, 1, {});
  EXPECT_EQ(e.pieces, 4);
  EXPECT_NEAR(e.simpler_ms, 9.0, 1e-12);
  EXPECT_NEAR(e.reduction, 7.75, 1e-12);
  EXPECT_NEAR(e.standard_error, 0.94648, 1e-5);
  EXPECT_NEAR(e.t, 8.1882, 1e-4);
  EXPECT_NEAR(e.z, 8.0799, 1e-4);
  EXPECT_NEAR(e.required, 1.0, 1e-12);
  EXPECT_TRUE(e.passes());
  EXPECT_NEAR(e.margin(), std::min(std::max(e.t / e.t_required, e.z / e.z_required), 7.75 / 1.0), 1e-12);
  // Without a noise floor only t decides; with too few pieces nothing does.
  const ClaimEvidence no_floor = weigh_claim(s, validation_blocks(s), simpler, richer, 0.0, 1, {});
  EXPECT_EQ(no_floor.z, 0.0);
  EXPECT_TRUE(no_floor.significant());
  const ClaimEvidence one_piece = weigh_claim(s, validation_blocks(s, 1), simpler, richer, 2.0, 1, {});
  ASSERT_EQ(one_piece.pieces, 2);
  FitSeries single = laid_out("fv", 25);
  const std::vector<double> zeros(single.size(), 0.0), ones(single.size(), 1.0);
  const ClaimEvidence too_few = weigh_claim(single, validation_blocks(single), zeros, ones, 2.0, 1, {});
  EXPECT_FALSE(too_few.weighable());
  EXPECT_FALSE(too_few.significant());
  EXPECT_FALSE(too_few.material());
  // Pieces cut from another series weigh nothing (and read nothing past its end).
  const ClaimEvidence other_series = weigh_claim(s, validation_blocks(single), simpler, richer, 2.0, 1, {});
  EXPECT_FALSE(other_series.weighable());
}

TEST(ClaimCriterion, AnEffectOfSixTenthsOfTheNoiseIsNamed) {
  const auto truth = [](double t) { return wave(t, 0.6); };
  const ClaimEvidence e = weighed(truth, kZero, truth);
  EXPECT_EQ(e.pieces, 96);  // 12 held out, 8 pieces each
  EXPECT_NEAR(e.reduction, 0.36, 0.04);
  EXPECT_GT(e.t, 5.0);
  EXPECT_TRUE(e.passes()) << e.describe();
}

// At the floor a systematic fall is soon significant; it must also be a quarter of the noise's
// variance (an effect of half the noise's RMS).
TEST(ClaimCriterion, AnEffectOfFourTenthsOfTheNoiseIsSignificantButNotMaterial) {
  const auto truth = [](double t) { return wave(t, 0.4); };
  const ClaimEvidence e = weighed(truth, kZero, truth);
  EXPECT_TRUE(e.significant()) << e.describe();
  EXPECT_NEAR(e.required, 0.25, 1e-12);
  EXPECT_FALSE(e.material()) << e.describe();
  EXPECT_FALSE(e.passes());
}

// A richer model that fitted noise: it predicts a ripple that is not there. Each draw risks a
// false significance of 0.5 % (the family's 5 % over 10 comparisons); none is material.
TEST(ClaimCriterion, ChanceIsNotAClaim) {
  int significant = 0, passed = 0;
  for (std::uint32_t seed = 1; seed <= 40; ++seed) {
    const ClaimEvidence e = weighed(kZero, kZero, [](double t) { return 0.01 * std::sin(9.0 * t); }, seed);
    significant += e.significant() ? 1 : 0;
    passed += e.passes() ? 1 : 0;
  }
  EXPECT_LE(significant, 1);
  EXPECT_EQ(passed, 0);
}

// A richer model that helps where the form is and hurts as much where it is not: no claim.
TEST(ClaimCriterion, ATradeOffIsNotAClaim) {
  const auto half = [](double t) { return t < 12.0 ? wave(t, 1.0) : 0.0; };
  const ClaimEvidence e = weighed(half, kZero, [](double t) { return wave(t, 1.0); });
  EXPECT_NEAR(e.reduction, 0.0, 0.1) << e.describe();
  EXPECT_FALSE(e.significant()) << e.describe();
}

// Form error of 3 N RMS over 1 N of noise (excess 9 N^2): an effect that takes 15 % of it is
// significant but not the fifth asked; one that takes 25 % passes.
TEST(ClaimCriterion, FarAboveTheFloorAnEffectMustTakeItsShareOfTheFormError) {
  const auto form = [](double t) { return wave(t, 3.0); };
  const auto taking = [&](double share) {
    const double left = std::sqrt(1.0 - share);
    return weighed(form, kZero, [&](double t) { return form(t) * (1.0 - left); });
  };
  const ClaimEvidence little = taking(0.15);
  EXPECT_NEAR(little.required, 0.2 * 9.0, 0.1);
  EXPECT_TRUE(little.significant());
  EXPECT_FALSE(little.passes()) << little.describe();
  EXPECT_TRUE(taking(0.25).passes());
}

TEST(ClaimCriterion, MoreComparisonsAskMoreOfBothStatistics) {
  const ClaimEvidence one = weighed(kZero, kZero, kZero, 11, 1);
  const ClaimEvidence twenty = weighed(kZero, kZero, kZero, 11, 20);
  EXPECT_NEAR(one.t_required, student_t_quantile(1.0 - 0.05 / 2.0, 95.0), 1e-9);
  EXPECT_NEAR(twenty.t_required, student_t_quantile(1.0 - 0.05 / 40.0, 95.0), 1e-9);
  EXPECT_NEAR(one.z_required, 1.95996, 1e-5);  // the printed 97.5 % point
  EXPECT_NEAR(twenty.z_required, normal_quantile(1.0 - 0.05 / 40.0), 1e-12);
  EXPECT_NEAR(normal_quantile(0.999), 3.09023, 1e-5);
  EXPECT_FALSE(one.passes());  // no fall at all
}

// An effect that acts at a few events: a step of the force in two short spans of the held-out
// run, 20 sigma high. Across the pieces its fall is lumpy, against the noise it is plain.
TEST(ClaimCriterion, AnEffectAtAFewEventsIsCreditedAgainstTheNoise) {
  const auto events = [](double t) { return std::fabs(t - 3.5) < 0.01 || std::fabs(t - 9.5) < 0.01 ? 20.0 : 0.0; };
  const ClaimEvidence e = weighed(events, kZero, events);
  EXPECT_LT(e.t, e.t_required) << e.describe();
  EXPECT_GT(e.z, 10.0 * e.z_required) << e.describe();
  EXPECT_TRUE(e.passes()) << e.describe();
}

}  // namespace claim_evidence_tests
