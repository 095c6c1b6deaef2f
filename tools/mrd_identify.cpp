// mrd-identify: the five J-A parameters (Ms, a, alpha, k, c) from measured B-H (or B-I)
// loops, by minimising the RMSE of B (Eq. 15). See docs/IDENTIFICATION.md.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "record/csv.hpp"
#include "tools/identification/identification_study.hpp"
#include "tools/identification/identify_report.hpp"
#include "tools/identification/start_point.hpp"
#include "tools/identification/synthetic_curve.hpp"

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
  bounds.lower[index] = *lo;
  bounds.upper[index] = *hi;
}

bool write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  return static_cast<bool>(out);
}

std::vector<Algorithm> parse_algorithms(const std::vector<std::string>& names) {
  std::vector<Algorithm> out;
  for (const auto& n : names) {
    const auto a = parse_algorithm(n);
    if (!a) throw CLI::ValidationError("--algos", "unknown algorithm '" + n + "'");
    out.push_back(*a);
  }
  return out;
}

int reproduce_paper(const StudyOptions& study, double table1_H_max, const std::string& out_path) {
  struct Case {
    const char* name;
    mrd::model::JilesAthertonParams truth;
    double H_max;
  };
  // Table 1 read as a = 25.3 A/m, alpha = 8.43e-5, at 60 A/m, where it is physical
  // (docs/MODEL.md); and the classic Jiles-Atherton steel set (1986), well conditioned.
  const std::string table1_name =
      "Paper Table 1 set, Hmax " + std::to_string(static_cast<int>(table1_H_max)) + " A/m";
  const Case cases[] = {{table1_name.c_str(), {1.3e6, 25.3, 8.43e-5, 66.6, 0.2}, table1_H_max},
                        {"Steel set (Ms 1.6e6, a 1100, alpha 1.6e-3, k 400, c 0.2), Hmax 5 kA/m",
                         {1.6e6, 1100.0, 1.6e-3, 400.0, 0.2}, 5000.0}};
  std::ostringstream report;
  for (const auto& c : cases) {
    const BHCurve curve = synthetic_loop(c.truth, c.H_max, 1000);
    std::fprintf(stderr, "reproduce-paper: %s ...\n", c.name);
    const auto sensitivity = parameter_sensitivity(BHObjective(curve), to_point(c.truth));
    const auto rows = parameter_recovery_study(c.truth, curve, study);
    report << "### " << c.name << "\n\nRelative error of each parameter [%], median [q25, q75] over "
           << study.seeds << " seeds; population " << study.budget.population << ", budget "
           << study.budget.evaluations << " evaluations, 1000 points.\n\n"
           << recovery_table_markdown(rows)
           << "\nSensitivity at the true values (singular values of dB/dln(theta), and the "
              "parameter mix of each direction):\n\n"
           << sensitivity_markdown(sensitivity) << "\n";
  }
  std::fputs(report.str().c_str(), stdout);
  if (!out_path.empty() && !write_file(out_path, report.str())) {
    std::fprintf(stderr, "mrd-identify: cannot write %s\n", out_path.c_str());
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Identify Jiles-Atherton parameters from measured B-H loops (Eq. 15)"};
  std::string file, algo = "improved-pso", json_path, plot_dir, start_text, evaluate_text, out_path;
  std::vector<std::string> bound_texts, algo_names;
  IdentifyOptions options;
  bool polish = false, reproduce = false, compare = false;
  int seeds = 20;
  double table1_H_max = 60.0;
  double step_fraction = mrd::model::JilesAthertonSettings{}.max_field_step_fraction;
  double turns = 0.0, length = 0.0;
  app.add_option("file", file, "CSV with H<n>_A_per_m,B<n>_T column pairs (or I<n>_A for B-I)");
  app.add_option("--algo", algo,
                 "pso | improved-pso | pagmo-pso | pagmo-de | pagmo-sade | pagmo-cmaes")
      ->capture_default_str();
  app.add_option("--seed", options.seed, "random seed; a seed gives the same run")->capture_default_str();
  app.add_option("--population", options.budget.population)->check(CLI::Range(5, 10000))->capture_default_str();
  app.add_option("--evaluations", options.budget.evaluations, "budget of model evaluations")
      ->check(CLI::Range(10, 100000000))->capture_default_str();
  app.add_option("--threads", options.threads, "0 = all cores (pagmo runs serially)")->capture_default_str();
  app.add_option("--start", start_text, "start point Ms,a,alpha,k,c (default: estimated from the loops)");
  app.add_option("--bounds", bound_texts, "name=lo:hi, repeatable (default: +-100% of the start)");
  app.add_flag("--polish", polish, "refine with Levenberg-Marquardt after the global search");
  app.add_option("--json", json_path, "write the result as JSON");
  app.add_option("--plot", plot_dir, "write the B-H overlay and convergence PNGs here");
  app.add_option("--turns", turns, "N, for B-I files [-]");
  app.add_option("--length", length, "Le, for B-I files [m]");
  app.add_option("--step-fraction", step_fraction,
                 "J-A sub-step as a fraction of min(a, k); larger is faster, less accurate")
      ->check(CLI::Range(0.01, 4.0))->capture_default_str();
  app.add_option("--evaluate", evaluate_text, "only print the RMSE of Ms,a,alpha,k,c on the file");
  std::string synthetic_path, truth_text;
  double synthetic_H_max = 0.0;
  std::size_t synthetic_points = 1000;
  app.add_option("--write-synthetic", synthetic_path,
                 "write one simulated major loop of --truth at --H-max to this CSV, then exit");
  app.add_option("--truth", truth_text, "Ms,a,alpha,k,c for --write-synthetic");
  app.add_option("--H-max", synthetic_H_max, "loop amplitude for --write-synthetic [A/m]");
  app.add_option("--points", synthetic_points, "points for --write-synthetic")->capture_default_str();
  app.add_flag("--reproduce-paper", reproduce, "Section 4.1 protocol on two known sets, all algorithms");
  app.add_option("--table1-amplitude", table1_H_max,
                 "--reproduce-paper: loop amplitude for the Table 1 set [A/m]; physical up to ~81")
      ->check(CLI::Range(1.0, 1e6))->capture_default_str();
  app.add_flag("--compare", compare, "run every algorithm over --seeds seeds on the file");
  app.add_option("--seeds", seeds, "seeds for --reproduce-paper and --compare")->check(CLI::Range(1, 1000))
      ->capture_default_str();
  app.add_option("--algos", algo_names, "algorithms for --reproduce-paper and --compare (default: all)");
  auto& ips = options.improved;
  app.add_option("--w-max", ips.w_max, "improved-pso: inertia at the start, Eq. 16")->capture_default_str();
  app.add_option("--w-min", ips.w_min, "improved-pso: inertia at the end, Eq. 16")->capture_default_str();
  app.add_option("--c1", ips.c1, "improved-pso: cognitive factor, Eq. 14")->capture_default_str();
  app.add_option("--c2", ips.c2, "improved-pso: social factor, Eq. 14")->capture_default_str();
  app.add_option("--velocity-limit", ips.velocity_limit, "improved-pso: |v| limit, fraction of the range")
      ->capture_default_str();
  app.add_option("--F", ips.F, "improved-pso: DE scaling factor, Eq. 18")->capture_default_str();
  app.add_option("--F-spread", ips.F_spread, "improved-pso: F drawn from [F, F + spread] per trial")
      ->capture_default_str();
  app.add_option("--CR", ips.CR, "improved-pso: DE crossover probability, Eq. 19")->capture_default_str();
  app.add_option("--stall", ips.stall_iterations, "improved-pso: iterations without gain before Cauchy")
      ->capture_default_str();
  app.add_option("--cauchy-scale", ips.cauchy_scale, "improved-pso: Eq. 22 step scale")->capture_default_str();
  app.add_option("--cauchy-trials", ips.cauchy_trials, "improved-pso: Eq. 22 draws per stall")->capture_default_str();
  app.add_option("--out", out_path, "also write the --reproduce-paper/--compare table here (Markdown)");
  CLI11_PARSE(app, argc, argv);

  try {
    StudyOptions study;
    study.seeds = seeds;
    study.budget = options.budget;
    study.threads = options.threads;
    study.improved = options.improved;
    if (!algo_names.empty()) study.algorithms = parse_algorithms(algo_names);
    if (reproduce) return reproduce_paper(study, table1_H_max, out_path);
    if (!synthetic_path.empty()) {
      if (!(synthetic_H_max > 0.0)) throw CLI::ValidationError("--H-max", "must be > 0");
      const Point truth = parse_parameter_list("--truth", truth_text);
      const BHCurve curve = synthetic_loop(to_params(truth), synthetic_H_max, synthetic_points);
      std::ostringstream csv;
      csv.precision(12);
      csv << "H_A_per_m,B_T\n";
      for (std::size_t i = 0; i < curve.loops[0].H.size(); ++i) {
        csv << curve.loops[0].H[i] << ',' << curve.loops[0].B[i] << '\n';
      }
      return write_file(synthetic_path, csv.str()) ? 0 : 1;
    }

    if (file.empty()) throw CLI::ValidationError("file", "a B-H curve file is required");
    const auto algorithm = parse_algorithm(algo);
    if (!algorithm) throw CLI::ValidationError("--algo", "unknown algorithm '" + algo + "'");
    options.algorithm = *algorithm;
    options.polish = polish;

    BHCurveOptions curve_options;
    if (turns > 0.0 || length > 0.0) {
      if (!(turns > 0.0 && length > 0.0)) {
        throw CLI::ValidationError("--turns/--length", "both N > 0 and Le > 0 are needed");
      }
      curve_options.has_circuit = true;
      curve_options.circuit = {turns, length};
    }
    const BHCurve curve = read_bh_curve(file, curve_options);
    mrd::model::JilesAthertonSettings settings;
    settings.max_field_step_fraction = step_fraction;
    const BHObjective objective(curve, settings);

    if (!evaluate_text.empty()) {
      const Point x = parse_parameter_list("--evaluate", evaluate_text);
      const auto report = mrd::model::validate(to_params(x));
      std::fputs(report.to_string().c_str(), stderr);
      const FitEvaluation fit = objective.evaluate(to_params(x));
      std::printf("%s: %zu points, RMSE %.6g T (%.4g%% of rms B %.4g T)%s\n", file.c_str(),
                  objective.points(), fit.rmse, 100.0 * fit.rmse / objective.rms_B(),
                  objective.rms_B(), fit.penalised ? " [non-physical: Eq. 10 guard fired]" : "");
      return 0;
    }
    if (compare) {
      const auto rows = measured_fit_study(curve, study);
      char summary[160];
      std::snprintf(summary, sizeof summary, "%zu loops, %zu points, rms B %.4g T; %d seeds each.\n\n",
                    curve.loops.size(), objective.points(), objective.rms_B(), study.seeds);
      const std::string table = summary + fit_table_markdown(rows, objective.rms_B());
      std::fputs(table.c_str(), stdout);
      if (!out_path.empty() && !write_file(out_path, table)) return 1;
      return 0;
    }

    if (!start_text.empty()) options.start = parse_parameter_list("--start", start_text);
    const Point start = options.start ? *options.start : estimate_start_point(curve);
    if (!bound_texts.empty()) options.start = start;  // the box is the user's: no re-centring
    if (!start_text.empty()) options.start = start;
    if (!bound_texts.empty()) {
      Bounds bounds = bounds_around(start);
      for (const auto& b : bound_texts) apply_bound(bounds, b);
      options.bounds = bounds;
    }
    const IdentifyResult result = identify(objective, curve, options);
    std::fputs(identify_text(result, objective).c_str(), stdout);
    if (!json_path.empty() && !write_file(json_path, identify_json(result))) {
      std::fprintf(stderr, "mrd-identify: cannot write %s\n", json_path.c_str());
      return 1;
    }
    if (!plot_dir.empty()) {
      const std::string why = plot_identification(result, objective, curve, plot_dir);
      if (!why.empty()) std::fprintf(stderr, "mrd-identify: plot skipped: %s\n", why.c_str());
    }
    return 0;
  } catch (const CLI::Error& e) {
    return app.exit(e);
  } catch (const mrd::record::InputError& e) {
    std::fprintf(stderr, "mrd-identify: %s\n", e.what());
    return 2;
  }
}
