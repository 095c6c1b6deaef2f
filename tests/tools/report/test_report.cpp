// The fit report's pieces (tools/report): checksums against FIPS 180-4's examples, the fit
// percentage and autocorrelation against hand-worked values, the parameter standard deviations
// against the closed form of a straight-line least-squares fit, and the HTML writer.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>

#include "tools/report/fit_statistics.hpp"
#include "tools/report/force_fit.hpp"
#include "tools/report/html_report.hpp"
#include "tools/report/sha256.hpp"

namespace {

using namespace mrd::tools;

TEST(ReportSha256, MatchesTheStandardsExamples) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  // Two blocks: the padding spills into a second one.
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST(ReportSha256, ReadsAFileWholeAndNamesAnUnreadableOneEmpty) {
  const auto path = std::filesystem::temp_directory_path() / "mrd_report_sha256.txt";
  std::ofstream(path) << "abc";
  EXPECT_EQ(sha256_file(path.string()), sha256_hex("abc"));
  EXPECT_EQ(sha256_file((path.string() + ".missing")), "");
  // FIPS 180-2's third example, a million 'a': read in several pieces.
  std::ofstream(path) << std::string(1000000, 'a');
  EXPECT_EQ(sha256_file(path.string()), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(ReportFit, NrmseFitIsMatlabsCompareFigure) {
  // y has mean 2 and |y - mean| = sqrt(2); yhat misses by 0.1 at each of the three points.
  const std::vector<double> y = {1.0, 2.0, 3.0}, yhat = {1.1, 1.9, 3.1};
  EXPECT_NEAR(nrmse_fit_percent(y, yhat), 100.0 * (1.0 - std::sqrt(0.03) / std::sqrt(2.0)), 1e-12);
  EXPECT_DOUBLE_EQ(nrmse_fit_percent(y, y), 100.0);
  EXPECT_NEAR(nrmse_fit_percent(y, {2.0, 2.0, 2.0}), 0.0, 1e-12);  // the mean scores 0
  EXPECT_LT(nrmse_fit_percent(y, {3.0, 2.0, 1.0}), 0.0);           // worse than the mean
  // The left-out sample would cost the fit; without it the fit is perfect.
  EXPECT_DOUBLE_EQ(nrmse_fit_percent({1.0, 2.0, 3.0, 4.0}, {1.0, 2.0, 3.0, 40.0}, {true, true, true, false}), 100.0);
  EXPECT_TRUE(std::isnan(nrmse_fit_percent({1.0, 1.0}, {1.0, 1.0})));
  EXPECT_TRUE(std::isnan(nrmse_fit_percent(y, {1.0})));
}

// A residual that carries the input 3 samples late, e_i = 0.5 u_{i-3} + n_i with u and n unit
// white noise: r(3) = 0.5 / sqrt(0.25 + 1), every other lag within the noise of an estimate.
TEST(ReportFit, CrossCorrelationFindsTheInputALateResidualCarries) {
  std::mt19937 rng(5);
  std::normal_distribution<double> unit(0.0, 1.0);
  const std::size_t n = 40000;
  std::vector<double> u(n), e(n);
  for (double& x : u) x = unit(rng);
  for (std::size_t i = 0; i < n; ++i) e[i] = (i >= 3 ? 0.5 * u[i - 3] : 0.0) + unit(rng);
  const std::vector<double> r = cross_correlation(u, e, 10);
  ASSERT_EQ(r.size(), 21u);
  EXPECT_NEAR(r[10 + 3], 0.5 / std::sqrt(1.25), 0.02);
  for (std::size_t k = 0; k < r.size(); ++k)
    if (k != 13) {
      EXPECT_LT(std::abs(r[k]), 4.0 / std::sqrt(static_cast<double>(n))) << "lag " << static_cast<int>(k) - 10;
    }
  EXPECT_TRUE(cross_correlation(u, std::vector<double>(n, 1.0), 10).empty());  // a constant residual: nothing to say
  // Through the report's figures: the velocity's peak at +3 ms on a 1 kHz run.
  ForceFitTraces t;
  for (std::size_t i = 0; i < n; ++i) {
    t.time.push_back(1e-3 * static_cast<double>(i));
    t.velocity.push_back(u[i]);
    t.displacement.push_back(unit(rng));
    t.predicted.push_back(0.0);
    t.measured.push_back(e[i]);
  }
  const ForceFitFigures f = force_fit_figures(t, 10);
  ASSERT_EQ(f.inputs.size(), 2u);
  EXPECT_EQ(f.inputs[0].input, "velocity");
  EXPECT_NEAR(f.inputs[0].at_lag_s, 3e-3, 1e-9);
  EXPECT_NEAR(f.inputs[0].max_abs_r, 0.447, 0.02);
  EXPECT_LT(f.inputs[1].max_abs_r, 4.0 / std::sqrt(static_cast<double>(n)));  // the displacement is unrelated
  EXPECT_NEAR(f.inputs[0].bound, 1.96 / std::sqrt(static_cast<double>(n)), 0.2 / std::sqrt(static_cast<double>(n)));
  EXPECT_EQ(force_fit_json(f)["input_xcorr"][0]["at_lag_s"].get<double>(), f.inputs[0].at_lag_s);
}

// A published reference model at half the measured force: fit 50 %, RMS half the force's, both in
// the figures and the JSON; without one, neither key.
TEST(ReportFit, AReferenceModelGetsItsOwnFitAndRms) {
  ForceFitTraces t;
  const std::size_t n = 1000;
  for (std::size_t i = 0; i < n; ++i) {
    t.time.push_back(1e-3 * static_cast<double>(i));
    t.measured.push_back(std::sin(2.0 * M_PI * static_cast<double>(i) / 100.0));
    t.predicted.push_back(t.measured.back());
    t.reference.push_back(0.5 * t.measured.back());
  }
  t.displacement = t.velocity = t.measured;
  const ForceFitFigures f = force_fit_figures(t, 10);
  EXPECT_NEAR(f.reference_fit_percent, 50.0, 1e-9);
  EXPECT_NEAR(f.reference_rms_N, 0.5 / std::sqrt(2.0), 1e-9);
  const Json json = force_fit_json(f);
  EXPECT_EQ(json["reference_rms_N"].get<double>(), f.reference_rms_N);
  t.reference.clear();
  EXPECT_FALSE(force_fit_json(force_fit_figures(t, 10)).contains("reference_fit_percent"));
}

// A smooth input (a 0.5 Hz sine at 1 kHz) and an unrelated smooth residual (AR(1), 0.99): their
// sample cross-correlation wanders far beyond 1.96/sqrt(N), so the bound is widened by both
// autocorrelations (Bartlett) and only about the nominal share of lags falls outside it.
TEST(ReportFit, TheCrossCorrelationBoundWidensForSmoothUnrelatedSignals) {
  const std::size_t n = 20000;
  double outside_naive = 0.0, outside_bartlett = 0.0;
  for (unsigned seed = 1; seed <= 10; ++seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> unit(0.0, 1.0);
    ForceFitTraces t;
    double ar = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double time = 1e-3 * static_cast<double>(i);
      ar = 0.99 * ar + unit(rng);
      t.time.push_back(time);
      t.velocity.push_back(std::sin(2.0 * M_PI * 0.5 * time + seed));
      t.displacement.push_back(std::cos(2.0 * M_PI * 0.5 * time + seed));
      t.predicted.push_back(0.0);
      t.measured.push_back(ar);
    }
    const ForceFitFigures f = force_fit_figures(t, 50);
    outside_bartlett += f.inputs[0].outside / 10.0;
    std::size_t naive = 0;
    for (const double r : f.inputs[0].r) naive += std::abs(r) > 1.96 / std::sqrt(static_cast<double>(n)) ? 1 : 0;
    outside_naive += static_cast<double>(naive) / static_cast<double>(f.inputs[0].r.size()) / 10.0;
    EXPECT_GT(f.inputs[0].bound, 3.0 * 1.96 / std::sqrt(static_cast<double>(n)));
  }
  EXPECT_GT(outside_naive, 0.5);      // the white-noise bound calls most lags significant
  EXPECT_LT(outside_bartlett, 0.2);  // the widened one about the nominal 5 %, averaged over seeds
}

TEST(ReportFit, AutocorrelationOfAnAlternatingSequenceAlternates) {
  // +-1 alternating, mean 0: r(k) = (N - k)/N (-1)^k.
  std::vector<double> e(10);
  for (std::size_t i = 0; i < e.size(); ++i) e[i] = i % 2 ? -1.0 : 1.0;
  const auto r = autocorrelation(e, 3);
  ASSERT_EQ(r.size(), 4u);
  EXPECT_DOUBLE_EQ(r[0], 1.0);
  EXPECT_DOUBLE_EQ(r[1], -0.9);
  EXPECT_DOUBLE_EQ(r[2], 0.8);
  EXPECT_DOUBLE_EQ(r[3], -0.7);
  EXPECT_DOUBLE_EQ(autocorrelation_bound_95(400), 1.96 / 20.0);
}

TEST(ReportFit, WhiteNoiseStaysMostlyInsideTheBound) {
  std::mt19937_64 random(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> e(20000);
  for (double& x : e) x = noise(random);
  const auto r = autocorrelation(e, 100);
  const double bound = autocorrelation_bound_95(e.size());
  int outside = 0;
  for (std::size_t k = 1; k < r.size(); ++k) outside += std::abs(r[k]) > bound;
  EXPECT_LE(outside, 12);  // 5 % expected; 12 of 100 is far in the tail of the binomial
}

// y = a + b x + noise: the covariance of (a, b) in closed form is sigma^2 [[Sxx + n xbar^2, ...]] / (n Sxx),
// i.e. var(b) = s^2 / Sxx and var(a) = s^2 (1/n + xbar^2 / Sxx), s^2 = SSR / (n - 2).
TEST(ReportFit, StandardDeviationsMatchTheStraightLineClosedForm) {
  std::mt19937_64 random(11);
  std::normal_distribution<double> noise(0.0, 0.3);
  const std::size_t n = 200;
  std::vector<double> x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = 0.05 * static_cast<double>(i) + 3.0;
    y[i] = 2.0 - 0.7 * x[i] + noise(random);
  }
  double xbar = 0.0, ybar = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    xbar += x[i] / static_cast<double>(n);
    ybar += y[i] / static_cast<double>(n);
  }
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (x[i] - xbar) * (x[i] - xbar);
    sxy += (x[i] - xbar) * (y[i] - ybar);
  }
  const double b = sxy / sxx, a = ybar - b * xbar;
  double ssr = 0.0;
  for (std::size_t i = 0; i < n; ++i) ssr += std::pow(y[i] - a - b * x[i], 2);
  const double s2 = ssr / static_cast<double>(n - 2);
  const ResidualFunction line = [&](const std::vector<double>& p) {
    std::vector<double> r(n);
    for (std::size_t i = 0; i < n; ++i) r[i] = y[i] - p[0] - p[1] * x[i];
    return r;
  };
  const ParameterUncertainty u = parameter_uncertainty(line, {a, b});
  EXPECT_FALSE(u.singular);
  EXPECT_NEAR(u.sigma, std::sqrt(s2), 1e-12);
  EXPECT_NEAR(u.standard_deviation[1], std::sqrt(s2 / sxx), 1e-8 * std::sqrt(s2 / sxx));
  EXPECT_NEAR(u.standard_deviation[0], std::sqrt(s2 * (1.0 / static_cast<double>(n) + xbar * xbar / sxx)),
              1e-8 * u.standard_deviation[0]);
  // corr(a, b) = -xbar / sqrt(Sxx / n + xbar^2).
  EXPECT_NEAR(u.correlation[0][1], -xbar / std::sqrt(sxx / static_cast<double>(n) + xbar * xbar), 1e-8);
}

