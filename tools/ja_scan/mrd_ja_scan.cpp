// mrd-ja-scan: where is a J-A parameter set physical? Runs symmetric major loops over a range
// of field amplitudes and reports, per amplitude, whether Eq. 10 ran away (its denominator
// guard fired), the loop's tip, remanence, closure and symmetry.
#include <CLI/CLI.hpp>
#include <cstdio>

#include "common/cli/command_line.hpp"
#include "tools/ja_scan/loop_scan.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Scan J-A major loops over field amplitude"};
  mrd::cli::set_up(app, "mrd-ja-scan");
  mrd::model::JilesAthertonParams p;
  double H_from = 1.0, H_to = 1e5;
  int points = 41;
  bool table1 = false;
  app.add_flag("--paper-table1", table1,
               "the paper's Table 1 set read as a = 25.3 A/m, alpha = 8.43e-5 (docs/MODEL.md)");
  app.add_option("--Ms", p.Ms, "[A/m]")->capture_default_str();
  app.add_option("--a", p.a, "[A/m]")->capture_default_str();
  app.add_option("--alpha", p.alpha)->capture_default_str();
  app.add_option("--k", p.k, "[A/m]")->capture_default_str();
  app.add_option("--c", p.c)->capture_default_str();
  app.add_option("--from", H_from, "smallest amplitude [A/m]")->check(mrd::cli::finite_in(1e-6, 1e9))
      ->capture_default_str();
  app.add_option("--to", H_to, "largest amplitude [A/m]")->check(mrd::cli::finite_in(1e-6, 1e9))
      ->capture_default_str();
  app.add_option("--points", points, "amplitudes, log-spaced")->check(CLI::Range(2, 1000))
      ->capture_default_str();
  bool integrator = false;
  app.add_flag("--integrator-error", integrator,
               "print RK4 and Heun error against a 100x finer RK4 reference with the exact "
               "Langevin function, and what the tabulated Langevin function changes, then exit");
  if (const auto status = mrd::cli::parse(app, argc, argv)) return *status;
  if (table1) p = {1.3e6, 25.3, 8.43e-5, 66.6, 0.2};
  const auto report = mrd::model::validate(p);
  std::fputs(report.to_string().c_str(), stderr);
  if (!report.ok() || !(H_from > 0.0) || !(H_to > H_from)) {
    std::fprintf(stderr, "mrd-ja-scan: invalid parameters or range\n");
    return mrd::cli::kUsage;
  }

  if (integrator) {
    mrd::tools::print_integrator_errors(p);
  } else {
    mrd::tools::print_loop_scan(p, H_from, H_to, points);
  }
  return 0;
}
