#pragma once

#include <cstdio>
#include <string>

#include "hal/status.hpp"
#include "sim/plant/rig.hpp"

namespace mrd::plant {

// The plant's run as a recorded-run CSV (tools/replay reads it; mrd-replay replays it):
// time_s,displacement_mm,current_A,force_kN,B_T,temperature_C. The displacement is the LVDT's
// reading before the LVDT faults, the current the one that flows in the coil, the force the
// load cell's. Buffered: a row is a formatted line in memory, written out in large blocks.
class RunLog {
 public:
  RunLog() = default;
  ~RunLog() { close(); }
  RunLog(const RunLog&) = delete;
  RunLog& operator=(const RunLog&) = delete;

  [[nodiscard]] hal::StartResult open(const std::string& path);
  void write(const RigSample& s);
  void close();
  [[nodiscard]] std::uint64_t rows() const { return rows_; }

  static constexpr const char* kHeader = "time_s,displacement_mm,current_A,force_kN,B_T,temperature_C\n";

 private:
  std::FILE* file_ = nullptr;
  std::uint64_t rows_ = 0;
};

}  // namespace mrd::plant
