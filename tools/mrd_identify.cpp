// mrd-identify: the five J-A parameters (Ms, a, alpha, k, c) from measured B-H (or B-I)
// loops, by minimising the RMSE of B (Eq. 15). See docs/IDENTIFICATION.md.
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/cli/command_line.hpp"
#include "config/config_loader.hpp"
#include "record/csv.hpp"
#include "tools/toml_patch.hpp"
#include "tools/identification/identification_study.hpp"
#include "tools/identification/identify_report.hpp"
#include "tools/identification/start_point.hpp"
#include "tools/identification/study_plots.hpp"
#include "tools/identification/synthetic_curve.hpp"
#include "tools/terminal_progress.hpp"
#include "tools/text_format.hpp"

namespace {

using namespace mrd::tools;

// "Ms,a,alpha,k,c" -> Point; throws CLI::ValidationError naming the option.
Point parse_parameter_list(const std::string& option, const std::string& text) {
  const auto fields = mrd::record::split_csv_line(text);
  if (fields.size() != kParameterCount) {
    throw CLI::ValidationError(option, "expected 5 numbers Ms,a,alpha,k,c, got '" + text + "'");
  }
  Point x(kParameterCount);
  for (int j = 0; j < kParameterCount; ++j) {
    const auto value = mrd::record::parse_finite(fields[static_cast<std::size_t>(j)]);
    if (!value) {
      throw CLI::ValidationError(option, std::string(kParameterNames[static_cast<std::size_t>(j)]) +
                                             ": '" + std::string(fields[static_cast<std::size_t>(j)]) +
                                             "' is not a number");
    }
    x[j] = *value;
  }
  if (const auto report = mrd::model::validate(to_params(x)); !report.ok()) {
    std::string why = report.to_string();
    while (why.ends_with('\n')) why.pop_back();
    throw CLI::ValidationError(option, why);
  }
  return x;
}

// "name=lo:hi" for one parameter.
void apply_bound(Bounds& bounds, const std::string& text) {
  const auto eq = text.find('=');
  const auto colon = text.find(':', eq == std::string::npos ? 0 : eq);
  if (eq == std::string::npos || colon == std::string::npos) {
    throw CLI::ValidationError("--bounds", "expected name=lo:hi, got '" + text + "'");
  }
  const std::string name = text.substr(0, eq);
  int index = -1;
  for (int j = 0; j < kParameterCount; ++j) {
    if (kParameterNames[static_cast<std::size_t>(j)] == name) index = j;
  }
  const auto lo = mrd::record::parse_finite(std::string_view(text).substr(eq + 1, colon - eq - 1));
  const auto hi = mrd::record::parse_finite(std::string_view(text).substr(colon + 1));
  if (index < 0) throw CLI::ValidationError("--bounds", "unknown parameter '" + name + "'");
  if (!lo || !hi || !(*lo <= *hi)) {
    throw CLI::ValidationError("--bounds", name + ": need numbers lo <= hi in '" + text + "'");
  }
  // Each edge a value the parameter can take, as --start is checked: a box past it searches sets
  // no material has (a negative a, c >= 1).
  for (const double edge : {*lo, *hi}) {
    Point x = to_point(mrd::model::JilesAthertonParams{});  // a valid set, this one parameter moved
    x[index] = edge;
    if (const auto report = mrd::model::validate(to_params(x)); !report.ok()) {
      std::string why = report.to_string();
      while (why.ends_with('\n')) why.pop_back();
      throw CLI::ValidationError("--bounds", why);
    }
  }
  bounds.lower[index] = *lo;
  bounds.upper[index] = *hi;
}

bool write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  out.close();
  if (!out) std::fprintf(stderr, "mrd-identify: cannot write %s: %s\n", path.c_str(), std::strerror(errno));
  return static_cast<bool>(out);
}

// A study's table into the --out folder, as NAME.md.
bool write_table(const std::string& out_dir, const char* name, const std::string& table) {
  return out_dir.empty() || write_file((std::filesystem::path(out_dir) / name).string() + ".md", table);
}

std::vector<Algorithm> parse_algorithms(const std::vector<std::string>& names) {
  std::vector<Algorithm> out;
  for (const auto& n : names) out.push_back(*parse_algorithm(n));  // checked by IsMember
  return out;
}

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

// The input loops and how they are played through the model.
struct CurveArguments {
  std::string file;
  double turns = 0.0;
  double length = 0.0;
  double step_fraction = mrd::model::JilesAthertonSettings{}.max_field_step_fraction;

