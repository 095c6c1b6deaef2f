// MatFile where libmatio was not found at build time (the arm64 cross build: its libmatio-dev
// pulls an HDF5 that cannot be installed beside the host's).
#include "record/csv.hpp"
#include "record/mat_file.hpp"

namespace mrd::record {

struct MatFile::Handle {};

MatFile::MatFile(const std::string& path) : path_(path) {
  throw InputError(path + ": a MATLAB .mat file, and this build of mrd reads none (built without libmatio); "
                          "export the run as CSV");
}

MatFile::~MatFile() = default;

std::vector<double> MatFile::read(const MatVariable&) const { return {}; }

}  // namespace mrd::record
