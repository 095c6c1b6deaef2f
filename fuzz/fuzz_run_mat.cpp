// libFuzzer target: the MATLAB .mat run reader (record/run_mat, through libmatio) as the tools
// reach it (read_recorded_run). The first byte chooses the column mapping: the project's own
// variable names, vectors and matrix columns by name, a sample-rate scalar for the time, or a
// constant current; the rest is the file, handed over through an in-memory file (memfd), since
// libmatio and HDF5 read only from a path. The only acceptable failure is InputError; a run it
// accepts must pass check_run. libmatio and HDF5 are not instrumented: their own bugs show as
// crashes only.
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz/run_invariants.hpp"
#include "record/csv.hpp"
#include "record/run_columns.hpp"
#include "record/run_reader.hpp"

namespace {

mrd::record::RunReadOptions options_for(std::uint8_t selector) {
  mrd::record::RunReadOptions options;
  switch (selector % 4) {
    case 1:
      options.columns = mrd::record::parse_column_mapping("t=time_s,data:1=displacement_mm,data:2=force_N,I=current_A");
      break;
    case 2: options.columns = mrd::record::parse_column_mapping("fs=sample_rate_Hz,x=displacement_mm,I=current_A"); break;
    case 3:
      options.columns = mrd::record::parse_column_mapping("t=time_s,data:1=displacement_mm");
      options.current = 0.5;
      break;
    default: break;
  }
  return options;
}

// One in-memory file for the whole run, rewritten for each input.
struct MemoryFile {
  int fd = memfd_create("fuzz_run_mat", 0);
  std::string path = "/proc/self/fd/" + std::to_string(fd);
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const auto options = options_for(data[0]);
  static const MemoryFile file;
  if (file.fd < 0 || ftruncate(file.fd, 0) != 0 ||
      pwrite(file.fd, data + 1, size - 1, 0) != static_cast<ssize_t>(size - 1))
    std::abort();
  try {
    mrd::fuzz::check_run(mrd::record::read_recorded_run(file.path, options));
  } catch (const mrd::record::InputError&) {
  }
  return 0;
}
