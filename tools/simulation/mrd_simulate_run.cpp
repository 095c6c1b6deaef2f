// mrd-simulate-run: a recorded-run CSV from the simulated damper, optionally carrying effects the
// run does not declare (the test material of the residual analysis, docs/CLOSING-THE-LOOP.md).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/cli/command_line.hpp"
#include "model/effects/effect_set.hpp"
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

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Write a recorded-run CSV from the simulated damper, with effects it does not declare"};
  mrd::cli::set_up(app, "mrd-simulate-run");
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
  auto* out_option = app.add_option("--out", out_dir, "folder of results: run.csv and manifest.json");
  auto* csv_option = app.add_option("--csv", csv_path, "write the run's CSV to exactly this file instead");
  out_option->excludes(csv_option);
  app.add_option("--profile", profile,
                 "table4 (sine, Table 4 currents), paper-sines (0.05-1 Hz, Table 4 currents), sine "
                 "(constant current), random (band-limited motion, constant current), telegraph "
                 "(band-limited motion, random telegraph current)")
      ->check(CLI::IsMember({"table4", "paper-sines", "sine", "random", "telegraph"}))
      ->capture_default_str();
  app.add_option("--damper", damper, "damper class")->check(CLI::IsMember({"50kN", "1kN"}))->capture_default_str();
  app.add_option("--rate", options.rate, "sample rate [Hz]")->capture_default_str();
  app.add_option("--duration", options.duration,
                 "seconds; default 5 cycles (sines), 30 s (random, telegraph), the whole sequence");
  app.add_option("--frequency", options.frequency, "sine frequency [Hz]")->capture_default_str();
  app.add_option("--amplitude-mm", amplitude_mm, "sine amplitude or random peak [mm]; default the class's");
  app.add_option("--current", options.current,
                 "constant current, or the telegraph's high level [A]; default half (telegraph: all) "
                 "of the class's maximum");
  app.add_option("--cycles", options.cycles, "paper-sines: cycles per frequency")->capture_default_str();
  app.add_option("--dwell", options.dwell, "telegraph mean dwell [s]")->capture_default_str();
  app.add_option("--noise-um", noise_um, "LVDT noise RMS [um]; default the class's");
  app.add_option("--force-noise-n", options.force_noise, "load-cell noise RMS [N]; default the class's");
  app.add_option("--seed", options.seed, "noise, random motion and telegraph seed")->capture_default_str();
  // Checked while parsing, so a misspelt effect is a usage error that names the option.
  const CLI::Validator effect_request(
      [](std::string& text) {
        std::string error;
        return mrd::tools::parse_effect_request(text, error) ? std::string() : error;
      },
      "NAME[:SIZE]");
  app.add_option("--effect", effects, "NAME[:SIZE], repeatable; SIZE small, medium, large or a factor "
                                      "(--list-effects names them)")
      ->check(effect_request);
  app.add_flag("--with-B", columns.B, "add the B_T column");
  app.add_flag("--with-temperature", columns.temperature, "add the temperature_C column");
  app.add_flag("--no-velocity", no_velocity, "leave out the velocity_mm_s column");
  app.add_option("--manifest", manifest, "also write what the run carries, as JSON, to this file");
  app.add_flag("--residual", report_residual,
               "also print the RMS error of the class's base model replayed on the written run, and of "
               "the model with the effects the run carries (the best a residual analysis can reach)");
  app.add_flag("--list-effects", show_effects, "print the effects' sizes per damper class and exit");
  if (const auto status = mrd::cli::parse(app, argc, argv)) return *status;

  if (show_effects) {
    list_effects();
    return mrd::cli::kOk;
  }
  const auto fail = [](const std::string& message, int status = mrd::cli::kUsage) {
    std::fprintf(stderr, "mrd-simulate-run: %s\n", message.c_str());
    return status;
  };
  if (out_dir.empty() && csv_path.empty()) return fail("--out DIR or --csv FILE is required");
  const auto parsed_profile = mrd::tools::parse_run_profile(profile);
  if (!parsed_profile) return fail("unknown profile '" + profile + "'");
  options.profile = *parsed_profile;
  const auto damper_class = mrd::tools::find_damper_class(damper);
  if (!damper_class) return fail("unknown damper class '" + damper + "' (50kN, 1kN)");
  options.damper = *damper_class;
  options.amplitude = amplitude_mm * 1e-3;
  options.lvdt_noise = noise_um < 0.0 ? -1.0 : noise_um * 1e-6;
  columns.velocity = !no_velocity;
  for (const auto& text : effects) {
    std::string error;
    const auto request = mrd::tools::parse_effect_request(text, error);
    if (!request) return fail(error);
    options.effects.push_back(*request);
  }
  if (const std::string problems = mrd::tools::check(mrd::tools::resolve(options)); !problems.empty()) {
    return fail(problems);
  }

  if (!out_dir.empty()) {
    if (!mrd::cli::prepare_output_directory("mrd-simulate-run", out_dir)) return mrd::cli::kIo;
    csv_path = (std::filesystem::path(out_dir) / "run.csv").string();
    if (manifest.empty()) manifest = (std::filesystem::path(out_dir) / "manifest.json").string();
  }

  const mrd::tools::SimulatedRun run = mrd::tools::simulate_run(options);
  std::ofstream file(csv_path);
  mrd::tools::write_run_csv(file, run, columns);
  file.close();
  if (!file) return fail("cannot write " + csv_path, mrd::cli::kIo);
  if (!manifest.empty()) {
    std::ofstream json(manifest);
    json << mrd::tools::run_manifest_json(run);
    json.close();
    if (!json) return fail("cannot write " + manifest, mrd::cli::kIo);
  }
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
  if (report_residual) {
    std::printf("base model residual: %.4g N RMS; with the carried effects: %.4g N RMS (load-cell noise %.4g N)\n",
                mrd::tools::model_residual(run), mrd::tools::model_residual(run, run.effects),
                run.options.force_noise);
  }
  std::printf("wrote %s%s%s\n", csv_path.c_str(), manifest.empty() ? "" : " and ", manifest.c_str());
  return mrd::cli::kOk;
}
