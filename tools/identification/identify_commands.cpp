#include "tools/identification/identify_commands.hpp"

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/cli/exit_code.hpp"
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

namespace mrd::tools {

namespace {

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

}  // namespace

BHCurve CurveArguments::read() const {
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
mrd::model::JilesAthertonSettings CurveArguments::settings() const {
  mrd::model::JilesAthertonSettings s;
  s.max_field_step_fraction = step_fraction;
  return s;
}

StudyOptions StudyArguments::study(const IdentifyOptions& options) const {
  StudyOptions s;
  s.seeds = seeds;
  s.budget = options.budget;
  s.threads = options.threads;
  s.improved = options.improved;
  if (!algo_names.empty()) s.algorithms = parse_algorithms(algo_names);
  return s;
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

}  // namespace mrd::tools
