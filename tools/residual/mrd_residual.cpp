// mrd-residual: fits the J-A + Bingham model to a recorded run, finds the residual, tries each
// candidate effect on part of the run and validates it on the rest, accepts the effects that
// pass, and writes the error before and after, an updated config and JSON.
// See docs/CLOSING-THE-LOOP.md, "mrd-residual".
// The options are declared here; the work is tools/residual/residual_command.
#include <CLI/CLI.hpp>

#include "common/cli/command_line.hpp"
#include "common/cli/exit_code.hpp"
#include "model/effects/effect_set.hpp"
#include "tools/residual/residual_command.hpp"

namespace {

using namespace mrd::tools;
using Arguments = ResidualArguments;

// The effects --candidates accepts, listed in --help.
std::vector<std::string> candidate_names() {
  std::vector<std::string> names;
  for (const mrd::model::EffectInfo& e : mrd::model::effect_infos())
    if (e.named_candidate) names.emplace_back(e.name);
  return names;
}

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
  app.add_option("--jump-recall", options.jump_recall,
                 "searches only: a repeated current jump from within this share of Ms of a kept one takes "
                 "its change of M instead of J-A's integration (0: off; 1e-6 runs a long telegraph run 3x faster)")
      ->check(mrd::cli::finite_in(0.0, 1e-3))->capture_default_str();
  app.add_flag("--terms-beside-base", options.terms_beside_base,
               "weigh the named effects together against the library's terms with the base identified again "
               "beside those terms (a force the base has no form for, a bump stop, bends a base fitted without it)");
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

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Fit the damper model to a recorded run, trace the residual to missing effects, add them"};
  mrd::cli::set_up(app, "mrd-residual");
  Arguments args;
  add_options(app, args);
  if (const auto status = mrd::cli::parse(app, argc, argv)) return *status;
  const auto config = args.run_options.load_config();
  if (!config) return mrd::cli::kUsage;
  return run_residual_command(args, *config, argc, argv);
}
