#pragma once

#include <string>
#include <string_view>

#include "tools/replay/recorded_run.hpp"
#include "tools/replay/run_read_options.hpp"

namespace mrd::tools {

// Any run file: a candump -l log when its first non-blank line starts with '(' (a
// timestamp), otherwise delimited text (parse_run_csv). Throws InputError.
RecordedRun parse_recorded_run(std::string_view text, const std::string& name,
                               const RunReadOptions& options = {});
RecordedRun read_recorded_run(const std::string& path, const RunReadOptions& options = {});

}  // namespace mrd::tools
