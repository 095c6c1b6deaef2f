// mrd-identify: the five J-A parameters (Ms, a, alpha, k, c) from measured B-H (or B-I)
// loops, by minimising the RMSE of B (Eq. 15). See docs/IDENTIFICATION.md. The options are
// declared here; each subcommand is a function of tools/identification/identify_commands.
#include <CLI/CLI.hpp>
#include <cstdio>

#include "common/cli/command_line.hpp"
#include "record/csv.hpp"
#include "tools/identification/identify_commands.hpp"

namespace {

using namespace mrd::tools;

// Options every search shares: the budget, the seed, the threads and the improved PSO's constants.
void add_search_options(CLI::App& cmd, IdentifyOptions& options) {
  cmd.add_option("--seed", options.seed, "random seed; a seed gives the same run")->capture_default_str();
  cmd.add_option("--population", options.budget.population, "particles in the swarm (or the population of the other algorithms)")->check(CLI::Range(5, 10000))->capture_default_str();
  cmd.add_option("--evaluations", options.budget.evaluations, "budget of model evaluations")
      ->check(CLI::Range(10, 100000000))->capture_default_str();
  cmd.add_option("--threads", options.threads, "0 = all cores (pagmo runs serially)")
      ->check(CLI::Range(0, 1024))->capture_default_str();
  auto& ips = options.improved;
  cmd.add_option("--w-max", ips.w_max, "improved-pso: inertia at the start, Eq. 16")
      ->check(mrd::cli::finite_in(0.0, 2.0))->capture_default_str();
  cmd.add_option("--w-min", ips.w_min, "improved-pso: inertia at the end, Eq. 16")
      ->check(mrd::cli::finite_in(0.0, 2.0))->capture_default_str();
  cmd.add_option("--c1", ips.c1, "improved-pso: cognitive factor, Eq. 14")
      ->check(mrd::cli::finite_in(0.0, 4.0))->capture_default_str();
  cmd.add_option("--c2", ips.c2, "improved-pso: social factor, Eq. 14")
      ->check(mrd::cli::finite_in(0.0, 4.0))->capture_default_str();
  cmd.add_option("--velocity-limit", ips.velocity_limit, "improved-pso: |v| limit, fraction of the range")
      ->check(mrd::cli::finite_in(1e-3, 1.0))->capture_default_str();
  cmd.add_option("--F", ips.F, "improved-pso: DE scaling factor, Eq. 18")
      ->check(mrd::cli::finite_in(0.0, 2.0))->capture_default_str();
  cmd.add_option("--F-spread", ips.F_spread, "improved-pso: F drawn from [F, F + spread] per trial")
      ->check(mrd::cli::finite_in(0.0, 2.0))->capture_default_str();
  cmd.add_option("--CR", ips.CR, "improved-pso: DE crossover probability, Eq. 19")
      ->check(mrd::cli::finite_in(0.0, 1.0))->capture_default_str();
  cmd.add_option("--stall", ips.stall_iterations, "improved-pso: iterations without gain before Cauchy")
      ->check(CLI::Range(1, 1000000))->capture_default_str();
  cmd.add_option("--cauchy-scale", ips.cauchy_scale, "improved-pso: Eq. 22 step scale")
      ->check(mrd::cli::finite_in(1e-9, 10.0))->capture_default_str();
  cmd.add_option("--cauchy-trials", ips.cauchy_trials, "improved-pso: Eq. 22 draws per stall")
      ->check(CLI::Range(1, 10000))->capture_default_str();
}

void add_curve_options(CLI::App& cmd, CurveArguments& curve) {
  cmd.add_option("file", curve.file, "CSV with H<n>_A_per_m,B<n>_T column pairs (or I<n>_A for B-I)")->required();
  cmd.add_option("--turns", curve.turns, "N, for B-I files [-]")->check(mrd::cli::finite_in(1.0, 1e6));
  cmd.add_option("--length", curve.length, "Le, for B-I files [m]")->check(mrd::cli::finite_in(1e-6, 10.0));
  cmd.add_option("--step-fraction", curve.step_fraction,
                 "J-A sub-step as a fraction of min(a (1 - alpha Ms/3a), k); larger is faster, less accurate")
      ->check(mrd::cli::finite_in(0.01, 4.0))->capture_default_str();
}

// figure_files: what --plot writes, for its --help.
void add_study_options(CLI::App& cmd, StudyArguments& study, const char* table_name, const char* figure_files) {
  cmd.add_flag("--quiet,-q", study.quiet, "no progress line on stderr (it shows only when stderr is a terminal)");
  cmd.add_option("--seeds", study.seeds, "seeds per algorithm")->check(CLI::Range(1, 1000))->capture_default_str();
  cmd.add_option("--algos", study.algo_names, "algorithms to run, comma-separated (default: all)")
      ->delimiter(',')
      ->check(CLI::IsMember(algorithm_names()));
  cmd.add_option("--out", study.out_dir, std::string("folder of results: the table as ") + table_name + ".md");
  cmd.add_option("--plot", study.plot_dir,
                 std::string("folder for the figures of every algorithm's seed-1 run: the convergence on one, "
                             "the fitted B-H curves on another (") + figure_files + ", PNG with their .dat)");
}

// Every subcommand's arguments, and the subcommands, which tell the one the command line chose.
struct Commands {
  FitArguments fit;
  CurveArguments evaluate_curve;
  std::string evaluate_text;
  CurveArguments compare_curve;
  IdentifyOptions compare_options;
  StudyArguments compare_study;
  IdentifyOptions paper_options;
  StudyArguments paper_study;
  double table1_H_max = 60.0;
  SyntheticArguments synthetic;
  CLI::App* fit_cmd = nullptr;
  CLI::App* evaluate_cmd = nullptr;
  CLI::App* compare_cmd = nullptr;
  CLI::App* paper_cmd = nullptr;
};

void add_fit_command(CLI::App& app, Commands& c) {
  FitArguments& fit = c.fit;
  c.fit_cmd = app.add_subcommand("fit", "fit Ms, a, alpha, k, c to the loops of a file");
  CLI::App& cmd = *c.fit_cmd;
  add_curve_options(cmd, fit.curve);
  add_search_options(cmd, fit.options);
  cmd.add_option("--algo", fit.algo, "the search")
      ->check(CLI::IsMember(algorithm_names()))
      ->capture_default_str();
  cmd.add_option("--start", fit.start_text, "start point Ms,a,alpha,k,c (default: estimated from the loops)");
  cmd.add_option("--bounds", fit.bound_texts, "name=lo:hi, repeatable (default: +-100% of the start)");
  cmd.add_flag("--polish", fit.polish, "refine with Levenberg-Marquardt after the global search");
  cmd.add_flag("--quiet,-q", fit.quiet, "no progress line on stderr (it shows only when stderr is a terminal)");
  cmd.add_option("--json", fit.json_path, "write the result as JSON");
  cmd.add_option("--plot", fit.plot_dir, "folder for the B-H overlay and convergence PNGs");
  cmd.add_option("--write-config", fit.config_path,
                 "write the identified set into [damper.jiles_atherton] of this config (patched in place, "
                 "comments kept; the default config when the file does not exist)");
  cmd.add_flag("--accept-unphysical", fit.accept_unphysical,
               "--write-config writes the set even when a parameter is flagged (on its search box's edge, "
               "outside what materials show, or not determined by the loops)");
  cmd.add_option("--report", fit.report_dir,
                 "write report.html here: B-H measured and fitted, residual, parameters with standard "
                 "deviations, provenance (docs/IDENTIFICATION.md)");
}

void add_evaluate_command(CLI::App& app, Commands& c) {
  c.evaluate_cmd = app.add_subcommand("evaluate", "print the RMSE of a given Ms,a,alpha,k,c on a file");
  add_curve_options(*c.evaluate_cmd, c.evaluate_curve);
  c.evaluate_cmd->add_option("params", c.evaluate_text, "Ms,a,alpha,k,c")->required();
}

void add_compare_command(CLI::App& app, Commands& c) {
  c.compare_cmd = app.add_subcommand("compare", "run every algorithm over several seeds on a file");
  add_curve_options(*c.compare_cmd, c.compare_curve);
  add_search_options(*c.compare_cmd, c.compare_options);
  add_study_options(*c.compare_cmd, c.compare_study, "compare", "compare_convergence.png, compare_bh.png");
}

void add_paper_command(CLI::App& app, Commands& c) {
  c.paper_cmd = app.add_subcommand("reproduce-paper", "Section 4.1 protocol on two known sets, all algorithms");
  add_search_options(*c.paper_cmd, c.paper_options);
  add_study_options(*c.paper_cmd, c.paper_study, "reproduce-paper", "table1_convergence.png, table1_bh.png, steel_*.png");
  c.paper_cmd->add_option("--table1-amplitude", c.table1_H_max,
                          "loop amplitude for the Table 1 set [A/m]; physical up to ~81")
      ->check(mrd::cli::finite_in(1.0, 1e6))->capture_default_str();
}

void add_synthetic_command(CLI::App& app, Commands& c) {
  SyntheticArguments& synthetic = c.synthetic;
  auto* cmd = app.add_subcommand("synthetic", "write one simulated major loop of a known set to a CSV");
  cmd->add_option("out", synthetic.path, "CSV to write")->required();
  cmd->add_option("--truth", synthetic.truth_text, "Ms,a,alpha,k,c")->required();
  cmd->add_option("--H-max", synthetic.H_max, "loop amplitude [A/m]")->required()
      ->check(mrd::cli::finite_in(1e-9, 1e9));
  cmd->add_option("--points", synthetic.points, "points on the loop")
      ->check(CLI::Range(8, 10000000))->capture_default_str();
}

// Every output can be written, and every folder of results exists, before the work starts.
bool check_outputs(const Commands& c) {
  return mrd::cli::check_outputs("mrd-identify", {&c.fit.json_path, &c.fit.config_path, &c.synthetic.path},
                                 {&c.fit.plot_dir, &c.fit.report_dir, &c.compare_study.out_dir,
                                  &c.compare_study.plot_dir, &c.paper_study.out_dir, &c.paper_study.plot_dir});
}

int run_command(const Commands& c) {
  if (*c.fit_cmd) return run_fit(c.fit);
  if (*c.evaluate_cmd) return run_evaluate(c.evaluate_curve, c.evaluate_text);
  if (*c.compare_cmd) return run_compare(c.compare_curve, c.compare_study, c.compare_options);
  if (*c.paper_cmd) return reproduce_paper(c.paper_study, c.paper_options, c.table1_H_max);
  return run_synthetic(c.synthetic);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Identify Jiles-Atherton parameters from measured B-H loops (Eq. 15)"};
  mrd::cli::set_up(app, "mrd-identify");
  app.require_subcommand(1);
  Commands commands;
  commands.fit.argv.assign(argv, argv + argc);
  add_fit_command(app, commands);  // the subcommands in the order --help lists them
  add_evaluate_command(app, commands);
  add_compare_command(app, commands);
  add_paper_command(app, commands);
  add_synthetic_command(app, commands);
  if (const auto status = mrd::cli::parse(app, argc, argv)) return *status;
  if (!check_outputs(commands)) return mrd::cli::kIo;
  try {
    return run_command(commands);
  } catch (const CLI::Error& e) {  // a value checked after parsing (--start, --bounds, ...)
    app.exit(e);
    return mrd::cli::kUsage;
  } catch (const mrd::record::InputError& e) {
    std::fprintf(stderr, "mrd-identify: %s\n", e.what());
    return mrd::cli::kBadInput;
  }
}
