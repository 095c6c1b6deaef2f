#include "tools/signal/signal_scale.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace mrd::tools {

namespace {

double median_in_place(std::vector<double>& v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace

double mad_sigma(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const double centre = median_in_place(values);
  for (double& x : values) x = std::fabs(x - centre);
  return 1.4826 * median_in_place(values);
}

double largest_magnitude(std::span<const double> values) {
  double largest = 0.0;
  for (const double x : values) largest = std::max(largest, std::fabs(x));
  return largest;
}

bool varies(std::span<const double> values, double share) {
  if (values.empty()) return false;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  const double largest = std::max(std::fabs(*lo), std::fabs(*hi));
  return largest > 0.0 && *hi - *lo > share * largest;
}

}  // namespace mrd::tools