TEST(ReportFit, AParameterTheResidualIgnoresHasNoDeviationAndLeavesTheOthers) {
  const std::vector<double> x = {0.0, 1.0, 2.0, 3.0, 4.0}, y = {0.1, 0.9, 2.2, 2.8, 4.1};
  const auto u = parameter_uncertainty(
      [&](const std::vector<double>& p) {
        std::vector<double> r(x.size());
        for (std::size_t i = 0; i < x.size(); ++i) r[i] = y[i] - p[0] * x[i];  // p[1] unused
        return r;
      },
      {1.0, 5.0});
  EXPECT_TRUE(u.singular);
  EXPECT_TRUE(std::isnan(u.standard_deviation[1]));
  EXPECT_GT(u.standard_deviation[0], 0.0);
}

// p[0] and p[1] act only as their sum: one of them is undetermined (NaN), and the other and p[2]
// are estimated as the straight line's intercept and slope.
TEST(ReportFit, ParametersThatActOnlyTogetherLeaveTheRestDetermined) {
  const std::vector<double> x = {0.0, 1.0, 2.0, 3.0, 4.0}, y = {0.1, 0.9, 2.2, 2.8, 4.1};
  const auto u = parameter_uncertainty(
      [&](const std::vector<double>& p) {
        std::vector<double> r(x.size());
        for (std::size_t i = 0; i < x.size(); ++i) r[i] = y[i] - (p[0] + p[1]) - p[2] * x[i];
        return r;
      },
      {0.02, 0.02, 1.0});
  EXPECT_TRUE(u.singular);
  EXPECT_NE(std::isnan(u.standard_deviation[0]), std::isnan(u.standard_deviation[1]));
  const double intercept_sd = std::isnan(u.standard_deviation[0]) ? u.standard_deviation[1] : u.standard_deviation[0];
  // The line's own: sd(b) = s / sqrt(Sxx), sd(a) = s sqrt(1/n + xbar^2 / Sxx), with Sxx = 10, xbar = 2.
  EXPECT_NEAR(u.standard_deviation[2], u.sigma / std::sqrt(10.0), 1e-6 * u.sigma);
  EXPECT_NEAR(intercept_sd, u.sigma * std::sqrt(0.2 + 0.4), 1e-6 * u.sigma);
}

