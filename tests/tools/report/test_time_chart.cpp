// The report's time charts (tools/report/time_chart): the min/max envelope against properties a
// thinning must keep (every peak, the order of a bucket's extremes, gaps), the encoding against a
// decoder written here from RFC 4648 and IEEE 754, and the size of a long run's report.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "tools/report/force_fit.hpp"
#include "tools/report/html_report.hpp"
#include "tools/report/time_chart.hpp"

namespace {

using namespace mrd::tools;

std::vector<unsigned char> from_base64(const std::string& text) {
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<unsigned char> out;
  unsigned buffer = 0;
  int bits = 0;
  for (const char c : text) {
    if (c == '=') break;
    buffer = (buffer << 6) | static_cast<unsigned>(alphabet.find(c));
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<unsigned char>((buffer >> bits) & 0xff));
    }
  }
  return out;
}

TEST(TimeChart, Base64MatchesRfc4648sExamples) {
  const std::string in = "foobar";
  const char* want[] = {"", "Zg==", "Zm8=", "Zm9v", "Zm9vYg==", "Zm9vYmE=", "Zm9vYmFy"};
  for (std::size_t n = 0; n <= in.size(); ++n) EXPECT_EQ(base64(in.data(), n), want[n]) << n;
}

TEST(TimeChart, AShortRunKeepsEverySample) {
  const std::vector<double> t = {0.0, 0.5, 1.0}, y = {3.0, NAN, -1.0};
  const TimeChart chart{"c", "", "time [s]", "y", &t, {{"y", &y}}, {}};
  const ThinnedChart thin = thin_to_envelope(chart, 10);
  EXPECT_EQ(thin.x, t);
  ASSERT_EQ(thin.series.size(), 1u);
  EXPECT_EQ(thin.series[0][0], 3.0);
  EXPECT_TRUE(std::isnan(thin.series[0][1]));
  EXPECT_EQ(thin.samples_per_point, 1.0);
}

// 100,000 samples of a slow sine with one spike up, one down and a gap: thinned to 1,000 points,
// both spikes survive where they were, each bucket's extremes come in the order they occurred,
// and the gap stays a gap.
TEST(TimeChart, TheEnvelopeKeepsEveryPeakWhereAndInTheOrderItOccurred) {
  const std::size_t n = 100000;
  std::vector<double> t(n), y(n);
  for (std::size_t i = 0; i < n; ++i) {
    t[i] = 1e-3 * static_cast<double>(i);
    y[i] = std::sin(0.5 * t[i]);
  }
  y[31234] = 50.0;
  y[31240] = -40.0;  // the same bucket: the up spike first
  for (std::size_t i = 70000; i < 70500; ++i) y[i] = NAN;
  const TimeChart chart{"c", "", "time [s]", "y", &t, {{"y", &y}}, {}};
  const ThinnedChart thin = thin_to_envelope(chart, 1000);
  ASSERT_EQ(thin.x.size(), 1000u);
  EXPECT_DOUBLE_EQ(thin.samples_per_point, 100.0);
  const std::vector<double>& e = thin.series[0];
  std::size_t up = e.size();
  for (std::size_t i = 0; i < e.size(); ++i)
    if (e[i] == 50.0) up = i;
  ASSERT_LT(up + 1, e.size());
  EXPECT_EQ(e[up + 1], -40.0);
  EXPECT_LE(thin.x[up], t[31234]);
  EXPECT_GT(thin.x[up] + 0.2, t[31234]);  // within its 200-sample bucket
  // The buckets wholly inside the gap are gaps; one beside it still has its samples.
  std::size_t gaps = 0;
  for (std::size_t i = 0; i < e.size(); ++i)
    if (std::isnan(e[i])) {
      ++gaps;
      EXPECT_GE(thin.x[i], 69.9);
      EXPECT_LT(thin.x[i], 70.5);
    }
  EXPECT_EQ(gaps, 2u * 2u);  // 500 missing samples cover two whole buckets of 200
  for (std::size_t i = 1; i < thin.x.size(); ++i) EXPECT_LT(thin.x[i - 1], thin.x[i]);
  EXPECT_EQ(thin.x.front(), t.front());  // the chart spans the run exactly
  EXPECT_EQ(thin.x.back(), t.back());
}

