#pragma once

#include <string>
#include <string_view>

#include "record/recorded_run.hpp"
#include "record/run_read_options.hpp"

namespace mrd::record {

// Reads a run from a MATLAB .mat file (v5 or v7.3, through libmatio): its variables are the
// columns.
//
// - A vector (1xN or Nx1) is a column by its name; column k of a matrix (one sample a row) is
//   `name:k`, k from 1.
// - Without options.columns, the variables named the project's way (time_s, displacement_mm,
//   current_A, ...) are read and the others ignored (in a note); with it, the variables and
//   matrix columns it names (by name; positions are for text files).
// - Where the run has no time vector, a scalar gives the time: one named sample_time_s,
//   sample_time_ms, sample_rate_Hz or sample_rate_kHz, or one options.columns maps to them
//   (Ts=sample_time_s), or --sample-rate. Other scalars (metadata) are ignored.
//
// Rows are then kept or set aside as in a text file (RunAssembler), numbered by sample from 1.
// A bad file throws InputError "file: variable 'name': message": a variable that is missing,
// not numeric, complex, a matrix without a column picked, a column out of range, vectors of
// different lengths.
RecordedRun read_mat_run(const std::string& path, const RunReadOptions& options = {});

// The 128-byte header of a v5 or v7.3 .mat file starts with its text ("MATLAB 5.0 MAT-file").
[[nodiscard]] bool starts_like_mat_file(std::string_view head);

}  // namespace mrd::record
