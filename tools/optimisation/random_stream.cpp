#include "tools/optimisation/random_stream.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mrd::tools {

std::size_t RandomStream::index(std::size_t n) {
  const auto i = static_cast<std::size_t>(uniform() * static_cast<double>(n));
  return std::min(i, n - 1);
}

double SeededStream::uniform() {
  return static_cast<double>(engine_() >> 11) * 0x1.0p-53;  // 53 random mantissa bits
}

double SeededStream::cauchy() {
  // Inverse CDF of Eq. 21: tan(pi (u - 1/2)); u = 0 would give -inf, so draw again.
  double u = 0.0;
  do {
    u = uniform();
  } while (u == 0.0);
  return std::tan(std::numbers::pi * (u - 0.5));
}

}  // namespace mrd::tools
