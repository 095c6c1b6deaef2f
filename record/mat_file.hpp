#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace mrd::record {

// One variable of a .mat file, as its directory describes it (no data read yet).
struct MatVariable {
  std::string name;
  std::vector<std::size_t> dims;  // MATLAB's: rows, columns, ...
  // Empty for a real numeric array (double, single, an integer class, logical); otherwise what
  // it is, for messages: "a cell array", "a struct", "text", "complex", "a sparse matrix", ...
  std::string not_numeric;

  [[nodiscard]] std::size_t elements() const;
};

// The most elements of one variable the reader takes (512 MiB as doubles): a larger one is a
// damaged or hostile file, refused before libmatio allocates it.
inline constexpr std::size_t kMaxMatElements = std::size_t{1} << 26;

// A MATLAB .mat file (v5, compressed or not, or v7.3, which is HDF5), read through libmatio.
// Builds without libmatio have no MATLAB support: opening throws InputError saying so.
class MatFile {
 public:
  // Throws InputError "path: ..." when the file cannot be opened or is no .mat file.
  explicit MatFile(const std::string& path);
  ~MatFile();
  MatFile(const MatFile&) = delete;
  MatFile& operator=(const MatFile&) = delete;

  [[nodiscard]] const std::vector<MatVariable>& variables() const { return variables_; }
  // The variable's elements as doubles in MATLAB's order (column after column). Throws
  // InputError naming the file and the variable when it cannot be read.
  [[nodiscard]] std::vector<double> read(const MatVariable& v) const;

 private:
  struct Handle;
  std::string path_;
  std::unique_ptr<Handle> handle_;
  std::vector<MatVariable> variables_;
};

}  // namespace mrd::record
