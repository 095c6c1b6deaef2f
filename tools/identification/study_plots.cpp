#include "tools/identification/study_plots.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "tools/plot/gnuplot.hpp"
#include "tools/text_format.hpp"

namespace mrd::tools {

namespace {

std::string file_in(const std::string& directory, const StudyFigureLabels& labels, const char* suffix) {
  return (std::filesystem::path(directory) / (labels.stem + suffix)).string();
}

// An algorithm looks alike in every study's figures, whichever others ran with it.
std::string colour_of(Algorithm algorithm) {
  switch (algorithm) {
    case Algorithm::kPso: return plot::colour::kBlue;
    case Algorithm::kImprovedPso: return plot::colour::kRed;
    case Algorithm::kPagmoPso: return plot::colour::kGreen;
    case Algorithm::kPagmoDe: return plot::colour::kOrange;
    case Algorithm::kPagmoSade: return plot::colour::kPurple;
    case Algorithm::kPagmoCmaes: return plot::colour::kBrown;
  }
  return "";
}

// The key names the paper's two swarms as the paper does, the reference peers by their --algo.
std::string title_of(Algorithm algorithm) {
  if (algorithm == Algorithm::kPso) return "classical PSO";
  if (algorithm == Algorithm::kImprovedPso) return "improved PSO";
  return std::string(algorithm_name(algorithm));
}

std::string fits_phrase(std::size_t count) {
  if (count == 1) return "the fit";
  if (count == 2) return "the two fits";
  return format("the %zu fits", count);
}

// Figure 8: per algorithm, the best fitness so far (the best of every box searched) against the
// evaluations spent; columns 2i+1 and 2i+2 of the data.
plot::Figure convergence_figure(const std::vector<Algorithm>& algorithms, const StudyFigureLabels& labels,
                                const std::string& directory) {
  plot::Panel panel{.x = {"evaluations", ""},
                    .y = {"RMSE of B (Eq. 15)", "T", std::nullopt, true},
                    .data = {file_in(directory, labels, "_convergence.dat")}};
  for (std::size_t i = 0; i < algorithms.size(); ++i) {
    const int evaluations = static_cast<int>(2 * i + 1);
    panel.series.push_back({title_of(algorithms[i]), plot::column(evaluations), plot::column(evaluations + 1),
                            plot::steps(colour_of(algorithms[i]), 2.0)});
  }
  return {.output = file_in(directory, labels, "_convergence.png"),
          .title = labels.set + (labels.box.empty() ? "" : ", " + labels.box) +
                   ": best fitness against evaluations (Figure 8)",
          .height = 600,
          .panels = {std::move(panel)}};
}

// Figure 7: each algorithm's fitted B against H (column 3 + i) under the curve it fitted (column
// 2), every other fit dashed so that two which coincide still both show.
plot::Figure bh_figure(const std::vector<Algorithm>& algorithms, const StudyFigureLabels& labels,
                       const std::string& directory) {
  const char* curve = labels.generated ? "generated" : "measured";
  plot::Panel panel{.x = {"H", "A/m"}, .y = {"B", "T"}, .data = {file_in(directory, labels, "_bh.dat")}};
  for (std::size_t i = 0; i < algorithms.size(); ++i) {
    panel.series.push_back({title_of(algorithms[i]), plot::column(1), plot::column(static_cast<int>(3 + i)),
                            {plot::Shape::lines, colour_of(algorithms[i]), 2.0, 0.2, i % 2 == 1}});
  }
  panel.series.push_back(
      {curve, plot::column(1), plot::column(2), plot::points(plot::colour::kDarkGrey, 0.3), plot::Layer::measured});
  return {.output = file_in(directory, labels, "_bh.png"),
          .title = labels.set + ": " + curve + (labels.generated ? " curve and " : " loops and ") +
                   fits_phrase(algorithms.size()) + " (Figure 7)",
          .height = 600,
          .panels = {std::move(panel)}};
}

std::string write_columns(const std::string& path, const std::vector<std::string>& names,
                          const std::vector<std::vector<double>>& columns) {
  std::vector<const std::vector<double>*> pointers;
  for (const auto& column : columns) pointers.push_back(&column);
  return plot::write_columns(path, names, pointers);
}

std::string write_convergence(const std::vector<IdentifyResult>& runs, const std::string& path) {
  std::vector<std::vector<double>> columns;
  std::vector<std::string> names;
  for (const IdentifyResult& run : runs) {
    std::vector<double> evaluations, best;
    for (const auto& point : run.search.convergence) {
      evaluations.push_back(static_cast<double>(point.evaluations));
      // The box in use may be worse than one searched before it: the global best never rises.
      best.push_back(best.empty() ? point.best_fitness : std::min(best.back(), point.best_fitness));
    }
    const std::string name(algorithm_name(run.algorithm));
    names.insert(names.end(), {name + "_evaluations", name + "_best_fitness_T"});
    columns.push_back(std::move(evaluations));
    columns.push_back(std::move(best));
  }
  return write_columns(path, names, columns);
}

// H and B of the curve, each run's fitted B beside them; a NaN row after each loop lifts the pen.
std::string write_bh(const std::vector<IdentifyResult>& runs, const BHObjective& objective, const BHCurve& curve,
                     const std::string& path) {
  std::vector<std::vector<double>> columns(2 + runs.size());
  std::vector<std::string> names = {"H_A_per_m", "B_T"};
  std::vector<std::vector<double>> fitted;
  for (const IdentifyResult& run : runs) {
    fitted.push_back(objective.simulate(to_params(run.search.best)));
    names.push_back(std::string(algorithm_name(run.algorithm)) + "_B_T");
  }
  std::size_t point = 0;
  for (const auto& loop : curve.loops) {
    for (std::size_t j = 0; j < loop.H.size(); ++j, ++point) {
      columns[0].push_back(loop.H[j]);
      columns[1].push_back(loop.B[j]);
      for (std::size_t r = 0; r < runs.size(); ++r) columns[2 + r].push_back(fitted[r][point]);
    }
    for (auto& column : columns) column.push_back(NAN);
  }
  return write_columns(path, names, columns);
}

}  // namespace

std::vector<plot::Figure> study_figures(const std::vector<Algorithm>& algorithms, const StudyFigureLabels& labels,
                                        const std::string& directory) {
  return {convergence_figure(algorithms, labels, directory), bh_figure(algorithms, labels, directory)};
}

std::string plot_study_runs(const std::vector<IdentifyResult>& runs, const BHObjective& objective,
                            const BHCurve& curve, const StudyFigureLabels& labels, const std::string& directory) {
  std::error_code ec;
  std::filesystem::create_directories(directory, ec);
  if (ec) return "cannot create " + directory + ": " + ec.message();
  if (auto why = write_convergence(runs, file_in(directory, labels, "_convergence.dat")); !why.empty()) return why;
  if (auto why = write_bh(runs, objective, curve, file_in(directory, labels, "_bh.dat")); !why.empty()) return why;
  std::vector<Algorithm> algorithms;
  for (const IdentifyResult& run : runs) algorithms.push_back(run.algorithm);
  return plot::draw(study_figures(algorithms, labels, directory));
}

}  // namespace mrd::tools
