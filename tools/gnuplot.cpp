#include "tools/gnuplot.hpp"

#include <cstdio>

namespace mrd::tools {

std::string run_gnuplot(const std::string& script) {
  FILE* pipe = popen("gnuplot 2>&1 >/dev/null", "w");
  if (pipe == nullptr) return "cannot start gnuplot";
  const bool written = std::fwrite(script.data(), 1, script.size(), pipe) == script.size();
  const int status = pclose(pipe);
  if (!written || status != 0) return "gnuplot failed (is gnuplot installed? apt-get install gnuplot-nox)";
  return {};
}

}  // namespace mrd::tools
