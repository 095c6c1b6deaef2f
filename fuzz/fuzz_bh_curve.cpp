// libFuzzer target: the B-H loop reader of mrd-identify (tools/identification/bh_curve). Any
// text, read as a B-H file and (first byte odd) as a B-I file with a magnetic circuit. The only
// acceptable failure is InputError; an accepted curve has loops of paired, finite H and B.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "tools/identification/bh_curve.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  mrd::tools::BHCurveOptions options;
  options.has_circuit = (data[0] & 1) != 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    const auto curve = mrd::tools::parse_bh_curve(text, "fuzz.csv", options);
    for (const auto& loop : curve.loops) {
      if (loop.H.size() != loop.B.size()) std::abort();
      for (std::size_t i = 0; i < loop.H.size(); ++i) {
        if (!std::isfinite(loop.H[i]) || !std::isfinite(loop.B[i])) std::abort();
      }
    }
    if (!std::isfinite(curve.rms_B()) || !std::isfinite(curve.max_abs_H())) std::abort();
  } catch (const mrd::record::InputError&) {
  }
  return 0;
}
