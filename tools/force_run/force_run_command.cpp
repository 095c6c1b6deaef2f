#include "tools/force_run/force_run_command.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/cli/exit_code.hpp"
#include "tools/force_run/controller_identification.hpp"
#include "tools/force_run/force_run.hpp"
#include "tools/plot/gnuplot.hpp"
#include "tools/json.hpp"

namespace mrd::tools {

namespace {

using Arguments = ForceRunArguments;


struct CaseRun {
  std::string name;
  ForceRunResult result;
  std::vector<std::string> notes;
};

Json to_json(const CaseRun& run, std::string_view profile_name, const DemandProfile& profile,
                         double coil_lag_ms) {
  Json j;
  j["case"] = run.name;
  j["profile"] = std::string(profile_name);
  j["profile_description"] = profile.description;
  j["coil_lag_ms"] = coil_lag_ms;
  j["yield_drift_pct"] = 100.0 * (run.result.plant_yield_factor.empty() ? 0.0 : 1.0 - run.result.plant_yield_factor.back());
  j["desired_rms_N"] = run.result.desired_rms;
  j["reachable_fraction"] = run.result.reachable_fraction;
  j["strategies"] = Json::array();
  for (const auto& s : run.result.strategies) {
    j["strategies"].push_back({{"name", std::string(strategy_name(s.kind))},
                               {"rms_error_N", s.rms_error},
                               {"max_error_N", s.max_error},
                               {"rms_error_reachable_N", s.rms_error_reachable}});
    if (!s.yield_scale.empty()) j["load_cell_final_scale"] = s.yield_scale.back();
  }
  j["notes"] = run.notes;
  return j;
}

bool write_trace(const std::string& path, const DemandProfile& profile, const ForceRunResult& r) {
  std::ofstream out(path);
  out << "time_s,displacement_mm,velocity_mm_s,desired_N";
  for (const auto& s : r.strategies) {
    const std::string name(strategy_name(s.kind));
    out << ',' << name << "_N," << name << "_A";
    if (!s.yield_scale.empty()) out << ',' << name << "_scale";
  }
  if (!r.plant_yield_factor.empty()) out << ",plant_yield_factor";
  out << '\n';
  for (std::size_t i = 0; i < profile.size(); ++i) {
    out << static_cast<double>(i) * profile.sample_period << ',' << profile.displacement[i] * 1e3 << ','
        << profile.velocity[i] * 1e3 << ',' << profile.force[i];
    for (const auto& s : r.strategies) {
      out << ',' << s.delivered[i] << ',' << s.current[i];
      if (!s.yield_scale.empty()) out << ',' << s.yield_scale[i];
    }
    if (!r.plant_yield_factor.empty()) out << ',' << r.plant_yield_factor[i];
    out << '\n';
  }
  return static_cast<bool>(out);
}


// The trace's forces are in N, drawn in kN.
plot::Column in_kN(plot::Column c) { return c.times(1e-3); }

// Four panels, one a strategy, each with the desired force under the delivered one: against time
// over [from_s, to_s], or against velocity with the samples of that span.
plot::Figure strategies_figure(const std::string& csv, const std::string& png, const std::string& title,
                               bool against_time, double from_s, double to_s) {
  static const char* const kNames[] = {"clipped_on_off", "inverse_bingham", "inverse_ja", "inverse_ja_lag"};
  plot::Figure figure{.output = png, .title = title, .width = 1200, .height = 850, .columns = 2};
  const plot::Column x = against_time ? plot::column(1) : plot::column(3).where(1, from_s, to_s);
  const plot::Axis x_axis = against_time ? plot::Axis{"time", "s", plot::Range{from_s, to_s}} : plot::Axis{"velocity", "mm/s"};
  const plot::Style desired = against_time ? plot::lines(plot::colour::kGrey, 2.0) : plot::dots(plot::colour::kGrey);
  const plot::Style delivered = against_time ? plot::lines(plot::colour::kBlue) : plot::dots(plot::colour::kBlue);
  for (int k = 0; k < 4; ++k) {
    const int column = 5 + 2 * k;  // write_trace: each strategy's force, then its current
    figure.panels.push_back({.title = kNames[k],
                             .x = x_axis,
                             .y = {"force", "kN"},
                             .data = {csv, true},
                             .series = {{"desired", x, in_kN(plot::column(4)), desired},
                                        {"delivered", x, in_kN(plot::column(column)), delivered, plot::Layer::measured}}});
  }
  return figure;
}

// With --load-cell: inverse_ja's error and inverse_ja_load_cell's over the whole run, and the
// correction's scale against the plant's drifting yield factor (columns as write_trace lays them
// out: inverse_ja is the third strategy, inverse_ja_load_cell the fifth with its scale after).
plot::Figure load_cell_figure(const std::string& csv, const std::string& png, const std::string& title, bool drifting) {
  plot::Panel scale{.title = "the model yield force scale",
                    .x = {"time", "s"},
                    .y = {"yield scale", "-"},
                    .data = {csv, true},
                    .series = {{"load-cell correction", plot::column(1), plot::column(15),
                                plot::lines(plot::colour::kBlue, 2.0)}}};
  if (drifting) {
    scale.series.push_back({"plant yield stress / its undrifted value", plot::column(1), plot::column(16),
                            plot::lines(plot::colour::kGrey, 2.0)});
  }
  return {.output = png,
          .title = title,
          .width = 1200,
          .height = 850,
          .panels = {{.title = "force error",
                      .x = {"time", "s"},
                      .y = {"delivered - desired", "kN"},
                      .data = {csv, true},
                      .series = {{"inverse_ja", plot::column(1), in_kN(plot::column(9).minus(4)),
                                  plot::lines(plot::colour::kRed)},
                                 {"inverse_ja_load_cell", plot::column(1), in_kN(plot::column(13).minus(4)),
                                  plot::lines(plot::colour::kBlue)}}},
                     std::move(scale)}};
}

// The simulated damper and its driver, which every case runs on.
struct Plant {
  mrd::model::DamperModel model;
  mrd::model::CompensatorLimits limits;
};

// Nullopt, with the problems on stderr, when the plant is not valid.
std::optional<Plant> make_plant(const Arguments& a) {
  Plant plant{with_coil_lag({}, a.coil_lag_ms * 1e-3), {}};
  plant.limits.min_current = -plant.limits.max_current;  // bipolar: a unipolar driver cannot clear remanence
  if (const auto report = mrd::model::validate(plant.model); !report.ok()) {
    std::fprintf(stderr, "mrd-force-run: invalid plant\n%s", report.to_string().c_str());
    return std::nullopt;
  }
  return plant;
}

DemandProfile make_profile(const Arguments& a, const Plant& plant) {
  const double dt = 1e-3;
  if (a.profile_kind() == ProfileKind::kRandom) return random_demand(a.duration, dt, a.seed);
  StructureDemandOptions structure;
  structure.weights.force_weight = a.lqr_force_weight;
  structure.ground.peak_acceleration = a.pga_g * 9.81;
  return structure_demand(a.duration, dt, a.seed, plant.model, plant.limits.max_current, structure);
}

// The controller's model for one case, with the notes that say how it was made.
mrd::model::DamperModel controller_for(const std::string& name, const Arguments& a, const Plant& plant,
                                       std::vector<std::string>& notes) {
  if (name == "matched") return plant.model;
  if (name == "perturbed") {
    notes.push_back("every J-A and Bingham parameter off by 10-20 % (docs/FORCE-CONTROL.md)");
    return perturbed_model(plant.model);
  }
  ControllerIdentificationOptions id;
  id.seed = a.seed;
  auto identified =
      identify_controller(plant.model, perturbed_model(plant.model), plant.limits, id);
  notes = std::move(identified.notes);
  return std::move(identified.model);
}

std::vector<CaseRun> run_cases(const Arguments& a, const Plant& plant, const DemandProfile& profile) {
  const std::vector<std::string> cases =
      a.case_choice == "all" ? std::vector<std::string>{"matched", "identified", "perturbed"}
                             : std::vector<std::string>{a.case_choice};
  ForceRunOptions options;
  options.plant = plant.model;
  options.limits = plant.limits;
  options.force_noise_rms = a.force_noise;
  options.seed = static_cast<unsigned>(a.seed);
  options.yield_drift = a.drift_pct / 100.0;
  options.load_cell = a.load_cell;
  options.load_cell_settings.time_constant = a.load_cell_tau;
  std::vector<CaseRun> runs;
  for (const std::string& name : cases) {
    CaseRun run;
    run.name = name;
    options.controller = controller_for(name, a, plant, run.notes);
    run.result = run_force_tracking(profile, options);
    runs.push_back(std::move(run));
  }
  return runs;
}

// "2.50 ms": the option cut to four characters, as the summary and the plot titles show it.
std::string coil_lag_text(double coil_lag_ms) { return std::to_string(coil_lag_ms).substr(0, 4) + " ms"; }

void print_summary(const Arguments& a, const Plant& plant, const DemandProfile& profile,
                   const std::vector<CaseRun>& runs) {
  std::printf("mrd: force tracking, %s; %.0f s at 1 kHz, plant coil lag %s, driver -%.1f..%.1f A at %.0f A/s\n",
              profile.description.c_str(), a.duration, a.coil_lag_ms > 0.0 ? coil_lag_text(a.coil_lag_ms).c_str() : "none",
              plant.limits.max_current, plant.limits.max_current, plant.limits.slew_rate);
  for (const auto& run : runs) {
    std::printf("\ncase %s: desired %.0f N RMS, %.1f %% of it reachable\n", run.name.c_str(), run.result.desired_rms,
                100.0 * run.result.reachable_fraction);
    for (const auto& note : run.notes) std::printf("  %s\n", note.c_str());
    std::printf("  %-16s %14s %14s %22s\n", "strategy", "RMS error [N]", "max error [N]", "RMS where reachable [N]");
    for (const auto& s : run.result.strategies) {
      std::printf("  %-16s %14.0f %14.0f %22.0f\n", std::string(strategy_name(s.kind)).c_str(), s.rms_error,
                  s.max_error, s.rms_error_reachable);
    }
  }
}

// --json: the judged case (identified when it ran) at the top, every case under "runs".
bool write_json(const Arguments& a, const DemandProfile& profile, const std::vector<CaseRun>& runs) {
  std::size_t top = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (runs[i].name == "identified") top = i;
  }
  Json j = to_json(runs[top], a.profile_choice, profile, a.coil_lag_ms);
  j["runs"] = Json::array();
  for (const auto& run : runs) j["runs"].push_back(to_json(run, a.profile_choice, profile, a.coil_lag_ms));
  std::ofstream out(a.json_path);
  out << json_text(j);
  if (!out) {
    std::fprintf(stderr, "mrd-force-run: cannot write %s\n", a.json_path.c_str());
    return false;
  }
  std::printf("\nwrote %s\n", a.json_path.c_str());
  return true;
}

// A figure that cannot be drawn is reported and skipped: the CSV it comes from is written.
void draw_figure(const plot::Figure& figure) {
  const std::string error = plot::draw({figure});
  if (error.empty()) {
    std::printf("wrote %s\n", figure.output.c_str());
  } else {
    std::fprintf(stderr, "mrd-force-run: no plot: %s\n", error.c_str());
  }
}

// One case's PNGs beside its trace STEM.csv.
void draw_case(const Arguments& a, const CaseRun& run, const std::string& stem) {
  const std::string title = run.name + " model, " + std::string(profile_name(a.profile_kind())) +
                            " profile" + (a.coil_lag_ms > 0.0 ? ", coil lag " + coil_lag_text(a.coil_lag_ms) : "");
  const double from = std::min(2.0, a.duration - 1.0), to = std::min(from + 6.0, a.duration);
  if (a.load_cell) {
    const std::string drift_title = title + ", yield drift " + std::to_string(a.drift_pct).substr(0, 4) + " %";
    draw_figure(load_cell_figure(stem + ".csv", stem + "_load_cell.png", drift_title, a.drift_pct > 0.0));
  }
  for (const bool against_time : {true, false}) {
    const std::string png = stem + (against_time ? "_force_time.png" : "_force_velocity.png");
    draw_figure(strategies_figure(stem + ".csv", png, title, against_time, from, to));
  }
}

// --out: each case's trace, and its plots unless --no-plot.
bool write_out_dir(const Arguments& a, const DemandProfile& profile, const std::vector<CaseRun>& runs) {
  std::error_code ec;
  std::filesystem::create_directories(a.out_dir, ec);
  if (ec) {
    std::fprintf(stderr, "mrd-force-run: cannot create %s: %s\n", a.out_dir.c_str(), ec.message().c_str());
    return false;
  }
  // A drifting plant's files apart from the steady plant's.
  const std::string drift =
      a.drift_pct > 0.0 ? "_drift" + std::to_string(static_cast<int>(std::lround(a.drift_pct))) : "";
  for (const auto& run : runs) {
    const std::string stem =
        a.out_dir + "/force_run_" + std::string(profile_name(a.profile_kind())) + "_" + run.name + drift;
    if (!write_trace(stem + ".csv", profile, run.result)) {
      std::fprintf(stderr, "mrd-force-run: cannot write %s.csv\n", stem.c_str());
      return false;
    }
    std::printf("wrote %s.csv\n", stem.c_str());
    if (!a.no_plot) draw_case(a, run, stem);
  }
  return true;
}

}  // namespace

int run_force_comparison(const ForceRunArguments& args) {
  const auto plant = make_plant(args);
  if (!plant) return mrd::cli::kUsage;
  const DemandProfile profile = make_profile(args, *plant);
  const std::vector<CaseRun> runs = run_cases(args, *plant, profile);
  print_summary(args, *plant, profile, runs);
  if (!args.json_path.empty() && !write_json(args, profile, runs)) return mrd::cli::kIo;
  if (!args.out_dir.empty() && !write_out_dir(args, profile, runs)) return mrd::cli::kIo;
  return mrd::cli::kOk;
}

}  // namespace mrd::tools
