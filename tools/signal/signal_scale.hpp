#pragma once

#include <span>
#include <vector>

// Scales of a sampled signal that the host tools' screening and fits share.
namespace mrd::tools {

// 1.4826 times the median absolute deviation from the median: the sigma of the values' Gaussian
// part, which a minority of outliers does not move.
[[nodiscard]] double mad_sigma(std::vector<double> values);

// The largest |value|, 0 for none.
[[nodiscard]] double largest_magnitude(std::span<const double> values);

// Whether the values' range exceeds `share` of their largest magnitude: a current that does
// (the field moves, so J-A and the yield law can be identified) rather than a constant one
// with its ripple.
[[nodiscard]] bool varies(std::span<const double> values, double share = 0.05);

}  // namespace mrd::tools