  void add_to(CLI::App& cmd) {
    cmd.add_option("file", file, "CSV with H<n>_A_per_m,B<n>_T column pairs (or I<n>_A for B-I)")->required();
    cmd.add_option("--turns", turns, "N, for B-I files [-]")->check(mrd::cli::finite_in(1.0, 1e6));
    cmd.add_option("--length", length, "Le, for B-I files [m]")->check(mrd::cli::finite_in(1e-6, 10.0));
    cmd.add_option("--step-fraction", step_fraction,
                   "J-A sub-step as a fraction of min(a (1 - alpha Ms/3a), k); larger is faster, less accurate")
        ->check(mrd::cli::finite_in(0.01, 4.0))->capture_default_str();
  }
  BHCurve read() const {
    BHCurveOptions curve_options;
    if (turns > 0.0 || length > 0.0) {
      if (!(turns > 0.0 && length > 0.0)) {
        throw CLI::ValidationError("--turns/--length", "both N > 0 and Le > 0 are needed");
      }
      curve_options.has_circuit = true;
      curve_options.circuit = {turns, length};
    }
    return read_bh_curve(file, curve_options);
  }
  mrd::model::JilesAthertonSettings settings() const {
    mrd::model::JilesAthertonSettings s;
    s.max_field_step_fraction = step_fraction;
    return s;
  }
};

// Options of the studies over several seeds and algorithms.
struct StudyArguments {
  int seeds = 20;
  std::vector<std::string> algo_names;
  std::string out_dir, plot_dir;
  bool quiet = false;

  // figure_files: what --plot writes, for its --help.
  void add_to(CLI::App& cmd, const char* table_name, const char* figure_files) {
    cmd.add_flag("--quiet,-q", quiet, "no progress line on stderr (it shows only when stderr is a terminal)");
    cmd.add_option("--seeds", seeds, "seeds per algorithm")->check(CLI::Range(1, 1000))->capture_default_str();
    cmd.add_option("--algos", algo_names, "algorithms to run, comma-separated (default: all)")
        ->delimiter(',')
        ->check(CLI::IsMember(algorithm_names()));
    cmd.add_option("--out", out_dir, std::string("folder of results: the table as ") + table_name + ".md");
    cmd.add_option("--plot", plot_dir,
                   std::string("folder for the figures of every algorithm's seed-1 run: the convergence on one, "
                               "the fitted B-H curves on another (") + figure_files + ", PNG with their .dat)");
  }
  StudyOptions study(const IdentifyOptions& options) const {
    StudyOptions s;
    s.seeds = seeds;
    s.budget = options.budget;
    s.threads = options.threads;
    s.improved = options.improved;
    if (!algo_names.empty()) s.algorithms = parse_algorithms(algo_names);
    return s;
  }
};

// A study's table rows, and each algorithm's run of seed 1 for --plot.
struct StudyOutcome {
  std::vector<StudyRow> rows;
  std::vector<IdentifyResult> first_seed_runs;
};

// Runs a study (compare and reproduce-paper take minutes) with a progress line on stderr, ended
// before it returns so that the table starts on a line of its own.
template <typename Study>
StudyOutcome run_with_progress(StudyOptions study, std::string_view stage, bool quiet, Study&& run) {
  StudyOutcome outcome;
  auto progress = TerminalProgress::on_stderr(quiet);
  study.progress = progress.get();
  study.stage = stage;
  study.first_seed_runs = &outcome.first_seed_runs;
  outcome.rows = run(study);
  return outcome;
}

// --plot: the figures of a study. Without gnuplot the tables still stand: a note, not an error.
void plot_study(const StudyOutcome& outcome, const BHCurve& curve, const StudyOptions& study,
                const StudyFigureLabels& labels, const std::string& directory) {
  if (directory.empty()) return;
  const std::string why =
      plot_study_runs(outcome.first_seed_runs, BHObjective(curve, study.settings), curve, labels, directory);
  if (!why.empty()) std::fprintf(stderr, "mrd-identify: plot skipped: %s\n", why.c_str());
}

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

// --write-config: the identified set into [damper.jiles_atherton] of the file (patched in place:
// its order and comments stay), or of the compiled-in default when the file does not exist yet.
int write_config(const std::string& path, const Point& best) {
  std::error_code ec;
  const bool existing = std::filesystem::exists(path, ec);
  std::string text;
  try {
    text = existing ? mrd::record::read_text_file(path) : std::string(mrd::config::default_config_text());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mrd-identify: --write-config: %s\n", e.what());
    return mrd::cli::kIo;
  }
  toml::table ja;
  for (int j = 0; j < kParameterCount; ++j) ja.insert(std::string(kParameterNames[static_cast<std::size_t>(j)]), best[j]);
  toml::table damper;
  damper.insert("jiles_atherton", std::move(ja));
  toml::table values;
  values.insert("damper", std::move(damper));
  mrd::tools::round_floats(values);
  try {
    text = patch_toml(text, values);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mrd-identify: --write-config %s: %s\n", path.c_str(), e.what());
    return mrd::cli::kUsage;
  }
  return write_file(path, text) ? mrd::cli::kOk : mrd::cli::kIo;  // write_file says why
}

