#pragma once

#include <string>
#include <vector>

#include "tools/identification/identification.hpp"
#include "tools/plot/figure.hpp"

// --plot DIR of the studies (compare, reproduce-paper): the paper's Figures 7 and 8 with every
// algorithm of the study on one figure each, from each algorithm's run of seed 1.
namespace mrd::tools {

// What the figures say about the curve the study fitted.
struct StudyFigureLabels {
  std::string stem;        // the files: STEM_convergence.png and STEM_bh.png, each with its .dat
  std::string set;         // what was fitted: "Paper Table 1 set, 40 A/m loop"
  std::string box;         // the search box: "+-100% box"; "" leaves it out of the title
  bool generated = false;  // simulated from known parameters ("generated"), else measured loops
};

// The two figures for these algorithms (in the order of the data's columns), reading
// DIR/STEM_convergence.dat (per algorithm: evaluations, best fitness so far) and DIR/STEM_bh.dat
// (H, the curve's B, then each algorithm's fitted B).
[[nodiscard]] std::vector<plot::Figure> study_figures(const std::vector<Algorithm>& algorithms,
                                                      const StudyFigureLabels& labels, const std::string& directory);

// Writes both data files of `runs` (one run per algorithm, each fitted to `curve`; the fitted B
// simulated by `objective`) into `directory` and draws the figures. Returns "" or why not
// (gnuplot missing: the caller notes it and carries on).
[[nodiscard]] std::string plot_study_runs(const std::vector<IdentifyResult>& runs, const BHObjective& objective,
                                          const BHCurve& curve, const StudyFigureLabels& labels,
                                          const std::string& directory);

}  // namespace mrd::tools
