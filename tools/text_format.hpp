#pragma once

#include <algorithm>
#include <cstdio>
#include <string>

namespace mrd::tools {

// printf into a std::string, for the fixed-format lines of the host tools' reports.
template <typename... Args>
std::string format(const char* pattern, Args... args) {
  const int n = std::snprintf(nullptr, 0, pattern, args...);
  std::string out(static_cast<std::size_t>(std::max(n, 0)), '\0');
  std::snprintf(out.data(), out.size() + 1, pattern, args...);
  return out;
}

}  // namespace mrd::tools