int run_fit(const FitArguments& args) {
  IdentifyOptions options = args.options;
  const auto algorithm = parse_algorithm(args.algo);
  options.algorithm = *algorithm;
  options.polish = args.polish;
  const BHCurve curve = args.curve.read();
  const BHObjective objective(curve, args.curve.settings());

  if (!args.start_text.empty()) options.start = parse_parameter_list("--start", args.start_text);
  const Point start = options.start ? *options.start : estimate_start_point(curve);
  if (!args.bound_texts.empty()) {
    options.start = start;  // the box is the user's: no re-centring
    Bounds bounds = bounds_around(start);
    for (const auto& b : args.bound_texts) apply_bound(bounds, b);
    options.bounds = bounds;
  }
  auto progress = TerminalProgress::on_stderr(args.quiet);
  options.progress = progress.get();
  const IdentifyResult result = identify(objective, curve, options);
  progress.reset();  // ends the status line before the result
  std::fputs(identify_text(result, objective).c_str(), stdout);
  const IdentifyStatistics statistics = identify_statistics(result, objective, curve);
  for (const std::string& line : statistics.flagged)
    std::printf("unphysical: %s (--write-config needs --accept-unphysical)\n", line.c_str());
  if (!args.json_path.empty() && !write_file(args.json_path, identify_json(result, &statistics))) return mrd::cli::kIo;
  if (!args.plot_dir.empty()) {
    const std::string why = plot_identification(result, objective, curve, args.plot_dir);
    if (!why.empty()) std::fprintf(stderr, "mrd-identify: plot skipped: %s\n", why.c_str());
  }
  if (!args.config_path.empty() && !statistics.flagged.empty() && !args.accept_unphysical) {
    std::fprintf(stderr, "mrd-identify: --write-config: %s not written: %zu parameter(s) flagged (listed as "
                 "'unphysical:' above); --accept-unphysical writes it anyway\n",
                 args.config_path.c_str(), statistics.flagged.size());
    return mrd::cli::kBadInput;
  }
  if (!args.config_path.empty()) {
    const Point best = result.polish ? result.polish->best : result.search.best;
    if (const int status = write_config(args.config_path, best); status != mrd::cli::kOk) return status;
  }
  if (!args.report_dir.empty()) {
    std::vector<const char*> words;
    for (const auto& w : args.argv) words.push_back(w.c_str());
    const Provenance provenance = provenance_of("mrd-identify", static_cast<int>(words.size()), words.data(),
                                                {args.curve.file}, std::to_string(options.seed));
    if (const auto why = write_identify_report(result, statistics, objective, curve, provenance, args.report_dir);
        !why.empty()) {
      std::fprintf(stderr, "mrd-identify: report: %s\n", why.c_str());
      return mrd::cli::kIo;
    }
  }
  return 0;
}

int run_evaluate(const CurveArguments& curve_args, const std::string& parameter_text) {
  const Point x = parse_parameter_list("params", parameter_text);  // errors end here; warnings print
  std::fputs(mrd::model::validate(to_params(x)).to_string().c_str(), stderr);
  const BHObjective objective(curve_args.read(), curve_args.settings());
  const FitEvaluation fit = objective.evaluate(to_params(x));
  std::printf("%s: %zu points, RMSE %.6g T (%.4g%% of rms B %.4g T)%s\n", curve_args.file.c_str(),
              objective.points(), fit.rmse, 100.0 * fit.rmse / objective.rms_B(), objective.rms_B(),
              fit.penalised ? " [non-physical: Eq. 10 guard fired]" : "");
  return 0;
}

int run_compare(const CurveArguments& curve_args, const StudyArguments& args, const IdentifyOptions& options) {
  const BHCurve curve = curve_args.read();
  const BHObjective objective(curve, curve_args.settings());
  StudyOptions study = args.study(options);
  study.settings = curve_args.settings();
  const StudyOutcome outcome = run_with_progress(
      study, "compare", args.quiet, [&](const StudyOptions& s) { return measured_fit_study(curve, s); });
  char summary[160];
  std::snprintf(summary, sizeof summary, "%zu loops, %zu points, rms B %.4g T; %d seeds each.\n\n",
                curve.loops.size(), objective.points(), objective.rms_B(), study.seeds);
  const std::string table = summary + fit_table_markdown(outcome.rows, objective.rms_B());
  std::fputs(table.c_str(), stdout);
  plot_study(outcome, curve, study,
             {.stem = "compare", .set = std::filesystem::path(curve_args.file).filename().string()}, args.plot_dir);
  return write_table(args.out_dir, "compare", table) ? mrd::cli::kOk : mrd::cli::kIo;
}