// The chart's JSON decodes, with a decoder of its own, to the thinned series within half a
// quantisation step; "no value" stays no value.
TEST(TimeChart, TheDataDecodesToTheSeries) {
  std::vector<double> t, y;
  for (int i = 0; i < 500; ++i) {
    t.push_back(1000.0 + 0.01 * i);  // an offset time axis: x is stored after x0
    y.push_back(i == 7 ? NAN : 1e4 * std::cos(0.1 * i));
  }
  const TimeChart chart{"c", "", "time [s]", "y", &t, {{"y", &y, "#123456", 1.5}}, {{1002.0, "b"}}};
  const Json data = time_chart_data(chart);
  EXPECT_EQ(data["x0"].get<double>(), 1000.0);
  const std::vector<unsigned char> xb = from_base64(data["x"].get<std::string>());
  ASSERT_EQ(xb.size(), 4u * t.size());
  const Json& s = data["series"][0];
  EXPECT_EQ(s["colour"], "#123456");
  const std::vector<unsigned char> qb = from_base64(s["q"].get<std::string>());
  ASSERT_EQ(qb.size(), 2u * y.size());
  const double offset = s["offset"].get<double>(), scale = s["scale"].get<double>();
  EXPECT_NEAR(scale, 2e4 / 65534.0, 1e-2 * scale);
  for (std::size_t i = 0; i < t.size(); ++i) {
    const std::uint32_t bits = xb[4 * i] | (xb[4 * i + 1] << 8) | (xb[4 * i + 2] << 16) |
                               (static_cast<std::uint32_t>(xb[4 * i + 3]) << 24);
    float x = 0;
    std::memcpy(&x, &bits, 4);
    EXPECT_NEAR(1000.0 + x, t[i], 1e-5);
    const unsigned q = qb[2 * i] | (qb[2 * i + 1] << 8);
    if (std::isnan(y[i])) {
      EXPECT_EQ(q, 65535u);
    } else {
      EXPECT_NEAR(offset + scale * q, y[i], 0.5 * scale + 1e-9) << i;
    }
  }
  EXPECT_EQ(data["markers"][0]["at"].get<double>(), 1002.0);
}

std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A 600,000-sample run of two runs, screened, with a base model: the whole report, charts, plots
// and scripts, stays under 2 MB and holds uPlot once and its two time charts.
TEST(TimeChart, AReportOfA600000SampleRunIsUnderTwoMegabytes) {
  const std::size_t n = 600000;
  ForceFitTraces t;
  t.name = "long";
  t.run_starts = {0, n / 2};
  t.run_names = {"first", "second"};
  for (std::size_t i = 0; i < n; ++i) {
    const double time = 1e-3 * static_cast<double>(i);
    t.time.push_back(time);
    t.displacement.push_back(0.01 * std::sin(6.0 * time));
    t.velocity.push_back(0.06 * std::cos(6.0 * time));
    t.measured.push_back(4e4 * std::tanh(20.0 * t.velocity.back()) + 100.0 * std::sin(1e3 * time));
    t.predicted.push_back(4e4 * std::tanh(20.0 * t.velocity.back()));
    t.baseline.push_back(0.9 * t.predicted.back());
    t.keep.push_back(i % 50000 > 100);
  }
  t.baseline_label = "base";
  const auto dir = std::filesystem::temp_directory_path() / "mrd_report_long";
  std::filesystem::remove_all(dir);
  HtmlReport report("long", dir.string());
  add_force_fit(report, t);
  ASSERT_EQ(report.write(), "");
  const auto size = std::filesystem::file_size(dir / "report.html");
  EXPECT_LT(size, 2'000'000u);
  EXPECT_GT(size, 200'000u);  // the envelope is there, not a stub
  const std::string html = slurp(dir / "report.html");
  std::size_t charts = 0;
  for (auto at = html.find("class=\"mrd-chart\""); at != std::string::npos; at = html.find("class=\"mrd-chart\"", at + 1))
    ++charts;
  EXPECT_EQ(charts, 2u);
  EXPECT_NE(html.find("https://github.com/leeoniya/uPlot"), std::string::npos);
  EXPECT_NE(html.find("Permission is hereby granted"), std::string::npos);  // the MIT licence travels with it
  EXPECT_NE(html.find("data:image/png;base64,iVBORw0KGgo"), std::string::npos);  // the scatter plots as PNG
  EXPECT_NE(html.find("min and max of 30 samples"), std::string::npos) << "the residual: 40,000 points";
  EXPECT_NE(html.find("min and max of 40 samples"), std::string::npos) << "four series share 120,000 values";
}

}  // namespace