std::string report_slurp(const std::filesystem::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Two runs at their own rates (1 kHz and 200 Hz): each gets its own figures and lag step, and no
// common step is claimed for the two rates.
TEST(ReportFit, SeveralRunsHaveTheirOwnFiguresAndSteps) {
  mrd::tools::ForceFitTraces t;
  t.run_starts = {0, 1000};
  t.run_names = {"fast.csv", "slow.csv"};
  for (int i = 0; i < 1000; ++i) t.time.push_back(1e-3 * i);
  for (int i = 0; i < 200; ++i) t.time.push_back(1.0 + 5e-3 * i);
  for (std::size_t i = 0; i < t.time.size(); ++i) {
    const double sign = i % 2 == 0 ? 1.0 : -1.0;
    t.measured.push_back(100.0 * std::sin(7.0 * static_cast<double>(i)));
    t.predicted.push_back(t.measured.back() - (i < 1000 ? 2.0 : 5.0) * sign);
  }
  t.displacement.assign(t.time.size(), 0.0);
  t.velocity.assign(t.time.size(), 0.0);
  const mrd::tools::ForceFitFigures f = mrd::tools::force_fit_figures(t, 10);
  ASSERT_EQ(f.runs.size(), 2u);
  EXPECT_EQ(f.runs[0].name, "fast.csv");
  EXPECT_EQ(f.runs[1].samples, 200u);
  EXPECT_NEAR(f.runs[0].rms_N, 2.0, 1e-12);
  EXPECT_NEAR(f.runs[1].rms_N, 5.0, 1e-12);
  // NRMSE = RMS over the run's measured range (a 100 N sine sampled densely: about 200 N).
  EXPECT_NEAR(f.runs[0].nrmse, 2.0 / 200.0, 0.01 * 2.0 / 200.0);
  EXPECT_NEAR(f.runs[1].nrmse, 5.0 / 200.0, 0.02 * 5.0 / 200.0);
  EXPECT_NEAR(f.runs[0].lag_step_s, 1e-3, 1e-12);
  EXPECT_NEAR(f.runs[1].lag_step_s, 5e-3, 1e-12);
  EXPECT_EQ(f.lag_step_s, 0.0);
  EXPECT_DOUBLE_EQ(f.acf_outside, 1.0);  // an alternating residual in each run: every lag outside
  const auto json = mrd::tools::force_fit_json(f);
  ASSERT_EQ(json["runs"].size(), 2u);
  EXPECT_EQ(json["runs"][1]["acf_lag_step_s"].get<double>(), f.runs[1].lag_step_s);
  EXPECT_EQ(json["runs"][0]["nrmse"].get<double>(), f.runs[0].nrmse);
  EXPECT_NE(mrd::tools::per_run_text(f).find("slow.csv"), std::string::npos);
  EXPECT_NE(mrd::tools::per_run_text(f).find("NRMSE"), std::string::npos);
  t.run_starts.clear();  // one run: no per-run figures, and one step
  EXPECT_TRUE(mrd::tools::force_fit_figures(t, 10).runs.empty());
}

TEST(ReportHtml, InlinesOneImagePerPlotAndKeepsTheScripts) {
  const auto dir = std::filesystem::temp_directory_path() / "mrd_report_html";
  std::filesystem::remove_all(dir);
  HtmlReport report("a <test> & \"quotes\"", dir.string());
  report.figures("figures", {{"fit", "fit.fit_percent", 97.5, "%"}, {"not finite", "x", NAN, ""}});
  const std::vector<double> t = {0.0, 1.0, 2.0}, f = {1.0, 4.0, 9.0};
  const std::string dat = report.data("series", {"t", "f"}, {&t, &f});
  namespace plot = mrd::tools::plot;
  report.plot("one", "first", {.data = {dat}, .series = {{"f", plot::column(1), plot::column(2)}}});
  report.plot("two", "second", {.data = {dat}, .series = {{"g", plot::column(2), plot::column(1), plot::points()}}});
  report.plot("three", "third", {.data = {dat}, .series = {{"h", plot::column(2), plot::column(1), plot::points()}}},
              HtmlReport::Drawing::raster);
  ASSERT_EQ(report.write(), "");
  const std::string html = report_slurp(dir / "report.html");
  std::size_t svgs = 0;
  for (auto at = html.find("<svg"); at != std::string::npos; at = html.find("<svg", at + 1)) ++svgs;
  EXPECT_EQ(svgs, 2u);
  EXPECT_EQ(html.find("<?xml"), std::string::npos);  // inlined without the prologue
  EXPECT_NE(html.find("<img class=\"plot\" width=\"860\" height=\"440\" alt=\"third\" src=\"data:image/png;base64,iVBORw0KGgo"),
            std::string::npos);
  EXPECT_EQ(html.find("uPlot"), std::string::npos);  // no time chart, no uPlot
  EXPECT_NE(html.find("a &lt;test&gt; &amp; &quot;quotes&quot;"), std::string::npos);
  EXPECT_NE(html.find("data-key=\"fit.fit_percent\" data-value=\"97.5\""), std::string::npos);
  EXPECT_NE(html.find("data-key=\"x\" data-value=\"nan\""), std::string::npos);
  // Each script redraws its figure where it lies, its caption at the top.
  EXPECT_EQ(report_slurp(dir / "one.gp").rfind("# first\n# redraw: gnuplot one.gp (in this directory)\n", 0), 0u);
  EXPECT_NE(report_slurp(dir / "one.gp").find("set output 'one.svg'\n"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir / "two.gp"));
  EXPECT_NE(report_slurp(dir / "series.dat").find("2 9"), std::string::npos);
}

TEST(ReportHtml, ProvenanceQuotesTheCommandLineAndSumsTheInputs) {
  const auto dir = std::filesystem::temp_directory_path() / "mrd_report_provenance";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "input.csv") << "abc";
  const char* argv[] = {"mrd-replay", "a run.csv", "--seed=3"};
  const Provenance p = provenance_of("mrd-replay", 3, argv, {(dir / "input.csv").string()}, "3");
  EXPECT_EQ(p.command_line, "mrd-replay 'a run.csv' --seed=3");
  HtmlReport report("provenance", dir.string());
  report.provenance(p);
  ASSERT_EQ(report.write(), "");
  const std::string html = report_slurp(dir / "report.html");
  EXPECT_NE(html.find(sha256_hex("abc")), std::string::npos);
  EXPECT_NE(html.find("mrd-replay 'a run.csv' --seed=3"), std::string::npos) << html;
}

}  // namespace