// reproduce-paper's known sets: the paper's Table 1 read as a = 25.3 A/m, alpha = 8.43e-5, at an
// amplitude where it is physical (docs/MODEL.md); the classic Jiles-Atherton steel set (1986),
// well conditioned.
struct KnownSet {
  std::string name;  // the table's heading
  StudyFigureLabels figures;
  mrd::model::JilesAthertonParams truth;
  double H_max = 0.0;
};

std::vector<KnownSet> known_sets(double table1_H_max) {
  const std::string amplitude = format("%g A/m", table1_H_max);
  return {{"Paper Table 1 set, Hmax " + amplitude,
           {"table1", "Paper Table 1 set, " + amplitude + " loop", "+-100% box", true},
           {1.3e6, 25.3, 8.43e-5, 66.6, 0.2},
           table1_H_max},
          {"Steel set (Ms 1.6e6, a 1100, alpha 1.6e-3, k 400, c 0.2), Hmax 5 kA/m",
           {"steel", "Steel set, 5 kA/m loop", "+-100% box", true},
           {1.6e6, 1100.0, 1.6e-3, 400.0, 0.2},
           5000.0}};
}

// Section 4.1 on one known set: its table and sensitivity into `report`, its figures into --plot.
void study_known_set(const KnownSet& set, const StudyArguments& args, const StudyOptions& study,
                     std::ostringstream& report) {
  const BHCurve curve = synthetic_loop(set.truth, set.H_max, 1000);
  std::fprintf(stderr, "reproduce-paper: %s ...\n", set.name.c_str());
  const auto sensitivity = parameter_sensitivity(BHObjective(curve), to_point(set.truth));
  const StudyOutcome outcome = run_with_progress(study, "recovery", args.quiet, [&](const StudyOptions& s) {
    return parameter_recovery_study(set.truth, curve, s);
  });
  report << "### " << set.name << "\n\nRelative error of each parameter [%], median [q25, q75] over "
         << study.seeds << " seeds; population " << study.budget.population << ", budget "
         << study.budget.evaluations << " evaluations, 1000 points.\n\n"
         << recovery_table_markdown(outcome.rows)
         << "\nSensitivity at the true values (singular values of dB/dln(theta), and the "
            "parameter mix of each direction):\n\n"
         << sensitivity_markdown(sensitivity) << "\n";
  plot_study(outcome, curve, study, set.figures, args.plot_dir);
}

int reproduce_paper(const StudyArguments& args, const IdentifyOptions& options, double table1_H_max) {
  const StudyOptions study = args.study(options);
  std::ostringstream report;
  for (const KnownSet& set : known_sets(table1_H_max)) study_known_set(set, args, study, report);
  std::fputs(report.str().c_str(), stdout);
  return write_table(args.out_dir, "reproduce-paper", report.str()) ? mrd::cli::kOk : mrd::cli::kIo;
}

struct SyntheticArguments {
  std::string path, truth_text;
  double H_max = 0.0;
  std::size_t points = 1000;
};

int run_synthetic(const SyntheticArguments& args) {
  const Point truth = parse_parameter_list("--truth", args.truth_text);
  const BHCurve curve = synthetic_loop(to_params(truth), args.H_max, args.points);
  std::ostringstream csv;
  csv.precision(12);
  csv << "H_A_per_m,B_T\n";
  for (std::size_t i = 0; i < curve.loops[0].H.size(); ++i) {
    csv << curve.loops[0].H[i] << ',' << curve.loops[0].B[i] << '\n';
  }
  return write_file(args.path, csv.str()) ? mrd::cli::kOk : mrd::cli::kIo;
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
  fit.curve.add_to(cmd);
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
  c.evaluate_curve.add_to(*c.evaluate_cmd);
  c.evaluate_cmd->add_option("params", c.evaluate_text, "Ms,a,alpha,k,c")->required();
}

void add_compare_command(CLI::App& app, Commands& c) {
  c.compare_cmd = app.add_subcommand("compare", "run every algorithm over several seeds on a file");
  c.compare_curve.add_to(*c.compare_cmd);
  add_search_options(*c.compare_cmd, c.compare_options);
  c.compare_study.add_to(*c.compare_cmd, "compare", "compare_convergence.png, compare_bh.png");
}

void add_paper_command(CLI::App& app, Commands& c) {
  c.paper_cmd = app.add_subcommand("reproduce-paper", "Section 4.1 protocol on two known sets, all algorithms");
  add_search_options(*c.paper_cmd, c.paper_options);
  c.paper_study.add_to(*c.paper_cmd, "reproduce-paper", "table1_convergence.png, table1_bh.png, steel_*.png");
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
