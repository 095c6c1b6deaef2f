// libFuzzer target: the candump -l log reader (tools/replay/candump_log). Any text; the first
// byte chooses feedback or command frames for the current, and a fallback constant current.
// The only acceptable failure is InputError; an accepted run passes check_run, has no more
// samples than LVDT frames used, and names the line of its first dropped frame.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "fuzz/run_invariants.hpp"
#include "record/csv.hpp"
#include "record/candump_log.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  mrd::record::RunReadOptions options;
  options.can.use_feedback = (data[0] & 1) != 0;
  if ((data[0] & 2) != 0) options.current = 0.25;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    const auto log = mrd::record::parse_candump(text, "fuzz.log", options);
    mrd::fuzz::check_run(log.run);
    const auto& s = log.stats;
    if (s.lvdt_frames < log.run.size()) std::abort();
    if (s.dropped() > 0 && s.first_dropped_line == 0) std::abort();
  } catch (const mrd::record::InputError&) {
  }
  return 0;
}
