#pragma once

#include <string>
#include <vector>

#include "model/bingham_damper.hpp"
#include "model/damper_model.hpp"
#include "tools/residual/claim_evidence.hpp"
#include "tools/residual/fit_series.hpp"

namespace mrd::tools {

// A term of the library that the residual regression accepted.
struct DiscoveredTerm {
  std::string term;               // "acceleration", "line_50Hz", ... (docs/CLOSING-THE-LOOP.md)
  double coefficient = 0.0;       // SI; a mains line's amplitude [N]
  std::string unit;
  bool interference = false;      // describes the measurement (mains), not the damper
  double validation_gain = 0.0;   // fraction of the validation RMS it removed when it joined
  ClaimEvidence evidence;         // its claim when it joined (pieces 0: judged by the threshold)
};

// How a term earns its place: the claim criterion on the series' held-out pieces, against the
// terms before it, over the library's terms tried at that step (as a round's candidates).
struct TermClaim {
  const ValidationBlocks* pieces = nullptr;  // null: the relative threshold alone decides
  double noise_floor = 0.0;                  // [N]
  ClaimCriterion criterion;
};

struct TermDiscovery {
  std::vector<DiscoveredTerm> terms;  // in the order accepted
  // The mains lines' fitted sum per sample of the series [N]: subtracted from the measured
  // force before the error after, never part of the model.
  std::vector<double> interference;
  // Terms the run could not tell apart, each group led by the one chosen.
  std::vector<std::vector<std::string>> ambiguous;
  // The model's own linear terms refitted beside the accepted ones (model_fit's LinearTerms).
  double force_scale = 1.0;
  double extra_viscous = 0.0;  // [N s/m]

  [[nodiscard]] bool has_terms() const { return !terms.empty(); }
  // The refitted linear terms and the damper terms (as the model's learned_terms effect,
  // switched on) applied to `model`.
  void add_to(model::DamperModel& model) const;
};

// `model` without the library's terms it carries (its learned_terms switched off, every
// coefficient 0); the refitted force scale and viscous term stay, as base coordinates.
[[nodiscard]] model::DamperModel without_terms(model::DamperModel model);

// The coefficient `model` carries for the library term named `term` (0 where it has none).
double carried_coefficient(const model::DamperModel& model, const std::string& term);

// Step 7 of mrd-residual: forward sparse regression of the residual (force - predicted) on the
// library of physical terms, fitted on the fitting blocks and judged on the validation blocks:
// the term that lowers the validation RMS most joins while every coefficient keeps its physical
// sign and its claim passes (`claim`; without pieces, while it lowers the validation RMS by at
// least `threshold`); at most `max_terms`. `threshold` also sets which other terms would have
// done as well (the ambiguous groups). `B` is the
// model's induction per sample [T].
// `fluid` is the model's viscous law: the extra viscous column is its shape u(v) (v for Bingham,
// the Herschel-Bulkley shape otherwise), and the refitted a c0 + b must stay >= 0, since the
// model cannot carry a negative viscosity (a term that needs one is not physical).
TermDiscovery discover_terms(const FitSeries& series, const std::vector<double>& predicted,
                             const std::vector<double>& B, const model::BinghamDamper& fluid, double threshold,
                             const TermClaim& claim = {}, std::size_t max_terms = 4);

// The library's term names, damper terms first, then the mains lines the series' rate resolves.
std::vector<std::string> term_library(double sample_rate);

}  // namespace mrd::tools
