#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "tools/identification/identification.hpp"

namespace mrd::tools {

struct Spread {
  double median = 0.0, q25 = 0.0, q75 = 0.0, min = 0.0, max = 0.0;
};
Spread spread_of(std::vector<double> values);

// One row of a many-seed study: an algorithm (or an algorithm followed by the LM polish).
struct StudyRow {
  std::string label;
  std::array<Spread, kParameterCount> relative_error_percent{};  // recovery studies only
  Spread rmse;
  Spread evaluations;
  Spread wall_s;
};

struct StudyOptions {
  std::vector<Algorithm> algorithms{std::begin(kAllAlgorithms), std::end(kAllAlgorithms)};
  int seeds = 20;
  Budget budget;
  unsigned threads = 0;
  bool polished_row = true;  // add "improved-pso + LM"
  int polish_evaluations = 3000;
  ImprovedPsoSettings improved;
  // After each seed's run: the algorithm, runs done of all, best RMSE so far (compare and
  // reproduce-paper run for minutes).
  ProgressSink* progress = nullptr;
  std::string_view stage = "study";  // the progress line's label
  // How the loops are played through the model (compare's --step-fraction).
  model::JilesAthertonSettings settings;
  // When set, each algorithm's run of seed 1 is appended here, in the order of `algorithms`:
  // --plot draws them (tools/identification/study_plots.hpp).
  std::vector<IdentifyResult>* first_seed_runs = nullptr;
};

// Section 4.1: fit a curve generated from `truth`, searching +-100% around the truth, and
// report each parameter's relative error over the seeds (the Table 2 analogue).
std::vector<StudyRow> parameter_recovery_study(const model::JilesAthertonParams& truth,
                                               const BHCurve& curve, const StudyOptions& options);

// Measured loops: RMSE of each algorithm over the seeds, from the estimated start point.
std::vector<StudyRow> measured_fit_study(const BHCurve& curve, const StudyOptions& options);

// Local identifiability at x: the singular values of the Jacobian of B (per point, divided by
// sqrt(N)) with respect to the relative change of each parameter, d B / d ln(theta_j). A small
// singular value is a direction in parameter space that barely changes the curve; its
// singular vector names the parameters that trade off along it.
struct Sensitivity {
  Eigen::VectorXd singular_values;   // [T per unit relative change], descending
  Eigen::MatrixXd directions;        // columns: right singular vectors
};
Sensitivity parameter_sensitivity(const BHObjective& objective, const Point& x);
std::string sensitivity_markdown(const Sensitivity& s);

std::string recovery_table_markdown(const std::vector<StudyRow>& rows);
std::string fit_table_markdown(const std::vector<StudyRow>& rows, double rms_B);

}  // namespace mrd::tools
