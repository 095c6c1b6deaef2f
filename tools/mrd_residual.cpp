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

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Fit the damper model to a recorded run, trace the residual to missing effects, add them"};
  mrd::cli::set_up(app, "mrd-residual");
  std::vector<std::string> run_paths;
  std::string json_path, plot_dir, config_out, report_dir;
  FitSeriesOptions series_options;
  ResidualOptions options;
  app.add_option("runs", run_paths,
                 "one run, or several analysed together (one model for all, e.g. tests at several currents): "
                 "delimited text, a MATLAB .mat file or a candump -l log, as mrd-replay reads them")
      ->required();
  RunOptionsCli run_options;
  run_options.add_to(app);
  app.add_option("--json", json_path, "write the result as JSON");
  app.add_option("--write-config", config_out,
                 "write the updated config (the fitted damper, accepted effects on); refused (exit 2) when a "
                 "fitted parameter sits on its physical range's edge, unless --accept-unphysical");
  bool accept_unphysical = false;
  app.add_flag("--accept-unphysical", accept_unphysical,
               "write --write-config even with parameters on their physical range's edge (they are listed)");
  app.add_option("--plot", plot_dir, "folder for the force-displacement, residual-time and residual-phase PNGs");
  app.add_option("--report", report_dir,
                 "write report.html here: fit, residual structure, parameters with standard deviations, "
                 "candidates, screening, provenance (docs/CLOSING-THE-LOOP.md)");
  bool spencer = false;
  app.add_flag("--reference-spencer-dyke", spencer,
               "also report Spencer 1997's modified Bouc-Wen model with its published parameters for "
               "Dyke's prototype damper (runs that logged the command voltage)");
  app.add_option("--candidates", options.candidates, "candidate effects, comma-separated (default: all)")
      ->delimiter(',')
      ->check(CLI::IsMember(candidate_names()));
  bool no_screening = false;
  app.add_flag("--no-screening", no_screening,
               "fit every sample, even those screening finds no damper produced (clipped, stuck, spikes, gaps)");
  app.add_flag("--settle-start", series_options.settle_start,
               "set aside each run's start until the coil current first reaches its extreme and the rod has "
               "travelled 5 % of its stroke: the core had a history before the record began (docs/CLOSING-THE-LOOP.md, \"Bad input\")");
  bool no_discovery = false;
  app.add_flag("--no-discovery", no_discovery,
               "do not regress what the named effects leave on the library of terms (docs/CLOSING-THE-LOOP.md)");
  app.add_flag("--robust-fit", options.robust_fit,
               "where the least-squares base leaves a fault no screening rule names, identify the base again "
               "under a robust loss, and run the candidates' fits and judgements under it (docs/CLOSING-THE-LOOP.md, \"Robust fit\")");
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
  app.add_option("--velocity-cutoff", series_options.velocity_cutoff,
                 "[Hz] zero-phase velocity filter, for runs without a velocity column (0: from the motion's spectrum)")
      ->check(mrd::cli::finite_in(0.0, 1e6))->capture_default_str();
  app.add_option("--max-fit-samples", options.max_fit_samples, "fits run on every k-th sample of the runs, at most this many")
      ->check(CLI::Range(std::size_t{1000}, std::size_t{100'000'000}))->capture_default_str();
  app.add_option("--threads", options.threads, "worker threads (0: every core)")
      ->check(CLI::Range(0u, 1024u))->capture_default_str();
  app.add_option("--seed", options.seed, "seed of the swarms")->capture_default_str();
  bool quiet = false;
  app.add_flag("--quiet,-q", quiet, "no progress line on stderr (it shows only when stderr is a terminal)");
  if (const auto status = mrd::cli::parse(app, argc, argv)) return *status;
  options.discover = !no_discovery;
  series_options.screen = !no_screening;

  const auto config = run_options.load_config();
  if (!config) return mrd::cli::kUsage;
  if (spencer && run_paths.size() != 1) {
    std::fprintf(stderr, "mrd-residual: --reference-spencer-dyke takes one run\n");
    return mrd::cli::kUsage;
  }
  // Every output is checked before the work, which may take minutes.
  if (!mrd::cli::check_outputs("mrd-residual", {&json_path, &config_out}, {&plot_dir, &report_dir})) return mrd::cli::kIo;
  options.start = config->config.law.damper;
  try {
    const mrd::record::RunReadOptions read = run_options.read_options(*config);
    series_options.amps_per_volt = run_options.amps_per_volt();
    std::vector<mrd::record::RecordedRun> runs;
    for (const auto& path : run_paths) runs.push_back(mrd::record::read_recorded_run(path, read));
    const FitSeries series = make_fit_series(runs, series_options);
    auto progress = TerminalProgress::on_stderr(quiet);
    options.progress = progress.get();
    const ResidualResult result = find_missing_effects(series, options);
    progress.reset();  // ends the status line before the summary

    std::fputs(residual_summary(runs, result).c_str(), stdout);
    ForceFitTraces traces = residual_traces(runs, series, result);
    if (spencer) {
      traces.reference = spencer_dyke_prediction(runs.front(), series);
      traces.reference_label = "Spencer 1997 (published parameters)";
      const ForceError s = force_error(series.force, traces.reference);
      const ForceError ours = force_error(series.force, result.predicted_after);
      std::printf("reference, Spencer 1997 (published parameters): RMS %.4g N, max %.4g N, NRMSE %.4g; "
                  "ours before %.4g, after %.4g\n",
                  s.rms, s.max, s.nrmse, result.before.all / ours.measured_range, ours.nrmse);
    }
    int status = 0;
    const ForceFitFigures fit = force_fit_figures(traces);
    std::fputs(per_run_text(fit).c_str(), stdout);
    if (!json_path.empty() && !mrd::record::write_text_file(json_path, residual_json(result, &fit))) {
      std::fprintf(stderr, "mrd-residual: cannot write %s\n", json_path.c_str());
      status = mrd::cli::kIo;
    }
    if (!config_out.empty() && !result.unphysical.empty() && !accept_unphysical) {
      std::fprintf(stderr, "mrd-residual: --write-config: %s not written: %zu parameter(s) outside what a damper has "
                   "(listed as 'unphysical:' above); --accept-unphysical writes it anyway\n",
                   config_out.c_str(), result.unphysical.size());
      status = mrd::cli::kBadInput;
    } else if (!config_out.empty()) {
      const std::string text = run_options.config_path().empty()
                                   ? std::string(mrd::config::default_config_text())
                                   : mrd::record::read_text_file(run_options.config_path());
      if (!mrd::record::write_text_file(config_out, updated_config(text, result))) {
        std::fprintf(stderr, "mrd-residual: cannot write %s\n", config_out.c_str());
        status = mrd::cli::kIo;
      }
    }
    if (!plot_dir.empty()) {
      const std::string name = runs.size() == 1 ? runs.front().name : std::to_string(runs.size()) + " runs";
      if (const auto why = plot_residual(series, result, name, plot_dir); !why.empty())
        std::fprintf(stderr, "mrd-residual: plot skipped: %s\n", why.c_str());
    }
    if (!report_dir.empty()) {
      std::vector<std::string> inputs = run_paths;
      if (!run_options.config_path().empty()) inputs.push_back(run_options.config_path());
      const Provenance provenance =
          provenance_of("mrd-residual", argc, argv, inputs, std::to_string(options.seed));
      if (const auto why = write_residual_report(runs, series, result, traces, provenance, report_dir); !why.empty()) {
        std::fprintf(stderr, "mrd-residual: report: %s\n", why.c_str());
        status = 3;
      }
    }
    return status;
  } catch (const mrd::record::InputError& e) {
    std::fprintf(stderr, "mrd-residual: %s\n", e.what());
    return mrd::cli::kBadInput;
  }
}
