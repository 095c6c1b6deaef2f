#include "record/run_read_options.hpp"

#include <cmath>
#include <cstdio>

#include "record/csv.hpp"

namespace mrd::record {

std::optional<double> current_from_file_name(std::string_view path) {
  std::string_view stem = path.substr(path.find_last_of('/') + 1);
  stem = stem.substr(0, stem.rfind('.'));
  if (stem.empty() || stem.back() != 'A') return std::nullopt;
  stem.remove_suffix(1);
  std::size_t start = stem.size();
  while (start > 0) {
    const char c = stem[start - 1];
    if (!((c >= '0' && c <= '9') || c == 'x' || c == 'p')) break;
    --start;
  }
  std::string number(stem.substr(start));
  for (char& c : number) {
    if (c == 'x' || c == 'p') c = '.';
  }
  if (number.empty() || number.front() == '.') return std::nullopt;
  return parse_finite(number);
}

std::optional<ConstantCurrent> constant_current(const RunReadOptions& options,
                                                std::string_view name) {
  char text[64];
  if (options.current_from_name) {
    const auto amps = current_from_file_name(name);
    if (!amps) {
      throw InputError(std::string(name) +
                       ": no coil current in the file name: expected it to end in <current>A, "
                       "with x for the decimal point, as in 25mm0x25Hz0x5A.txt");
    }
    std::snprintf(text, sizeof text, "file name: %.6g A", *amps);
    return ConstantCurrent{*amps, text};
  }
  if (options.current) {
    if (!std::isfinite(*options.current)) throw InputError("--current must be a finite number");
    std::snprintf(text, sizeof text, "--current %.6g A", *options.current);
    return ConstantCurrent{*options.current, text};
  }
  return std::nullopt;
}

}  // namespace mrd::record
