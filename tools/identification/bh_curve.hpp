#pragma once

#include <string>
#include <vector>

#include "model/jiles_atherton_params.hpp"
#include "record/csv.hpp"  // InputError

namespace mrd::tools {

// One measured period of a B-H loop, in file order. SI units: H [A/m], B [T].
struct BHLoop {
  std::vector<double> H;
  std::vector<double> B;
};

struct BHCurve {
  std::string source;  // file name, for messages and plots
  std::vector<BHLoop> loops;

  [[nodiscard]] std::size_t points() const;
  [[nodiscard]] double max_abs_H() const;
  [[nodiscard]] double rms_B() const;  // scale for relative errors and penalties
};

struct BHCurveOptions {
  // Needed only for B-I files (current columns): H = N I / Le, Eq. 9.
  bool has_circuit = false;
  model::MagneticCircuit circuit;
};

// Reads a CSV whose header names each column with its unit:
//   field:   H<tag>_A_per_m, H<tag>_kA_per_m, or current I<tag>_A, I<tag>_mA (B-I curves);
//   density: B<tag>_T, B<tag>_mT.
// Columns pair up in order (first field with first density, ...), one loop per pair, as in
// the Szewczyk JAmodel files. A single pair may be split into loops by a `loop` column.
// A loop shorter than the others ends with empty cells. Throws InputError.
BHCurve read_bh_curve(const std::string& path, const BHCurveOptions& options = {});

// Same, from text already in memory (`name` stands in for the file name in messages).
BHCurve parse_bh_curve(const std::string& text, const std::string& name,
                       const BHCurveOptions& options = {});

}  // namespace mrd::tools
