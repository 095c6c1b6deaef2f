#pragma once

#include <string>
#include <string_view>

#include "record/recorded_run.hpp"
#include "record/run_read_options.hpp"

namespace mrd::record {

// Any run file: a candump -l log when its first non-blank line starts with '(' (a
// timestamp), otherwise delimited text (parse_run_csv). Throws InputError.
RecordedRun parse_recorded_run(std::string_view text, const std::string& name,
                               const RunReadOptions& options = {});
RecordedRun read_recorded_run(const std::string& path, const RunReadOptions& options = {});

}  // namespace mrd::record
