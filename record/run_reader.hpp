#pragma once

#include <string>
#include <string_view>

#include "record/recorded_run.hpp"
#include "record/run_read_options.hpp"

namespace mrd::record {

// Any run file, told by its content: a MATLAB .mat file (v5 or v7.3: read_mat_run) by its header,
// a candump -l log when its first non-blank line starts with '(' (a timestamp), otherwise
// delimited text (parse_run_csv: comma, semicolon, tab or blanks, found from the header).
// Throws InputError.
RecordedRun read_recorded_run(const std::string& path, const RunReadOptions& options = {});
// The same for text in memory; a .mat file must be read from its file.
RecordedRun parse_recorded_run(std::string_view text, const std::string& name,
                               const RunReadOptions& options = {});

}  // namespace mrd::record
