#pragma once

// mrd-identify's subcommands as library functions: each takes its parsed arguments, runs, prints
// and writes its outputs, and returns the exit code (common/cli/exit_code.hpp). The main
// (mrd_identify.cpp) declares the options and calls one of them. A value checked only after
// parsing (--start, --bounds, the evaluated set) throws CLI::ValidationError naming its option;
// a bad input file throws record::InputError.
#include <cstddef>
#include <string>
#include <vector>

#include "tools/identification/identification.hpp"
#include "tools/identification/identification_study.hpp"
#include "tools/identification/bh_curve.hpp"

namespace mrd::tools {

// The input loops and how they are played through the model.
struct CurveArguments {
  std::string file;
  double turns = 0.0;
  double length = 0.0;
  double step_fraction = mrd::model::JilesAthertonSettings{}.max_field_step_fraction;
  [[nodiscard]] BHCurve read() const;
  [[nodiscard]] mrd::model::JilesAthertonSettings settings() const;
};

// Options of the studies over several seeds and algorithms.
struct StudyArguments {
  int seeds = 20;
  std::vector<std::string> algo_names;
  std::string out_dir, plot_dir;
  bool quiet = false;
  [[nodiscard]] StudyOptions study(const IdentifyOptions& options) const;
};

struct FitArguments {
  CurveArguments curve;
  IdentifyOptions options;
  std::string algo = "improved-pso", start_text, json_path, plot_dir, report_dir, config_path;
  std::vector<std::string> argv;  // the command line, for the report's provenance
  std::vector<std::string> bound_texts;
  bool polish = false;
  bool quiet = false;
  bool accept_unphysical = false;
};

struct SyntheticArguments {
  std::string path, truth_text;
  double H_max = 0.0;
  std::size_t points = 1000;
};

int run_fit(const FitArguments& args);
// The RMSE of one given set (Ms,a,alpha,k,c) on the loops.
int run_evaluate(const CurveArguments& curve, const std::string& parameter_text);
// Every algorithm over several seeds on the loops.
int run_compare(const CurveArguments& curve, const StudyArguments& args, const IdentifyOptions& options);
// Section 4.1's protocol on two known sets.
int reproduce_paper(const StudyArguments& args, const IdentifyOptions& options, double table1_H_max);
// One simulated major loop of a known set, as CSV.
int run_synthetic(const SyntheticArguments& args);

}  // namespace mrd::tools
