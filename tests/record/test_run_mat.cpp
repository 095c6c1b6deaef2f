// MATLAB .mat runs (v5, compressed v5, v7.3) read as the same run as its CSV: vectors, matrix
// columns (name:k), a scalar sample time where there is no time vector, other scalars ignored;
// and errors that name the file, the variable and the fault.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include "record/csv.hpp"
#include "record/mat_v5_check.hpp"
#include "record/run_csv.hpp"
#include "record/run_mat.hpp"
#include "record/run_reader.hpp"
#include "tests/record/input_error_of.hpp"
#include "tests/record/support/mat_writer.hpp"
#include "tests/record/support/same_run.hpp"

namespace {

using mrd::record::RecordedRun;
using mrd::record::RunReadOptions;
using mrd::record::testing::a_run;
using mrd::record::testing::as_text;
using mrd::record::testing::Columns;
using mrd::record::testing::expect_same_run;
using mrd::record::testing::input_error_of;
using mrd::record::testing::kTextColumns;
using mrd::record::testing::with_columns;
using mrd::record::testing::MatVar;
using mrd::record::testing::MatVersion;
using mrd::record::testing::scalar_var;
using mrd::record::testing::vector_var;
using mrd::record::testing::write_mat;

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("mrd_run_mat_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir / name;
}

RecordedRun written_mat(const std::string& name, MatVersion version, const std::vector<MatVar>& vars,
                        const RunReadOptions& options) {
  const std::string path = scratch(name).string();
  EXPECT_TRUE(write_mat(path, version, vars)) << path;
  return mrd::record::read_recorded_run(path, options);
}

std::string mat_error_of(const std::vector<MatVar>& vars, const RunReadOptions& options) {
  const std::string path = scratch("bad.mat").string();
  EXPECT_TRUE(write_mat(path, MatVersion::kV5, vars));
  return input_error_of([&] { (void)mrd::record::read_recorded_run(path, options); });
}

TEST(RunFormats, SameRunAsMatV5CompressedV5AndV73VectorsOrMatrixColumns) {
  const Columns c = a_run();
  const RecordedRun reference = mrd::record::parse_run_csv(as_text(c, ",", "\n"), "run.csv", kTextColumns);
  const std::vector<MatVar> vectors{vector_var("t", c.t), vector_var("x", c.x), vector_var("F", c.F),
                                    vector_var("I", c.I), scalar_var("gain", 2.5)};
  for (const MatVersion version : {MatVersion::kV5, MatVersion::kV5Compressed, MatVersion::kV73}) {
    const std::string name = "vectors" + std::to_string(static_cast<int>(version)) + ".mat";
    const RecordedRun run = written_mat(name, version, vectors, kTextColumns);
    expect_same_run(reference, run, name);
    EXPECT_EQ(run.notes, std::vector<std::string>{"variables not mapped, ignored: gain"});
  }
  // One matrix, a sample a row, its columns picked as data:k; a row vector for time.
  MatVar data{"data", c.x, c.t.size(), 3};
  data.data.insert(data.data.end(), c.F.begin(), c.F.end());
  data.data.insert(data.data.end(), c.I.begin(), c.I.end());
  MatVar row_time{"t", c.t, 1, c.t.size()};
  for (const MatVersion version : {MatVersion::kV5, MatVersion::kV73}) {
    const RecordedRun run = written_mat("matrix.mat", version, {row_time, data},
                                        with_columns("t=time_s,data:1=displacement_mm,data:2=force_N,data:3=current_A"));
    EXPECT_EQ(run.time, reference.time);
    EXPECT_EQ(run.displacement, reference.displacement);
    EXPECT_EQ(run.force, reference.force);
    EXPECT_EQ(run.coil, reference.coil);
    EXPECT_EQ(run.coil_source, "data:3");
  }
}

// Files not written by libmatio: run_v5.mat laid out byte by byte by make_fixtures.py as MATLAB's
// save does (short names packed into their tag, a double stored as uint16 data, a char array),
// run_v73.mat copied from it into HDF5; both hold the run of run.csv.
TEST(RunFormats, CommittedV5AndV73FilesReadAsTheirCsv) {
  const std::string dir = MRD_RECORD_TEST_DATA "/formats/";
  const RecordedRun reference = mrd::record::read_recorded_run(dir + "run.csv", kTextColumns);
  ASSERT_EQ(reference.size(), 300u);
  const RunReadOptions matrix = with_columns("t=time_s,data:1=displacement_mm,data:2=force_N,data:3=current_A");
  for (const char* file : {"run_v5.mat", "run_v73.mat"}) {
    const RecordedRun run = mrd::record::read_recorded_run(dir + file, matrix);
    EXPECT_EQ(run.time, reference.time) << file;
    EXPECT_EQ(run.displacement, reference.displacement) << file;
    EXPECT_EQ(run.force, reference.force) << file;
    EXPECT_EQ(run.coil, reference.coil) << file;
    EXPECT_EQ(run.notes, std::vector<std::string>{"variables not mapped, ignored: fs, rig"}) << file;
  }
  // Its sample rate, stored as uint16 data, gives the time where the time vector is left out.
  const RecordedRun by_rate =
      mrd::record::read_recorded_run(dir + "run_v5.mat", with_columns("fs=sample_rate_Hz,data:1=displacement_mm,data:3=current_A"));
  ASSERT_EQ(by_rate.size(), 300u);
  EXPECT_NEAR(by_rate.time[299], reference.time[299], 1e-12);
}

TEST(RunFormats, MatVariablesNamedTheProjectsWayNeedNoMapping) {
  const Columns c = a_run(10);
  const RecordedRun run =
      written_mat("own.mat", MatVersion::kV5,
                  {vector_var("time_s", c.t), vector_var("displacement_mm", c.x), vector_var("current_A", c.I),
                   vector_var("force_N", c.F), scalar_var("operator_id", 7.0)},
                  {});
  ASSERT_EQ(run.size(), 10u);
  EXPECT_DOUBLE_EQ(run.displacement[3], c.x[3] * 1e-3);
  EXPECT_DOUBLE_EQ(run.force[9], c.F[9]);
  EXPECT_EQ(run.coil_source, "current_A");
  EXPECT_EQ(run.notes, std::vector<std::string>{"variables not named time_s, displacement_mm, ..., ignored: operator_id"});
}

TEST(RunFormats, IntegerAndSingleClassesReadAsNumbers) {
  MatVar x = vector_var("x", {1, 2, 3, 4});
  x.kind = MatVar::Kind::kInt16;
  MatVar i = vector_var("I", {0.25, 0.5, 0.75, 1.0});
  i.kind = MatVar::Kind::kSingle;
  const RecordedRun run = written_mat("classes.mat", MatVersion::kV5,
                                      {vector_var("t", {0, 0.5, 1, 1.5}), x, i}, with_columns("t=time_s,x=displacement_cm,I=current_A"));
  EXPECT_EQ(run.displacement, (std::vector<double>{0.01, 0.02, 0.03, 0.04}));
  EXPECT_EQ(run.coil, (std::vector<double>{0.25, 0.5, 0.75, 1.0}));
}

// A run without a time vector takes its time from a scalar beside it; with a time vector the
// scalar is metadata.
TEST(RunFormats, AScalarSampleTimeOrRateGivesTheTime) {
  const std::vector<double> x{1, 2, 3, 4}, I{0, 0, 0, 0};
  const RecordedRun by_option = written_mat("ts.mat", MatVersion::kV5,
                                            {vector_var("x", x), vector_var("I", I), scalar_var("Ts", 2.0)},
                                            with_columns("Ts=sample_time_ms,x=displacement_mm,I=current_A"));
  ASSERT_EQ(by_option.size(), 4u);
  EXPECT_DOUBLE_EQ(by_option.time[3], 0.006);
  EXPECT_DOUBLE_EQ(by_option.sample_rate, 500.0);
  EXPECT_EQ(by_option.notes.front(), "time from the sample time 'Ts': 0.002 s a sample");

  const RecordedRun by_name = written_mat(
      "fs.mat", MatVersion::kV73,
      {vector_var("displacement_mm", x), vector_var("current_A", I), scalar_var("sample_rate_Hz", 250.0)}, {});
  EXPECT_DOUBLE_EQ(by_name.time[2], 0.008);

  const RecordedRun both = written_mat("both.mat", MatVersion::kV5,
                                       {vector_var("time_s", {0, 1, 2, 3}), vector_var("displacement_mm", x),
                                        vector_var("current_A", I), scalar_var("sample_rate_Hz", 250.0)},
                                       {});
  EXPECT_DOUBLE_EQ(both.time[2], 2.0);
  EXPECT_EQ(both.notes.front(), "variable 'sample_rate_Hz' ignored: the run has a time vector");
}

// NaN in a .mat file is a failed read like an empty cell: its sample is set aside, by number.
TEST(RunFormats, MatNonFiniteSamplesAreSetAsideBySample) {
  const RecordedRun run =
      written_mat("nan.mat", MatVersion::kV5,
                  {vector_var("t", {0, 1, 2, 3, 4}), vector_var("x", {1, 2, NAN, 4, 5}), vector_var("I", {0, 0, 0, 0, 0})},
                  with_columns("t=time_s,x=displacement_mm,I=current_A"));
  EXPECT_EQ(run.time, (std::vector<double>{0, 1, 3, 4}));
  ASSERT_EQ(run.set_aside_rows.size(), 1u);
  EXPECT_EQ(run.set_aside_rows[0].reason, "non_finite");
  EXPECT_EQ(run.set_aside_rows[0].line, 3u);
  EXPECT_EQ(run.set_aside_rows[0].column, "x");
  EXPECT_EQ(run.notes.back(), "rows set aside: 1 non_finite (first at sample 3)");
}

TEST(RunFormatsErrors, MatErrorsNameTheFileTheVariableAndTheFault) {
  const std::string file = scratch("bad.mat").string();
  const RunReadOptions columns = with_columns("t=time_s,data:3=displacement_mm,I=current_A");
  const MatVar t = vector_var("t", {0, 1, 2});
  const MatVar I = vector_var("I", {0, 0, 0});
  const MatVar data{"data", {1, 2, 3, 4, 5, 6}, 3, 2};
  EXPECT_EQ(mat_error_of({t, I}, columns), file + ": variable 'data': not in the file (variables: t, I)");
  EXPECT_EQ(mat_error_of({t, I, data}, columns),
            file + ": variable 'data:3': column 3 out of range: 'data' is 3x2 (data:1 to data:2)");
  EXPECT_EQ(mat_error_of({t, I, data}, with_columns("t=time_s,data=displacement_mm,I=current_A")),
            file + ": variable 'data': is a 3x2 matrix: pick a column, data:1 to data:2");
  EXPECT_EQ(mat_error_of({t, vector_var("I", {0, 0}), data}, with_columns("t=time_s,data:1=displacement_mm,I=current_A")),
            file + ": variable 'I': 2 samples, but 't' has 3");
  MatVar text{"data", {}, 0, 1, MatVar::Kind::kText, "MTS 810"};
  EXPECT_EQ(mat_error_of({t, I, text}, with_columns("t=time_s,data=displacement_mm,I=current_A")),
            file + ": variable 'data': is text, not numbers");
  MatVar complex = vector_var("data", {1, 2, 3});
  complex.kind = MatVar::Kind::kComplex;
  EXPECT_EQ(mat_error_of({t, I, complex}, with_columns("t=time_s,data=displacement_mm,I=current_A")),
            file + ": variable 'data': is complex, not numbers");
  MatVar cube{"data", std::vector<double>(12, 1.0), 3, 4, MatVar::Kind::kThreeD};
  EXPECT_EQ(mat_error_of({t, I, cube}, with_columns("t=time_s,data:1=displacement_mm,I=current_A")),
            file + ": variable 'data': has 3 dimensions; expected a vector or a matrix");
  EXPECT_EQ(mat_error_of({t, I, data}, with_columns("1=time_s,2=displacement_mm")),
            file + ": --columns by position is for text files without a header; name the .mat file's variables "
                   "(x=displacement_mm, data:2=force_N)");
  EXPECT_EQ(mat_error_of({t, I, data}, with_columns("t=time_s,Ts=sample_time_s,data:1=displacement_mm,I=current_A")),
            file + ": variable 'Ts': the run has a time vector; map one of the two");
  EXPECT_EQ(mat_error_of({I, data}, with_columns("t=sample_time_s,data:1=displacement_mm,I=current_A")),
            file + ": variable 't': not in the file (variables: I, data)");
  EXPECT_EQ(mat_error_of({t, I, data}, with_columns("t=sample_time_s,data:1=displacement_mm,I=current_A")),
            file + ": variable 't': a sample time or rate must be a scalar, not 3x1");
  EXPECT_EQ(mat_error_of({scalar_var("Ts", 0.0), I, data}, with_columns("Ts=sample_time_s,data:1=displacement_mm,I=current_A")),
            file + ": variable 'Ts': must be a finite number > 0, got 0");
  // Found by fuzz_run_mat: a denormal has no finite reciprocal, so the times would not increase.
  EXPECT_EQ(mat_error_of({scalar_var("Ts", 5e-324), I, data}, with_columns("Ts=sample_time_s,data:1=displacement_mm,I=current_A")),
            file + ": variable 'Ts': is too small to time samples by, got 4.94066e-324");
  EXPECT_EQ(mat_error_of({scalar_var("fs", 5e-324), I, data}, with_columns("fs=sample_rate_Hz,data:1=displacement_mm,I=current_A")),
            file + ": variable 'fs': is too small to time samples by, got 4.94066e-324");
  EXPECT_EQ(mat_error_of({I, data}, with_columns("data:1=displacement_mm,I=current_A")),
            file + ": no time: expected a time_s or time_ms vector, a sample_time_s or sample_rate_Hz scalar, or "
                   "--sample-rate");
}

// Found by fuzz_run_mat: a dimensions tag declaring 4 GB made libmatio allocate 8 GB before
// reading a byte of it. The structure is checked first; the same file with the tag's true size
// reads. Also a cell array that claims more cells than it holds, and a compressed variable.
TEST(RunFormatsErrors, ATagLargerThanItsFileIsRefusedBeforeLibmatioAllocatesIt) {
  const std::string path = scratch("tags.mat").string();
  ASSERT_TRUE(write_mat(path, MatVersion::kV5, {vector_var("time_s", {0, 1}), vector_var("displacement_mm", {1, 2}),
                                                vector_var("current_A", {0, 0})}));
  const std::string good = mrd::record::read_text_file(path);
  EXPECT_EQ(mrd::record::check_mat_v5_structure(good, 1 << 20), "");
  std::string bad = good;
  const std::size_t dims_tag = 128 + 8 + 16;  // after the first matrix's tag and array flags
  ASSERT_EQ(bad[dims_tag], '\x05');            // miINT32, the dimensions
  bad.replace(dims_tag + 4, 4, "\xff\xff\xff\xff");
  EXPECT_EQ(mrd::record::check_mat_v5_structure(bad, 1 << 20),
            "element at byte 128: a rank of 1073741823 (1 to 32 fit)");
  ASSERT_EQ(mrd::record::write_text_file(path, bad), "");
  EXPECT_EQ(input_error_of([&] { (void)mrd::record::read_recorded_run(path); }),
            path + ": a damaged .mat file: element at byte 128: a rank of 1073741823 (1 to 32 fit)");

  // Found by fuzz_run_mat in CI: dimensions 1 x 2^31-ish within a proper rank of 2 made libmatio
  // allocate 16 GB for a variable of two doubles.
  std::string wide = good;
  wide.replace(dims_tag + 12, 4, std::string("\x00\x00\xf8\x7f", 4));
  EXPECT_EQ(mrd::record::check_mat_v5_structure(wide, 1 << 20),
            "element at byte 128: a 2x2146959360 array in 40 bytes");
  wide[128 + 16] = '\x10';  // the class libmatio takes for a function handle
  EXPECT_EQ(mrd::record::check_mat_v5_structure(wide, 1 << 20),
            "element at byte 128: a 2x2146959360 array in 40 bytes");

  std::string cells = good;
  cells[128 + 16] = '\x01';  // the first variable's class: a cell array of 2 cells, holding none
  EXPECT_EQ(mrd::record::check_mat_v5_structure(cells, 1 << 20),
            "element at byte 128: a cell array or struct of 2 elements holds 0 matrices");

  ASSERT_TRUE(write_mat(path, MatVersion::kV5Compressed, {vector_var("time_s", {0, 1, 2, 3})}));
  const std::string compressed = mrd::record::read_text_file(path);
  EXPECT_EQ(mrd::record::check_mat_v5_structure(compressed, 1 << 20), "");
  EXPECT_EQ(mrd::record::check_mat_v5_structure(compressed, 16), "element at byte 128: inflates to more than 16 bytes");
}

TEST(RunFormatsErrors, NotAMatFileThoughItsHeaderSaysSo) {
  const std::string path = scratch("fake.mat").string();
  std::string bytes = "MATLAB 5.0 MAT-file, written by hand";
  bytes.resize(200, '\x07');
  ASSERT_EQ(mrd::record::write_text_file(path, bytes), "");
  const std::string error = input_error_of([&] { (void)mrd::record::read_recorded_run(path); });
  EXPECT_EQ(error.rfind(path + ": ", 0), 0u) << error;
  EXPECT_EQ(input_error_of([&] { (void)mrd::record::parse_recorded_run(bytes, "mem.mat"); }),
            "mem.mat: a MATLAB .mat file; read it from its file (read_recorded_run)");
}

}  // namespace
