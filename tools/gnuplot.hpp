#pragma once

#include <string>

namespace mrd::tools {

// Runs a gnuplot script (host tools only). Returns an empty string on success, otherwise
// why it failed, so callers can report it and carry on without the plot.
std::string run_gnuplot(const std::string& script);

}  // namespace mrd::tools
