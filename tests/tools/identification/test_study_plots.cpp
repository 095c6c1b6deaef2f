// The studies' --plot (tools/identification/study_plots): every algorithm's seed-1 run on one
// convergence figure and one B-H figure, the curve drawn over the fits, and the data beside them.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "tests/support/test_files.hpp"
#include "tools/identification/identification_study.hpp"
#include "tools/identification/study_plots.hpp"
#include "tools/identification/synthetic_curve.hpp"

namespace study_plots_test {

using namespace mrd::tools;

const StudyFigureLabels kTable1{"table1", "Paper Table 1 set, 40 A/m loop", "+-100% box", true};

std::vector<std::string> titles_of(const plot::Panel& panel) {
  std::vector<std::string> titles;
  for (const auto& series : panel.series) titles.push_back(series.title);
  return titles;
}

// The lines of a file: the '#' line naming the columns first.
std::vector<std::string> lines_of(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::size_t fields_of(const std::string& line) {
  std::istringstream in(line);
  std::size_t n = 0;
  for (std::string field; in >> field;) ++n;
  return n;
}

TEST(StudyPlots, OneCurvePerAlgorithmAndTheGeneratedCurveOverTheFits) {
  const auto figures = study_figures({Algorithm::kPso, Algorithm::kImprovedPso}, kTable1, "out");
  ASSERT_EQ(figures.size(), 2u);
  const plot::Figure& convergence = figures[0];
  EXPECT_EQ(convergence.output, "out/table1_convergence.png");
  EXPECT_EQ(convergence.title,
            "Paper Table 1 set, 40 A/m loop, +-100% box: best fitness against evaluations (Figure 8)");
  ASSERT_EQ(convergence.panels.size(), 1u);
  EXPECT_TRUE(convergence.panels[0].y.log);
  EXPECT_EQ(convergence.panels[0].data.path, "out/table1_convergence.dat");
  EXPECT_EQ(titles_of(convergence.panels[0]), (std::vector<std::string>{"classical PSO", "improved PSO"}));
  EXPECT_EQ(convergence.panels[0].series[1].y.index, 4);  // the second algorithm's best fitness

  const plot::Figure& bh = figures[1];
  EXPECT_EQ(bh.output, "out/table1_bh.png");
  EXPECT_EQ(bh.title, "Paper Table 1 set, 40 A/m loop: generated curve and the two fits (Figure 7)");
  ASSERT_EQ(bh.panels.size(), 1u);
  EXPECT_EQ(titles_of(bh.panels[0]), (std::vector<std::string>{"classical PSO", "improved PSO", "generated"}));
  EXPECT_EQ(bh.panels[0].series[2].layer, plot::Layer::measured);  // drawn on top
  EXPECT_NE(bh.panels[0].series[0].style.colour, bh.panels[0].series[1].style.colour);
}

TEST(StudyPlots, MeasuredLoopsWithoutABoxAreNamedSo) {
  const auto figures = study_figures({Algorithm::kImprovedPso}, {"compare", "loops.csv", "", false}, "out");
  EXPECT_EQ(figures[0].title, "loops.csv: best fitness against evaluations (Figure 8)");
  EXPECT_EQ(figures[1].title, "loops.csv: measured loops and the fit (Figure 7)");
  EXPECT_EQ(figures[1].panels[0].series.back().title, "measured");
}

// A short study keeps each algorithm's seed-1 run; its figures' data has a column per algorithm
// and gnuplot draws them.
TEST(StudyPlots, WritesTheDataOfEachAlgorithmsFirstSeedAndDrawsIt) {
  const mrd::model::JilesAthertonParams steel{1.6e6, 1100.0, 1.6e-3, 400.0, 0.2};
  const BHCurve curve = synthetic_loop(steel, 5000.0, 100);
  std::vector<IdentifyResult> runs;
  StudyOptions study;
  study.algorithms = {Algorithm::kPso, Algorithm::kImprovedPso};
  study.seeds = 2;
  study.budget = {.population = 10, .evaluations = 200};
  study.threads = 1;
  study.first_seed_runs = &runs;
  (void)parameter_recovery_study(steel, curve, study);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].algorithm, Algorithm::kPso);
  EXPECT_EQ(runs[1].algorithm, Algorithm::kImprovedPso);

  const mrd::test::TestDirectory dir("mrd_study_plots");
  const std::string why = plot_study_runs(runs, BHObjective(curve), curve, kTable1, dir.path().string());
  const auto convergence = lines_of(dir / "table1_convergence.dat");
  ASSERT_GT(convergence.size(), 2u);
  EXPECT_EQ(convergence[0], "# pso_evaluations pso_best_fitness_T improved-pso_evaluations improved-pso_best_fitness_T");
  EXPECT_EQ(fields_of(convergence[1]), 4u);
  const auto bh = lines_of(dir / "table1_bh.dat");
  EXPECT_EQ(bh[0], "# H_A_per_m B_T pso_B_T improved-pso_B_T");
  ASSERT_EQ(bh.size(), 1u + 100u + 1u);  // the column line, the loop, the row that lifts the pen
  EXPECT_EQ(fields_of(bh[1]), 4u);
  EXPECT_EQ(bh.back(), "NaN NaN NaN NaN");
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) GTEST_SKIP() << "gnuplot is not installed";
  ASSERT_EQ(why, "");
  EXPECT_GT(std::filesystem::file_size(dir / "table1_convergence.png"), 1000u);
  EXPECT_GT(std::filesystem::file_size(dir / "table1_bh.png"), 1000u);
}

}  // namespace study_plots_test
