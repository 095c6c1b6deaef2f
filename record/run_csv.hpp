#pragma once

#include <string>
#include <string_view>

#include "record/recorded_run.hpp"
#include "record/run_read_options.hpp"

namespace mrd::record {

// Reads a run from delimited text, split on the delimiter its first line uses (find_delimiter:
// semicolon, comma, tab, else blanks); in a semicolon file a number may have a decimal comma.
// CRLF line ends and a UTF-8 byte-order mark are accepted.
//
// - The project's own format: a header naming every column with its unit (time_s,
//   displacement_mm, current_A or voltage_V, force_N or force_kN, velocity_mm_s, B_T, temperature_C, ...;
//   known_unit_names() lists them), in any order. A column it does not know is an error.
// - A foreign file through options.columns: by header name (quoted names and a trailing
//   comma are fine; unmapped columns are ignored and listed in the run's notes), or by
//   position for files without a header.
//
// Every row has as many fields as the header (or the first row). Each used cell must be a
// number; an empty, nan or inf cell, a repeated row and a time that does not increase set their
// row aside (RunAssembler). Blank lines are skipped. A bad file throws InputError
// "file:line: column 'name': message", the first problem found.
RecordedRun parse_run_csv(std::string_view text, const std::string& name,
                          const RunReadOptions& options = {});

}  // namespace mrd::record
