#include "sim/plant/run_log.hpp"

#include <cerrno>
#include <cstring>

namespace mrd::plant {

hal::StartResult RunLog::open(const std::string& path) {
  file_ = std::fopen(path.c_str(), "w");
  if (file_ == nullptr) {
    return hal::StartResult::failure("cannot write the plant log " + path + ": " + std::strerror(errno));
  }
  std::setvbuf(file_, nullptr, _IOFBF, 1 << 20);
  std::fputs(kHeader, file_);
  return hal::StartResult::success();
}

void RunLog::write(const RigSample& s) {
  if (file_ == nullptr) return;
  const auto& r = s.reading;
  std::fprintf(file_, "%.6f,%.5f,%.6g,%.6g,%.6g,%.5g\n", s.time, r.lvdt_displacement * 1e3,
               r.coil_current, r.measured_force * 1e-3, r.B, r.temperature);
  ++rows_;
}

void RunLog::close() {
  if (file_ != nullptr) std::fclose(file_);
  file_ = nullptr;
}

}  // namespace mrd::plant
