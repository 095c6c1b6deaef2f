#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "tools/json.hpp"

// An interactive time plot of a report: the browser draws it with uPlot (tools/report/web), drag
// to zoom, double-click for the whole run. A long run is thinned to a min/max envelope, so a peak
// is never lost however far out the view is; the report stays small for any length of run.
namespace mrd::tools {

struct TimeSeries {
  std::string label;
  const std::vector<double>* values = nullptr;  // one per time; NaN: no value (a gap in the line)
  std::string colour = "#1f77b4";
  double width = 1.0;
  bool points = false;  // markers, no line: for sparse values (samples set aside) a line would hide
};

struct TimeMarker {
  double at = 0.0;  // [s] on the chart's axis
  std::string label;
};

struct TimeChart {
  std::string name, caption;
  std::string x_label = "time [s]";
  std::string y_label;
  const std::vector<double>* time = nullptr;  // increasing
  std::vector<TimeSeries> series;
  std::vector<TimeMarker> markers;
};

// What a chart holds after thinning: each sample (samples_per_point 1), or per bucket of
// samples two points, the bucket's extremes in the order they occurred, at the bucket's first and
// last time (so the chart spans the run exactly). A series without one value per time is left
// out (as an empty one).
struct ThinnedChart {
  std::vector<double> x;
  std::vector<std::vector<double>> series;
  double samples_per_point = 1.0;
};
[[nodiscard]] ThinnedChart thin_to_envelope(const TimeChart& chart, std::size_t max_points);

// The chart's data for tools/report/web/time_chart.js: x as float32 after x0 and each series as
// uint16 steps (65535: no value), little-endian and base64. At most max_points points, and fewer
// with many series: 120,000 values in all (about 300 kB in the report whatever the run's length).
[[nodiscard]] Json time_chart_data(const TimeChart& chart, std::size_t max_points = 40000);

// Base64 (RFC 4648) of raw bytes, from libcrypto.
[[nodiscard]] std::string base64(const void* bytes, std::size_t size);

}  // namespace mrd::tools
