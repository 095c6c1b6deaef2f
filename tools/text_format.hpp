#pragma once

#include <string>

namespace mrd::tools {

// printf into a std::string, for the fixed-format lines of the host tools' reports. A real
// variadic function so the compiler checks each pattern against its arguments (-Wformat).
[[gnu::format(printf, 1, 2)]] std::string format(const char* pattern, ...);

}  // namespace mrd::tools
