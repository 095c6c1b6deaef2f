#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace mrd::record::testing {

// One variable to write: numbers (rows x columns, column after column, as MATLAB stores them) in
// a numeric class, or text.
struct MatVar {
  enum class Kind { kDouble, kSingle, kInt16, kComplex, kText, kThreeD };
  std::string name;
  std::vector<double> data;
  std::size_t rows = 0;
  std::size_t columns = 1;
  Kind kind = Kind::kDouble;
  std::string text;  // kText
};

// A column vector (N x 1) of doubles, and a 1 x 1 scalar.
MatVar vector_var(std::string name, std::vector<double> data);
MatVar scalar_var(std::string name, double value);

enum class MatVersion { kV5, kV5Compressed, kV73 };

// Writes the variables with libmatio's own writer; false when it cannot.
bool write_mat(const std::string& path, MatVersion version, const std::vector<MatVar>& vars);

}  // namespace mrd::record::testing
