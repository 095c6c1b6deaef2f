// mrd-simulate-run: a recorded-run CSV from the simulated damper, optionally carrying effects the
// run does not declare (the test material of the residual analysis, docs/CLOSING-THE-LOOP.md).
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "common/cli/command_line.hpp"
#include "model/effects/effect_set.hpp"
#include "record/csv.hpp"
#include "tools/simulation/run_csv.hpp"
#include "tools/simulation/run_generator.hpp"

namespace {

void list_effects() {
  for (const char* name : {"50kN", "1kN"}) {
    const auto c = *mrd::tools::find_damper_class(name);
    std::printf("%s class, size 1 (small = 0.5, large = 2 times it):\n", name);
    for (const mrd::model::EffectInfo& e : mrd::model::effect_infos()) {
      if (!e.named_candidate) continue;
      std::printf("  %-20s %s\n", std::string(e.name).c_str(), e.size_summary(c.nominal_effects).c_str());
    }
  }
}

// What the command line asks for, before it is checked and resolved into RunOptions.
struct Arguments {
  mrd::tools::RunOptions options;
  std::string out_dir, csv_path;
  std::string profile = "table4";
  std::string damper = "50kN";
  std::vector<std::string> effects;
  double amplitude_mm = 0.0;
  double noise_um = -1.0;
  std::string manifest;
  mrd::tools::RunColumns columns;
  bool no_velocity = false;
  bool show_effects = false;
  bool report_residual = false;
};

void add_options(CLI::App& app, Arguments& a) {
  mrd::tools::RunOptions& options = a.options;
  auto* out_option = app.add_option("--out", a.out_dir, "folder of results: run.csv and manifest.json");
  auto* csv_option = app.add_option("--csv", a.csv_path, "write the run's CSV to exactly this file instead");
  out_option->excludes(csv_option);
  app.add_option("--profile", a.profile,
                 "table4 (sine, Table 4 currents), paper-sines (0.05-1 Hz, Table 4 currents), sine "
                 "(constant current), random (band-limited motion, constant current), telegraph "
                 "(band-limited motion, random telegraph current)")
      ->check(CLI::IsMember({"table4", "paper-sines", "sine", "random", "telegraph"}))
      ->capture_default_str();
  app.add_option("--damper", a.damper, "damper class")->check(CLI::IsMember({"50kN", "1kN"}))->capture_default_str();
  app.add_option("--rate", options.rate, "sample rate [Hz]")->check(mrd::cli::finite_in(1.0, 1e6))->capture_default_str();
  app.add_option("--duration", options.duration,
                 "seconds; default 5 cycles (sines), 30 s (random, telegraph), the whole sequence")
      ->check(mrd::cli::finite_in(0.01, 86400.0));
  app.add_option("--frequency", options.frequency, "sine frequency [Hz]")->check(mrd::cli::finite_in(1e-3, 1000.0))
      ->capture_default_str();
  app.add_option("--amplitude-mm", a.amplitude_mm, "sine amplitude or random peak [mm]; default the class's")
      ->check(mrd::cli::finite_in(1e-3, 1000.0));
  app.add_option("--current", options.current,
                 "constant current, or the telegraph's high level [A]; default half (telegraph: all) "
                 "of the class's maximum")
      ->check(mrd::cli::finite_in(0.0, 100.0));
  app.add_option("--cycles", options.cycles, "paper-sines: cycles per frequency")->check(CLI::Range(1, 1000))
      ->capture_default_str();
  app.add_option("--dwell", options.dwell, "telegraph mean dwell [s]")->check(mrd::cli::finite_in(1e-4, 100.0))
      ->capture_default_str();
  app.add_option("--noise-um", a.noise_um, "LVDT noise RMS [um]; default the class's")
      ->check(mrd::cli::finite_in(0.0, 1e5));
  app.add_option("--force-noise-n", options.force_noise, "load-cell noise RMS [N]; default the class's")
      ->check(mrd::cli::finite_in(0.0, 1e7));
  app.add_option("--seed", options.seed, "noise, random motion and telegraph seed")->capture_default_str();
  // Checked while parsing, so a misspelt effect is a usage error that names the option.
  const CLI::Validator effect_request(
      [](std::string& text) {
        std::string error;
        return mrd::tools::parse_effect_request(text, error) ? std::string() : error;
      },
      "NAME[:SIZE]");
  app.add_option("--effect", a.effects, "NAME[:SIZE], repeatable; SIZE small, medium, large or a factor "
                                        "(--list-effects names them)")
      ->check(effect_request);
  app.add_flag("--with-B", a.columns.B, "add the B_T column");
  app.add_flag("--with-temperature", a.columns.temperature, "add the temperature_C column");
  app.add_flag("--no-velocity", a.no_velocity, "leave out the velocity_mm_s column");
  app.add_option("--manifest", a.manifest, "also write what the run carries, as JSON, to this file");
  app.add_flag("--residual", a.report_residual,
               "also print the RMS error of the class's base model replayed on the written run, and of "
               "the model with the effects the run carries (the best a residual analysis can reach)");
  app.add_flag("--list-effects", a.show_effects, "print the effects' sizes per damper class and exit");
}

int fail(const std::string& message, int status = mrd::cli::kUsage) {
  std::fprintf(stderr, "mrd-simulate-run: %s\n", message.c_str());
  return status;
}

// The options' text resolved into RunOptions and checked; an error is the usage message.
std::optional<std::string> resolve_arguments(Arguments& a) {
  if (a.out_dir.empty() && a.csv_path.empty()) return "--out DIR or --csv FILE is required";
  const auto parsed_profile = mrd::tools::parse_run_profile(a.profile);
  if (!parsed_profile) return "unknown profile '" + a.profile + "'";
  a.options.profile = *parsed_profile;
  const auto damper_class = mrd::tools::find_damper_class(a.damper);
  if (!damper_class) return "unknown damper class '" + a.damper + "' (50kN, 1kN)";
  a.options.damper = *damper_class;
  a.options.amplitude = a.amplitude_mm * 1e-3;
  a.options.lvdt_noise = a.noise_um < 0.0 ? -1.0 : a.noise_um * 1e-6;
  a.columns.velocity = !a.no_velocity;
  for (const auto& text : a.effects) {
    std::string error;
    const auto request = mrd::tools::parse_effect_request(text, error);
    if (!request) return error;
    a.options.effects.push_back(*request);
  }
  if (std::string problems = mrd::tools::check(mrd::tools::resolve(a.options)); !problems.empty()) return problems;
  return std::nullopt;
}

// The run's CSV and, when asked or with --out, its manifest; an error names the file.
std::optional<std::string> write_outputs(const mrd::tools::SimulatedRun& run, const Arguments& a) {
  std::ofstream file(a.csv_path);
  mrd::tools::write_run_csv(file, run, a.columns);
  file.close();
  if (!file) return "cannot write " + a.csv_path + ": " + std::strerror(errno);
  if (!a.manifest.empty()) {
    if (std::string why = mrd::record::write_text_file(a.manifest, mrd::tools::run_manifest_json(run)); !why.empty())
      return why;
  }
  return std::nullopt;
}

void print_summary(const mrd::tools::SimulatedRun& run, const Arguments& a) {
  std::string carried;
  for (const auto& e : run.options.effects) {
    char size[32];
    std::snprintf(size, sizeof size, ":%g", e.size);
    carried += " " + e.name + size;
  }
  std::printf("mrd-simulate-run: %s, %s damper, %zu samples at %.0f Hz (%.1f s), seed %llu, effects:%s\n",
              std::string(to_string(run.options.profile)).c_str(), run.options.damper.name.c_str(),
              run.samples.size(), run.options.rate, run.options.duration,
              static_cast<unsigned long long>(run.options.seed), carried.empty() ? " none" : carried.c_str());
  if (a.report_residual) {
    std::printf("base model residual: %.4g N RMS; with the carried effects: %.4g N RMS (load-cell noise %.4g N)\n",
                mrd::tools::model_residual(run), mrd::tools::model_residual(run, run.effects),
                run.options.force_noise);
  }
  std::printf("wrote %s%s%s\n", a.csv_path.c_str(), a.manifest.empty() ? "" : " and ", a.manifest.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Write a recorded-run CSV from the simulated damper, with effects it does not declare"};
  mrd::cli::set_up(app, "mrd-simulate-run");
  Arguments a;
  add_options(app, a);
  if (const auto status = mrd::cli::parse(app, argc, argv)) return *status;
  if (a.show_effects) {
    list_effects();
    return mrd::cli::kOk;
  }
  if (const auto error = resolve_arguments(a)) return fail(*error);
  if (!a.out_dir.empty()) {
    if (!mrd::cli::prepare_output_directory("mrd-simulate-run", a.out_dir)) return mrd::cli::kIo;
    a.csv_path = (std::filesystem::path(a.out_dir) / "run.csv").string();
    if (a.manifest.empty()) a.manifest = (std::filesystem::path(a.out_dir) / "manifest.json").string();
  }
  if (!mrd::cli::check_outputs("mrd-simulate-run", {&a.csv_path, &a.manifest}, {})) return mrd::cli::kIo;
  const mrd::tools::SimulatedRun run = mrd::tools::simulate_run(a.options);
  if (const auto error = write_outputs(run, a)) return fail(*error, mrd::cli::kIo);
  print_summary(run, a);
  return mrd::cli::kOk;
}
