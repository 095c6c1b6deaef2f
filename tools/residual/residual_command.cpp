#include "tools/residual/residual_command.hpp"

#include <cstdio>

#include "common/cli/program_outputs.hpp"
#include "common/cli/exit_code.hpp"
#include "record/csv.hpp"
#include "record/run_reader.hpp"
#include "tools/residual/residual_report.hpp"
#include "tools/residual/residual_search.hpp"
#include "tools/residual/spencer_reference.hpp"
#include "tools/terminal_progress.hpp"

namespace mrd::tools {

namespace {

using Arguments = ResidualArguments;

// kOk, or the status to exit with. Every output is checked before the work, which may take minutes.
int check_arguments(const Arguments& a) {
  if (a.spencer && a.run_paths.size() != 1) {
    std::fprintf(stderr, "mrd-residual: --reference-spencer-dyke takes one run\n");
    return mrd::cli::kUsage;
  }
  if (!mrd::cli::check_outputs("mrd-residual", {&a.json_path, &a.config_out}, {&a.plot_dir, &a.report_dir})) {
    return mrd::cli::kIo;
  }
  return mrd::cli::kOk;
}

// The runs, the series fitted to, and what the search found in them.
struct Analysis {
  std::vector<mrd::record::RecordedRun> runs;
  FitSeries series;
  ResidualResult result;
};

// Throws InputError for a run that cannot be read.
Analysis analyse(const Arguments& a, const mrd::config::LoadedConfig& config) {
  const mrd::record::RunReadOptions read = a.run_options.read_options(config);
  FitSeriesOptions series_options = a.series_options;
  series_options.screen = !a.no_screening;
  series_options.amps_per_volt = a.run_options.amps_per_volt();
  Analysis analysis;
  for (const auto& path : a.run_paths) analysis.runs.push_back(mrd::record::read_recorded_run(path, read));
  analysis.series = make_fit_series(analysis.runs, series_options);
  ResidualOptions options = a.options;
  options.discover = !a.no_discovery;
  options.start = config.config.law.damper;
  auto progress = TerminalProgress::on_stderr(a.quiet);
  options.progress = progress.get();
  analysis.result = find_missing_effects(analysis.series, options);
  progress.reset();  // ends the status line before the summary
  return analysis;
}

// --reference-spencer-dyke: Spencer's prediction beside ours in the traces, its figures printed.
void add_spencer_reference(const Analysis& analysis, ForceFitTraces& traces) {
  traces.reference = spencer_dyke_prediction(analysis.runs.front(), analysis.series);
  traces.reference_label = "Spencer 1997 (published parameters)";
  const ForceError s = force_error(analysis.series.force, traces.reference);
  const ForceError ours = force_error(analysis.series.force, analysis.result.predicted_after);
  std::printf("reference, Spencer 1997 (published parameters): RMS %.4g N, max %.4g N, NRMSE %.4g; "
              "ours before %.4g, after %.4g\n",
              s.rms, s.max, s.nrmse, analysis.result.before.all / ours.measured_range, ours.nrmse);
}

// --write-config: the config read (or the default) with the fitted damper; refused while a
// parameter is unphysical, unless --accept-unphysical.
int write_config(const Arguments& a, const ResidualResult& result) {
  if (!result.unphysical.empty() && !a.accept_unphysical) {
    std::fprintf(stderr, "mrd-residual: --write-config: %s not written: %zu parameter(s) outside what a damper has "
                 "(listed as 'unphysical:' above); --accept-unphysical writes it anyway\n",
                 a.config_out.c_str(), result.unphysical.size());
    return mrd::cli::kBadInput;
  }
  const std::string& config_path = a.run_options.config_path();
  const std::string text = config_path.empty() ? std::string(mrd::config::default_config_text())
                                               : mrd::record::read_text_file(config_path);
  if (const std::string why = mrd::record::write_text_file(a.config_out, updated_config(text, result)); !why.empty()) {
    std::fprintf(stderr, "mrd-residual: %s\n", why.c_str());
    return mrd::cli::kIo;
  }
  return mrd::cli::kOk;
}

bool write_report(const Arguments& a, const Analysis& analysis, const ForceFitTraces& traces, int argc,
                  char** argv) {
  std::vector<std::string> inputs = a.run_paths;
  if (!a.run_options.config_path().empty()) inputs.push_back(a.run_options.config_path());
  const Provenance provenance = provenance_of("mrd-residual", argc, argv, inputs, std::to_string(a.options.seed));
  if (const auto why =
          write_residual_report(analysis.runs, analysis.series, analysis.result, traces, provenance, a.report_dir);
      !why.empty()) {
    std::fprintf(stderr, "mrd-residual: report: %s\n", why.c_str());
    return false;
  }
  return true;
}

// What the outputs are drawn from: the measured and predicted forces, and their figures.
struct Fit {
  ForceFitTraces traces;
  ForceFitFigures figures;
};

// The summary and the per-run figures on stdout.
Fit summarise(const Arguments& a, const Analysis& analysis) {
  std::fputs(residual_summary(analysis.runs, analysis.result).c_str(), stdout);
  Fit fit{residual_traces(analysis.runs, analysis.series, analysis.result), {}};
  if (a.spencer) add_spencer_reference(analysis, fit.traces);
  fit.figures = force_fit_figures(fit.traces);
  std::fputs(per_run_text(fit.figures).c_str(), stdout);
  return fit;
}

// Every output asked for, each tried whatever the others did; the status of the last that failed.
int write_outputs(const Arguments& a, const Analysis& analysis, const Fit& fit, int argc, char** argv) {
  int status = mrd::cli::kOk;
  if (!a.json_path.empty()) {
    if (const std::string why = mrd::record::write_text_file(a.json_path, residual_json(analysis.result, &fit.figures));
        !why.empty()) {
      std::fprintf(stderr, "mrd-residual: %s\n", why.c_str());
      status = mrd::cli::kIo;
    }
  }
  if (!a.config_out.empty()) {
    if (const int written = write_config(a, analysis.result); written != mrd::cli::kOk) status = written;
  }
  if (!a.plot_dir.empty()) {
    const auto& runs = analysis.runs;
    const std::string name = runs.size() == 1 ? runs.front().name : std::to_string(runs.size()) + " runs";
    if (const auto why = plot_residual(analysis.series, analysis.result, name, a.plot_dir); !why.empty())
      std::fprintf(stderr, "mrd-residual: plot skipped: %s\n", why.c_str());
  }
  if (!a.report_dir.empty() && !write_report(a, analysis, fit.traces, argc, argv)) status = mrd::cli::kIo;
  return status;
}

}  // namespace

int run_residual_command(const ResidualArguments& args, const mrd::config::LoadedConfig& config, int argc,
                         char** argv) {
  if (const int status = check_arguments(args); status != mrd::cli::kOk) return status;
  try {
    const Analysis analysis = analyse(args, config);
    const Fit fit = summarise(args, analysis);
    return write_outputs(args, analysis, fit, argc, argv);
  } catch (const mrd::record::InputError& e) {
    std::fprintf(stderr, "mrd-residual: %s\n", e.what());
    return mrd::cli::kBadInput;
  }
}

}  // namespace mrd::tools
