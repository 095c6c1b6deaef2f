#include "sim/plant/run_log.hpp"

#include <cerrno>
#include <cstring>

#include "common/time_origin.hpp"

namespace mrd::plant {

hal::StartResult RunLog::open(const std::string& path) {
  file_ = std::fopen(path.c_str(), "w");
  if (file_ == nullptr) {
    return hal::StartResult::failure("cannot write the plant log " + path + ": " + std::strerror(errno));
  }
  std::setvbuf(file_, nullptr, _IOFBF, 1 << 20);
  header_ = writer_.header();  // here, not on the stepping thread's first cycle: it allocates
  header_pending_ = true;
  return hal::StartResult::success();
}

void RunLog::write_header() {
  if (!header_pending_) return;
  std::fputs(header_.c_str(), file_);
  header_pending_ = false;
}

void RunLog::write(const RigSample& s) {
  if (file_ == nullptr) return;
  const auto& r = s.reading;
  write_header();
  char line[record::RunCsvWriter::kMaxRowChars];
  const std::size_t n = writer_.format_row(
      {.time = s.time, .displacement = r.lvdt_displacement, .coil = r.coil_current, .force = r.measured_force,
       .B = r.B, .temperature = r.temperature},
      line);
  std::fwrite(line, 1, n, file_);
  rows_.add();
}

void RunLog::write_time_origin(double monotonic_s) {
  if (file_ == nullptr) return;
  char line[96];
  const int n = format_time_origin(monotonic_s, line, sizeof line);
  if (n > 0) std::fwrite(line, 1, static_cast<std::size_t>(n), file_);
  write_header();
}

void RunLog::close() {
  if (file_ != nullptr) write_header();  // a run with no row still gets its column line
  if (file_ != nullptr) std::fclose(file_);
  file_ = nullptr;
}

}  // namespace mrd::plant
