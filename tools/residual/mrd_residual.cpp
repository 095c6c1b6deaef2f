// mrd-residual: fits the J-A + Bingham model to a recorded run, finds the residual, tries each
// candidate effect on part of the run and validates it on the rest, accepts the effects that
// pass, and writes the error before and after, an updated config and JSON.
// See docs/CLOSING-THE-LOOP.md, "mrd-residual".
#include <CLI/CLI.hpp>
#include <cstdio>

#include "common/cli/command_line.hpp"
#include "config/config_loader.hpp"
#include "record/csv.hpp"
#include "tools/replay/run_options_cli.hpp"
#include "record/run_reader.hpp"
#include "tools/residual/residual_report.hpp"
#include "tools/residual/residual_search.hpp"
#include "tools/residual/spencer_reference.hpp"
#include "tools/terminal_progress.hpp"

namespace {

using namespace mrd::tools;

// The effects --candidates accepts, listed in --help.
std::vector<std::string> candidate_names() {
  std::vector<std::string> names;
  for (const mrd::model::EffectInfo& e : mrd::model::effect_infos())
    if (e.named_candidate) names.emplace_back(e.name);
  return names;
}

// The command line, as parsed; analyse() completes the options with the config and the --no- flags.
struct Arguments {
  std::vector<std::string> run_paths;
  std::string json_path, plot_dir, config_out, report_dir;
  FitSeriesOptions series_options;
  ResidualOptions options;
  RunOptionsCli run_options;
  bool accept_unphysical = false;
  bool spencer = false;
  bool no_screening = false;
  bool no_discovery = false;
  bool quiet = false;
};

void add_output_options(CLI::App& app, Arguments& a) {
  app.add_option("--json", a.json_path, "write the result as JSON");
  app.add_option("--write-config", a.config_out,
                 "write the updated config (the fitted damper, accepted effects on); refused (exit 2) when a "
                 "fitted parameter sits on its physical range's edge, unless --accept-unphysical");
  app.add_flag("--accept-unphysical", a.accept_unphysical,
               "write --write-config even with parameters on their physical range's edge (they are listed)");
  app.add_option("--plot", a.plot_dir, "folder for the force-displacement, residual-time and residual-phase PNGs");
  app.add_option("--report", a.report_dir,
                 "write report.html here: fit, residual structure, parameters with standard deviations, "
                 "candidates, screening, provenance (docs/CLOSING-THE-LOOP.md)");
  app.add_flag("--reference-spencer-dyke", a.spencer,
               "also report Spencer 1997's modified Bouc-Wen model with its published parameters for "
               "Dyke's prototype damper (runs that logged the command voltage)");
}

// What the search fits: the candidates, the samples, the library of terms, the loss.
void add_fit_options(CLI::App& app, Arguments& a) {
  app.add_option("--candidates", a.options.candidates, "candidate effects, comma-separated (default: all)")
      ->delimiter(',')
      ->check(CLI::IsMember(candidate_names()));
  app.add_flag("--no-screening", a.no_screening,
               "fit every sample, even those screening finds no damper produced (clipped, stuck, spikes, gaps)");
  app.add_flag("--settle-start", a.series_options.settle_start,
               "set aside each run's start until the coil current first reaches its extreme and the rod has "
               "travelled 5 % of its stroke: the core had a history before the record began (docs/CLOSING-THE-LOOP.md, \"Bad input\")");
  app.add_flag("--no-discovery", a.no_discovery,
               "do not regress what the named effects leave on the library of terms (docs/CLOSING-THE-LOOP.md)");
  app.add_flag("--robust-fit", a.options.robust_fit,
               "where the least-squares base leaves a fault no screening rule names, identify the base again "
               "under a robust loss, and run the candidates' fits and judgements under it (docs/CLOSING-THE-LOOP.md, \"Robust fit\")");
}

// How an effect is judged, and how the search runs.
void add_search_options(CLI::App& app, Arguments& a) {
  ResidualOptions& options = a.options;
  app.add_option("--threshold", options.minimum_reduction,
                 "margin (a fraction of the validation RMS) by which one explanation must beat another to tell them "
                 "apart: ambiguity, the library's terms against an effect, the discovery's terms")
      ->check(mrd::cli::finite_in(0.0, 0.9))->capture_default_str();
  app.add_option("--claim-confidence", options.claim.confidence,
                 "family-wise confidence that an accepted effect's fall of the held-out error is no chance "
                 "(paired blocks, over a round's candidates)")
      ->check(mrd::cli::finite_in(0.5, 0.999999))->capture_default_str();
  app.add_option("--claim-share", options.claim.excess_share,
                 "share of the held-out mean square above the noise floor an effect must remove to be accepted")
      ->check(mrd::cli::finite_in(0.0, 1.0))->capture_default_str();
  app.add_option("--claim-noise-share", options.claim.noise_share,
                 "least fall of the held-out mean square an effect must show, as a share of the noise floor's variance")
      ->check(mrd::cli::finite_in(0.0, 100.0))->capture_default_str();
  app.add_option("--velocity-cutoff", a.series_options.velocity_cutoff,
                 "[Hz] zero-phase velocity filter, for runs without a velocity column (0: from the motion's spectrum)")
      ->check(mrd::cli::finite_in(0.0, 1e6))->capture_default_str();
  app.add_option("--max-fit-samples", options.max_fit_samples, "fits run on every k-th sample of the runs, at most this many")
      ->check(CLI::Range(std::size_t{1000}, std::size_t{100'000'000}))->capture_default_str();
  app.add_option("--threads", options.threads, "worker threads (0: every core)")
      ->check(CLI::Range(0u, 1024u))->capture_default_str();
  app.add_option("--seed", options.seed, "seed of the swarms")->capture_default_str();
  app.add_flag("--quiet,-q", a.quiet, "no progress line on stderr (it shows only when stderr is a terminal)");
}

void add_options(CLI::App& app, Arguments& a) {
  app.add_option("runs", a.run_paths,
                 "one run, or several analysed together (one model for all, e.g. tests at several currents): "
                 "delimited text, a MATLAB .mat file or a candump -l log, as mrd-replay reads them")
      ->required();
  a.run_options.add_to(app);
  add_output_options(app, a);  // in the order --help lists them
  add_fit_options(app, a);
  add_search_options(app, a);
}

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

int main(int argc, char** argv) {
  CLI::App app{"Fit the damper model to a recorded run, trace the residual to missing effects, add them"};
  mrd::cli::set_up(app, "mrd-residual");
  Arguments args;
  add_options(app, args);
  if (const auto status = mrd::cli::parse(app, argc, argv)) return *status;

  const auto config = args.run_options.load_config();
  if (!config) return mrd::cli::kUsage;
  if (const int status = check_arguments(args); status != mrd::cli::kOk) return status;
  try {
    const Analysis analysis = analyse(args, *config);
    const Fit fit = summarise(args, analysis);
    return write_outputs(args, analysis, fit, argc, argv);
  } catch (const mrd::record::InputError& e) {
    std::fprintf(stderr, "mrd-residual: %s\n", e.what());
    return mrd::cli::kBadInput;
  }
}
