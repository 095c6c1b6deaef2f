#include "tools/report/time_chart.hpp"

#include <openssl/evp.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace mrd::tools {

namespace {

constexpr std::uint16_t kNoValue = 65535;

// Little-endian bytes of each value, whatever the host's order.
template <typename T>
std::string little_endian_base64(const std::vector<T>& values) {
  std::vector<unsigned char> raw(values.size() * sizeof(T));
  for (std::size_t i = 0; i < values.size(); ++i) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, &values[i], sizeof(T));
    if constexpr (std::endian::native == std::endian::big) std::reverse(b, b + sizeof(T));
    std::memcpy(raw.data() + i * sizeof(T), b, sizeof(T));
  }
  return base64(raw.data(), raw.size());
}

// The finite extremes of v[from, to) in the order they occur: NaN, NaN when there is none.
std::pair<double, double> extremes_in_order(const std::vector<double>& v, std::size_t from, std::size_t to) {
  std::size_t low = to, high = to;
  for (std::size_t i = from; i < to; ++i) {
    if (!std::isfinite(v[i])) continue;
    if (low == to || v[i] < v[low]) low = i;
    if (high == to || v[i] > v[high]) high = i;
  }
  if (low == to) return {NAN, NAN};
  return low <= high ? std::pair{v[low], v[high]} : std::pair{v[high], v[low]};
}

}  // namespace

std::string base64(const void* bytes, std::size_t size) {
  std::string out(4 * ((size + 2) / 3) + 1, '\0');
  const int written = EVP_EncodeBlock(reinterpret_cast<unsigned char*>(out.data()),
                                      static_cast<const unsigned char*>(bytes), static_cast<int>(size));
  out.resize(static_cast<std::size_t>(std::max(written, 0)));
  return out;
}

ThinnedChart thin_to_envelope(const TimeChart& chart, std::size_t max_points) {
  ThinnedChart out;
  if (chart.time == nullptr) return out;
  const std::vector<double>& t = *chart.time;
  const std::size_t n = t.size();
  out.series.resize(chart.series.size());
  const auto usable = [&](const TimeSeries& s) { return s.values != nullptr && s.values->size() == n; };
  if (n <= std::max<std::size_t>(2, max_points)) {
    out.x = t;
    for (std::size_t s = 0; s < chart.series.size(); ++s)
      if (usable(chart.series[s])) out.series[s] = *chart.series[s].values;
    return out;
  }
  const std::size_t buckets = std::max<std::size_t>(1, max_points / 2);
  out.samples_per_point = static_cast<double>(n) / static_cast<double>(2 * buckets);
  out.x.reserve(2 * buckets);
  for (auto& s : out.series) s.reserve(2 * buckets);
  for (std::size_t b = 0; b < buckets; ++b) {
    const std::size_t from = b * n / buckets, to = (b + 1) * n / buckets;
    out.x.push_back(t[from]);
    out.x.push_back(t[to - 1]);
    for (std::size_t s = 0; s < chart.series.size(); ++s) {
      if (!usable(chart.series[s])) continue;
      const auto [first, second] = extremes_in_order(*chart.series[s].values, from, to);
      out.series[s].push_back(first);
      out.series[s].push_back(second);
    }
  }
  return out;
}

Json time_chart_data(const TimeChart& chart, std::size_t max_points) {
  constexpr std::size_t kValueBudget = 120000;
  const std::size_t count = std::max<std::size_t>(1, chart.series.size());
  const ThinnedChart thin = thin_to_envelope(chart, std::min(max_points, std::max<std::size_t>(2000, kValueBudget / count)));
  const double x0 = thin.x.empty() ? 0.0 : thin.x.front();
  std::vector<float> x(thin.x.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = static_cast<float>(thin.x[i] - x0);
  Json series = Json::array();
  for (std::size_t s = 0; s < chart.series.size(); ++s) {
    std::vector<double> v = thin.series[s];
    if (v.size() != thin.x.size()) v.assign(thin.x.size(), NAN);  // a series left out: no value anywhere
    double low = INFINITY, high = -INFINITY;
    for (const double y : v)
      if (std::isfinite(y)) low = std::min(low, y), high = std::max(high, y);
    if (!std::isfinite(low)) low = high = 0.0;
    const double step = high > low ? (high - low) / (kNoValue - 1) : 1.0;
    std::vector<std::uint16_t> q(v.size(), kNoValue);
    for (std::size_t i = 0; i < v.size(); ++i)
      if (std::isfinite(v[i])) q[i] = static_cast<std::uint16_t>(std::lround((v[i] - low) / step));
    series.push_back({{"label", chart.series[s].label}, {"colour", chart.series[s].colour}, {"width", chart.series[s].width},
                      {"points", chart.series[s].points},
                      {"offset", low}, {"scale", step}, {"q", little_endian_base64(q)}});
  }
  Json markers = Json::array();
  for (const TimeMarker& m : chart.markers) markers.push_back({{"at", m.at}, {"label", m.label}});
  return {{"x_label", chart.x_label}, {"y_label", chart.y_label}, {"x0", x0}, {"x", little_endian_base64(x)},
          {"samples_per_point", thin.samples_per_point}, {"series", series}, {"markers", markers}};
}

}  // namespace mrd::tools
