#include "tools/residual/residual_report.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <toml++/toml.h>

#include "config/effects_config.hpp"
#include "tools/plot/gnuplot.hpp"
#include "tools/json.hpp"
#include "tools/report/force_fit.hpp"
#include "tools/residual/candidate_effects.hpp"
#include "tools/text_format.hpp"
#include "tools/toml_patch.hpp"

namespace mrd::tools {

namespace {

// The screening's spans, at most 12 lines.
std::string screening_summary(const ResidualResult& r) {
  if (!r.screened) {
    std::size_t gaps = 0;
    for (const auto& [run, s] : r.screenings) gaps += s.excluded_samples;
    return gaps == 0 ? std::string("screening: off (--no-screening)\n")
                     : format("screening: off (--no-screening); %zu samples of logging gaps and their settling set aside\n", gaps);
  }
  std::string out;
  std::size_t excluded = 0, lines = 0, total = 0;
  for (const auto& [run, s] : r.screenings) {
    excluded += s.excluded_samples;
    total += s.excluded.size();
    for (const ScreenedSpan& span : s.spans) {
      if (++lines > 12) continue;
      out += format("  %s: %.4f-%.4f s, %s %s%s\n", run.c_str(), span.start_s, span.end_s, span.channel.c_str(),
                    std::string(to_string(span.reason)).c_str(),
                    span.line > 0 ? format(" (line %zu)", span.line).c_str() : "");
    }
  }
  if (lines > 12) out += format("  ... and %zu more spans (the JSON lists them all)\n", lines - 12);
  return format("screening: %zu of %zu samples set aside, in %zu spans%s\n", excluded, total, lines,
                excluded > 0 ? "; errors are on the kept samples" : "") +
         out;
}

// What the robust loss down-weighted against the final model, at most 5 spans.
std::string robust_summary(const ResidualResult& r) {
  const RobustWeights& w = r.robust_after;
  std::string out = format("robust loss: Huber at %g sigma (sigma %.4g N); %.2f%% of the kept samples' weight taken (outside current switches)",
                           r.robust_tuning, w.sigma, 100.0 * w.down_weighted_share);
  out += !r.robust_fit         ? std::string("; the fits are least squares (--robust-fit not asked)\n")
         : r.robust_refits > 0 ? std::string("; the base identified again under the robust loss (--robust-fit)\n")
                               : std::string("; least squares sufficed (--robust-fit: too little weight taken)\n");
  for (const DownWeightedSpan& span : r.down_weighted)
    out += format("  down-weighted most: %s %.4f-%.4f s, %zu samples, peak residual %.4g N\n", span.run.c_str(),
                  span.start_s, span.end_s, span.samples, span.peak_residual);
  return out;
}

// Where the logged current's steps were placed within their rows, when there were any.
std::string switch_timing_summary(const SwitchTiming& t) {
  if (t.steps == 0) return {};
  if (!t.applied)
    return format("switch timing: %zu current steps taken at their rows (timing them within the row would lower the "
                  "RMS %.4g N by no more than fitting noise would)\n", t.steps, t.rms_before);
  return format("switch timing: %zu current steps placed within their rows, %zu from the force after them "
                "(median %.2f of a period before the row); RMS on the kept samples %.4g -> %.4g N with the model refitted\n",
                t.steps, t.estimated, t.median_phase, t.rms_before, t.rms_after);
}

// Each candidate once: the trial of the round it was accepted in, else its last.
std::vector<const CandidateTrial*> final_trials(const ResidualResult& r) {
  std::vector<const CandidateTrial*> out;
  for (const CandidateTrial& t : r.trials) {
    auto it = std::find_if(out.begin(), out.end(), [&](const CandidateTrial* o) { return o->effect == t.effect; });
    if (it == out.end())
      out.push_back(&t);
    else if (!(*it)->accepted())
      *it = &t;
  }
  return out;
}

double range_of(const std::vector<double>& v) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return v.empty() ? 0.0 : *hi - *lo;
}

}  // namespace

std::string residual_summary(const std::vector<record::RecordedRun>& runs, const ResidualResult& r) {
  std::string out;
  for (const record::RecordedRun& run : runs) {
    out += format("%s: %zu samples, %.6g s at %.6g Hz\n", run.name.c_str(), run.size(), run.duration(),
                  run.sample_rate);
    for (const auto& note : run.notes) out += "  note: " + note + "\n";
  }
  for (const auto& note : r.notes) out += "note: " + note + "\n";
  out += r.decimation == 1 ? format("fitted on all %zu samples", r.fit_samples)
                           : format("fitted on %zu samples (every %zuth)", r.fit_samples, r.decimation);
  out += format("; half of the %d blocks of each run held out for validation\n", FitSeriesOptions{}.blocks);
  out += "base model (J-A + Bingham, lumped):\n";
  for (const auto& line : r.base_parameters) out += "  " + line + "\n";
  out += screening_summary(r);
  out += format("before: RMS %.4g N, max %.4g N (validation blocks %.4g N); white-noise floor %.4g N\n", r.before.all,
                r.before.max, r.before.validation, r.noise_floor);
  out += "  residual: " + describe(r.structure_before) + "\n";
  int round = 0;
  for (const CandidateTrial& t : r.trials) {
    if (t.round != round) {
      round = t.round;
      out += format("round %d (validation RMS %.4g N):\n", round, t.validation_before);
    }
    out += format("  %-20s validation %10.4g N  whole run %10.4g N  %s\n", t.effect.c_str(), t.validation_rms,
                  t.rms_after, t.explanation.c_str());
    if (!t.parameters.empty()) {
      out += "  " + std::string(22, ' ') + "fitted:";
      for (const auto& [key, value] : t.parameters) out += format(" %s %.4g", key.c_str(), value);
      out += "\n";
    }
  }
  for (const auto& line : r.revisions) out += "set revision: " + line + "\n";
  for (const DiscoveredTerm& t : r.discovered) {
    out += format("discovered: %-22s %11.4g %-10s %s, validation RMS -%.1f%%%s\n", t.term.c_str(), t.coefficient,
                  t.unit.c_str(), t.interference ? "interference (taken off the measurement, not the model)" : "damper term, added to the model",
                  100.0 * t.validation_gain, t.evidence.weighable() ? ("; " + t.evidence.describe()).c_str() : "");
  }
  for (const AmbiguousGroup& group : r.ambiguous) {
    out += "ambiguous:";
    for (const auto& e : group.members) out += " " + e;
    out += format(" (kept %s; %s)\n", group.members.front().c_str(), group.separating_run.c_str());
  }
  if (r.accepted.empty()) {
    out += "effect: none\n";
  } else {
    out += "effects accepted:";
    for (const auto& e : r.accepted) out += " " + e;
    out += "\n";
    for (const auto& e : r.accepted) {
      out += "  " + e + ":";
      for (const auto& [key, value] : model::find_effect(e)->report(r.final_model.effects))
        out += format(" %s %.4g", key.c_str(), value);
      out += "\n";
    }
  }
  out += robust_summary(r);
  out += switch_timing_summary(r.switch_timing);
  out += format("after: RMS %.4g N, max %.4g N (%.1f%% of before)\n", r.after.all, r.after.max,
                r.before.all > 0.0 ? 100.0 * r.after.all / r.before.all : 0.0);
  out += "unexplained: " + r.unexplained + "\n";
  if (!r.parameters.empty()) {
    out += "final model's base parameters (value, standard deviation; nan: the run does not determine it):\n";
    for (const ParameterEstimate& p : r.parameters)
      out += format("  %-30s %12.4g +- %-10.2g %-5s%s\n", p.name.c_str(), p.value, p.standard_deviation, p.unit.c_str(),
                    determined(p) ? "" : " (not determined by the run)");
  }
  for (const std::string& line : r.unphysical) out += "unphysical: " + line + " (--write-config needs --accept-unphysical)\n";
  out += format("analysed %zu samples in %.2f s (%lld observer passes over the fitting series)\n", r.samples,
                r.seconds, static_cast<long long>(r.evaluations));
  std::string by_step;
  for (const ResidualResult::StepCost& c : r.steps)
    by_step += format("%s%s %.1f s (%lld passes)", by_step.empty() ? "" : ", ", c.step.c_str(), c.seconds,
                      static_cast<long long>(c.evaluations));
  if (!by_step.empty()) out += "  by step: " + by_step + "\n";
  return out;
}

namespace {

// The claim criterion's evidence (step 5) for an effect or a library term.
Json evidence_json(const ClaimEvidence& e) {
  return {{"pieces", e.pieces},
          {"mean_square_fall_N2", e.reduction},
          {"fall_required_N2", e.required},
          {"standard_error_N2", e.standard_error},
          {"t", e.t},
          {"t_required", e.t_required},
          {"z", e.z},
          {"z_required", e.z_required},
          {"significant", e.significant()},
          {"material", e.material()}};
}

// One candidate's entry: its figures and its evidence.
Json candidate_json(const CandidateTrial& t) {
  return {{"effect", t.effect},
          {"rms_after_N", t.rms_after},
          {"validation_rms_N", t.validation_rms},
          {"accepted", t.accepted()},
          {"evidence", evidence_json(t.evidence)}};
}

// What the screening set aside: the count and every span, with the reader's line where it has one.
Json screening_json(const ResidualResult& r) {
  std::size_t excluded = 0;
  Json spans = Json::array();
  for (const auto& [run, s] : r.screenings) {
    excluded += s.excluded_samples;
    for (const ScreenedSpan& span : s.spans) {
      Json entry = {{"run", run},
                    {"start_s", span.start_s},
                    {"end_s", span.end_s},
                    {"channel", span.channel},
                    {"reason", std::string(to_string(span.reason))}};
      if (span.line > 0) entry["line"] = span.line;
      spans.push_back(std::move(entry));
    }
  }
  return {{"excluded_samples", excluded}, {"spans", spans}};
}

Json switch_timing_json(const SwitchTiming& t) {
  return {{"steps", t.steps},
          {"estimated", t.estimated},
          {"applied", t.applied},
          {"median_phase", t.median_phase},
          {"rms_before_N", t.rms_before},
          {"rms_after_N", t.rms_after}};
}

}  // namespace

std::string residual_json(const ResidualResult& r, const ForceFitFigures* fit) {
  Json effect_params = Json::object();
  for (const auto& e : r.accepted) {
    Json params = Json::object();
    for (const auto& [key, value] : model::find_effect(e)->report(r.final_model.effects)) params[key] = value;
    effect_params[e] = params;
  }
  Json candidates = Json::array();
  for (const CandidateTrial* t : final_trials(r)) candidates.push_back(candidate_json(*t));
  Json discovered = Json::array();
  for (const DiscoveredTerm& t : r.discovered) {
    discovered.push_back({{"term", t.term},
                          {"coefficient", t.coefficient},
                          {"unit", t.unit},
                          {"kind", t.interference ? "interference" : "damper"},
                          {"validation_gain", t.validation_gain},
                          {"evidence", evidence_json(t.evidence)}});
  }
  Json down_weighted = Json::array();
  for (const DownWeightedSpan& span : r.down_weighted)
    down_weighted.push_back({{"run", span.run},
                             {"start_s", span.start_s},
                             {"end_s", span.end_s},
                             {"samples", span.samples},
                             {"lost_weight", span.lost_weight},
                             {"peak_residual_N", span.peak_residual}});
  Json parameters = Json::array();
  for (const ParameterEstimate& p : r.parameters)
    parameters.push_back({{"name", p.name}, {"value", p.value}, {"sd", p.standard_deviation}, {"unit", p.unit},
                          {"determined", determined(p)}, {"correlation", p.correlation}});
  Json ambiguous = Json::array(), ambiguity_tests = Json::array();
  for (const AmbiguousGroup& group : r.ambiguous) {
    ambiguous.push_back(group.members);
    ambiguity_tests.push_back(group.separating_run);
  }
  Json out = {{"samples", r.samples},
                    {"rms_before_N", r.before.all},
                    {"noise_floor_N", r.noise_floor},
                    {"fit_before_percent", r.fit_before_percent},
                    {"fit_after_percent", r.fit_after_percent},
                    {"parameters", parameters},
                    {"unphysical", r.unphysical},
                    {"max_before_N", r.before.max},
                    {"effects", r.accepted},
                    {"effect", r.accepted.empty() ? "none" : r.accepted.front()},
                    {"rms_after_N", r.after.all},
                    {"max_after_N", r.after.max},
                    {"effect_params", effect_params},
                    {"candidates", candidates},
                    {"ambiguous", ambiguous},
                    {"ambiguity_tests", ambiguity_tests},
                    {"discovered", discovered},
                    {"screening", screening_json(r)},
                    {"robust",
                     {{"asked", r.robust_fit},
                      {"sigma_N", r.robust_after.sigma},
                      {"down_weighted_share", r.robust_after.down_weighted_share},
                      {"base_refits", r.robust_refits},
                      {"spans", down_weighted}}},
                    {"switch_timing", switch_timing_json(r.switch_timing)},
                    {"set_revisions", r.revisions},
                    {"unexplained", r.unexplained}};
  if (fit != nullptr) out["fit"] = force_fit_json(*fit);
  return json_text(out);
}

std::string updated_config(std::string_view config_text, const ResidualResult& r) {
  try {
    (void)toml::parse(config_text);
  } catch (const toml::parse_error& e) {
    throw std::runtime_error(std::string("the starting config does not parse: ") + std::string(e.description()));
  }
  const model::DamperModel& m = r.final_model;
  toml::table damper;
  const auto set = [&](const char* table, const char* key, double value) {
    if (!damper.contains(table)) damper.insert(table, toml::table{});
    damper[table].as_table()->insert_or_assign(key, value);
  };
  set("jiles_atherton", "Ms", m.jiles_atherton.Ms);
  set("jiles_atherton", "a", m.jiles_atherton.a);
  set("jiles_atherton", "alpha", m.jiles_atherton.alpha);
  set("jiles_atherton", "k", m.jiles_atherton.k);
  set("jiles_atherton", "c", m.jiles_atherton.c);
  set("circuit", "turns", m.circuit.turns);
  set("circuit", "effective_length", m.circuit.effective_length);
  set("fluid", "viscosity", m.fluid.viscosity);
  set("fluid", "volume_fraction", m.fluid.volume_fraction);
  set("fluid", "particle_diameter", m.fluid.particle_diameter);
  set("fluid", "particle_saturation", m.fluid.particle_saturation);
  set("fluid", "field_exponent", m.fluid.field_exponent);
  set("fluid", "flow_index", m.fluid.flow_index);
  set("fluid", "saturation_induction", m.fluid.saturation_induction);
  set("fluid", "saturation_shape", m.fluid.saturation_shape);
  set("geometry", "piston_area", m.geometry.piston_area);
  set("geometry", "pole_length", m.geometry.pole_length);
  set("geometry", "gap", m.geometry.gap);
  set("geometry", "piston_diameter", m.geometry.piston_diameter);
  set("geometry", "sign_velocity_scale", m.geometry.sign_velocity_scale);
  set("geometry", "sign_shape", m.geometry.sign_shape);
  set("geometry", "seal_friction", m.geometry.seal_friction);
  toml::table effects = toml::parse(config::effects_toml(m.effects));
  damper.insert_or_assign("effects", *effects["damper"]["effects"].as_table());
  toml::table values;
  values.insert("damper", std::move(damper));
  round_floats(values);
  // Values patched in place: the starting config's order and comments stay (tools/toml_patch).
  std::string header = "# Written by mrd-residual: the damper fitted to the run";
  if (!r.accepted.empty()) {
    header += ", with";
    for (const auto& e : r.accepted) header += ' ' + e;
  }
  header += ". Every other key is the starting config's.\n";
  std::string text = patch_toml(config_text, values);
  if (text.rfind("# Written by mrd-residual:", 0) == 0) text.erase(0, text.find('\n') + 1);
  return header + text;
}

std::string plot_residual(const FitSeries& s, const ResidualResult& r, const std::string& name,
                          const std::string& directory) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec) return "cannot create " + directory + ": " + ec.message();
  const std::size_t stride = std::max<std::size_t>(1, s.size() / 40000);
  const std::string data = (fs::path(directory) / "residual.dat").string();
  const std::vector<double> time = series_time(s);
  {
    std::ofstream out(data);
    for (std::size_t i = 0; i < s.size(); i += stride) {
      out << time[i] << ' ' << 1e3 * s.displacement[i] << ' ' << 1e3 * s.velocity[i]
          << ' ' << s.force[i] << ' ' << r.predicted_before[i] << ' ' << r.predicted_after[i] << ' '
          << s.force[i] - r.predicted_before[i] << ' ' << s.force[i] - r.predicted_after[i] << ' '
          << (s.role[i] == SampleRole::kExcluded ? 1 : 0) << '\n';
    }
    if (!out) return "cannot write " + data;
  }
  std::string after = "after: none";
  if (!r.accepted.empty()) {
    after = "after: +";
    for (const auto& e : r.accepted) after += " " + e;
  }
  const std::string figures = format("RMS %.4g N -> %.4g N (range %.4g N)", r.before.all, r.after.all, range_of(s.force));
  auto png = [&](const char* file) { return (fs::path(directory) / file).string(); };
  const plot::DataFile file{data};
  const plot::Axis residual_axis{"measured - predicted", "N"};
  // residual.dat: time, displacement, velocity, measured, base, after, their residuals, set aside (1).
  const auto set_aside = [](int x, int y) {
    return plot::Series{"set aside by the screening", plot::column(x), plot::column(y).where(9, 0.5),
                        plot::rings(plot::colour::kOrange), plot::Layer::note};
  };
  const auto against = [&](plot::Axis x_axis, int x) {
    return plot::Panel{.title = "against " + x_axis.label,
                       .x = std::move(x_axis),
                       .y = residual_axis,
                       .data = file,
                       .series = {{"base", plot::column(x), plot::column(7), plot::points(plot::colour::kBlue)},
                                  {"after", plot::column(x), plot::column(8), plot::points(plot::colour::kRed)}}};
  };
  const plot::Figure force_displacement{
      .output = png("residual_force_displacement.png"),
      .title = name + ": force against displacement, " + figures,
      .panels = {{.x = {"displacement", "mm"},
                  .y = {"force", "N"},
                  .data = file,
                  .series = {{"measured", plot::column(2), plot::column(4), plot::points(plot::colour::kGrey),
                              plot::Layer::measured},
                             {"base model", plot::column(2), plot::column(5), plot::points(plot::colour::kBlue)},
                             {after, plot::column(2), plot::column(6), plot::points(plot::colour::kRed)},
                             set_aside(2, 4)}}}};
  const plot::Figure residual_time{
      .output = png("residual_time.png"),
      .title = name + ": residual against time, " + figures,
      .panels = {{.x = {s.run_starts.size() > 1 ? "time, each run after the one before" : "time", "s"},
                  .y = residual_axis,
                  .data = file,
                  .series = {{"base model", plot::column(1), plot::column(7), plot::lines(plot::colour::kBlue)},
                             {after, plot::column(1), plot::column(8), plot::lines(plot::colour::kRed)},
                             set_aside(1, 8)},
                  .markers = run_boundaries(time, s.run_starts, s.run_names)}}};
  const plot::Figure phase{.output = png("residual_phase.png"),
                           .title = name + ": residual against the motion",
                           .width = 1200,
                           .height = 500,
                           .columns = 2,
                           .panels = {against({"displacement", "mm"}, 2), against({"velocity", "mm/s"}, 3)}};
  return plot::draw({force_displacement, residual_time, phase});
}

ForceFitTraces residual_traces(const std::vector<record::RecordedRun>& runs, const FitSeries& s,
                               const ResidualResult& r) {
  std::string effects;
  for (const auto& e : r.accepted) effects += (effects.empty() ? "" : ", ") + e;
  ForceFitTraces traces;
  traces.name = runs.size() == 1 ? runs.front().name : std::to_string(runs.size()) + " runs";
  traces.time = series_time(s);
  if (s.run_starts.size() > 1) {
    traces.run_starts = s.run_starts;
    traces.run_names = s.run_names;
  }
  traces.displacement = s.displacement;
  traces.velocity = s.velocity;
  traces.measured = s.force;
  traces.predicted = r.predicted_after;
  traces.predicted_label = effects.empty() ? "final model (= base)" : "final model (+ " + effects + ")";
  traces.baseline = r.predicted_before;
  traces.baseline_label = "base model";
  if (r.screened) {
    traces.keep.resize(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) traces.keep[i] = s.role[i] != SampleRole::kExcluded;
  }
  return traces;
}

namespace {

// The final model's parameters with their deviations and correlations, those flagged, and the
// accepted effects' own.
void add_parameter_section(HtmlReport& report, const ResidualResult& r) {
  report.heading("Parameters");
  std::vector<HtmlReport::Parameter> rows;
  for (std::size_t i = 0; i < r.parameters.size(); ++i) {
    const ParameterEstimate& p = r.parameters[i];
    const std::string key = "parameters." + std::to_string(i);
    rows.push_back({p.name, p.unit, p.value, p.standard_deviation, key + ".value", key + ".sd"});
  }
  report.parameters("Final model: standard deviations from sigma^2 (J^T J)^-1 at the fit (central differences over "
                    "the fitting series)", rows);
  std::vector<std::string> names;
  std::vector<std::vector<double>> correlation;
  for (const ParameterEstimate& p : r.parameters) {
    names.push_back(p.name);
    correlation.push_back(p.correlation);
  }
  report.correlation_matrix("Correlation of the final model's parameter estimates (the JSON's parameters[].correlation)",
                            names, correlation);
  std::vector<std::vector<std::string>> flagged;
  for (const ParameterEstimate& p : r.parameters)
    if (!determined(p))
      flagged.push_back({p.name, p.shape ? "not determined by the run (standard deviation nan or above 1)"
                                         : "not determined by the run (standard deviation nan or above its value)"});
  for (const std::string& line : r.unphysical) flagged.push_back({line, "unphysical: --write-config needs --accept-unphysical"});
  if (!flagged.empty()) report.table("Flagged parameters", {"parameter", "why"}, flagged);
  std::vector<std::vector<std::string>> effect_rows;
  for (const auto& e : r.accepted)
    for (const auto& [key, value] : model::find_effect(e)->report(r.final_model.effects))
      effect_rows.push_back({e, key, format("%.6g", value)});
  report.table("Accepted effects' parameters", {"effect", "parameter", "value"}, effect_rows);
}

}  // namespace

std::string write_residual_report(const std::vector<record::RecordedRun>& runs, const FitSeries& s,
                                  const ResidualResult& r, const ForceFitTraces& traces, const Provenance& provenance,
                                  const std::string& directory) {
  const std::string name = runs.size() == 1 ? runs.front().name : std::to_string(runs.size()) + " runs";
  HtmlReport report("mrd-residual: " + name, directory);
  std::string effects = "none";
  if (!r.accepted.empty()) {
    effects.clear();
    for (const auto& e : r.accepted) effects += (effects.empty() ? "" : ", ") + e;
  }
  report.paragraph(format("%zu samples; the J-A + Bingham base model fitted, then candidate effects tried on half of "
                          "the run and validated on the other half. Accepted: %s. Unexplained: %s",
                          r.samples, effects.c_str(), r.unexplained.c_str()));
  report.figures("Before and after (as the JSON)",
                 {{"RMS error, base model", "rms_before_N", r.before.all, "N"},
                  {"max error, base model", "max_before_N", r.before.max, "N"},
                  {"fit, base model", "fit_before_percent", r.fit_before_percent, "%"},
                  {"RMS error, final model", "rms_after_N", r.after.all, "N"},
                  {"max error, final model", "max_after_N", r.after.max, "N"},
                  {"fit, final model", "fit_after_percent", r.fit_after_percent, "%"}});
  add_force_fit(report, traces);

  add_parameter_section(report, r);

  report.heading("Effects and terms tried");
  std::vector<std::vector<std::string>> trials;
  for (const CandidateTrial* t : final_trials(r)) {
    trials.push_back({t->effect, std::to_string(t->round), format("%.6g", t->validation_before),
                      format("%.6g", t->validation_rms), format("%.6g", t->rms_after), t->accepted() ? "accepted" : "rejected",
                      t->explanation});
  }
  report.table(format("Candidates (each at its last round; accepted when the paired held-out blocks show the fall "
                      "significant and at least a share of what the model leaves above the noise floor of %.4g N)",
                      r.noise_floor),
               {"effect", "round", "validation before [N]", "validation with it [N]", "whole run [N]", "verdict", "why"},
               trials);
  std::vector<std::vector<std::string>> terms;
  for (const DiscoveredTerm& t : r.discovered) {
    terms.push_back({t.term, format("%.6g", t.coefficient), t.unit, t.interference ? "interference" : "damper",
                     format("%.1f %%", 100.0 * t.validation_gain), t.evidence.describe()});
  }
  report.table("Library terms accepted by the regression of what the effects left (each by the claim criterion, "
               "against the terms before it)",
               {"term", "coefficient", "unit", "kind", "validation RMS gain", "evidence"}, terms);
  std::vector<std::vector<std::string>> groups;
  for (const AmbiguousGroup& group : r.ambiguous) {
    std::string members;
    for (const auto& e : group.members) members += (members.empty() ? "" : ", ") + e;
    groups.push_back({members, group.separating_run});
  }
  report.table("Effects the run cannot tell apart (the first is kept)", {"effects", "the run that would separate them"},
               groups);

  report.heading("Screening");
  std::vector<std::vector<std::string>> spans;
  for (const auto& [run, sc] : r.screenings)
    for (const ScreenedSpan& span : sc.spans)
      spans.push_back({run, format("%.4f", span.start_s), format("%.4f", span.end_s), span.channel,
                       std::string(to_string(span.reason))});
  report.paragraph(r.screened ? format("%zu samples set aside; every error and fit above is on the kept samples.",
                                       s.excluded_samples())
                              : std::string("Screening was off (--no-screening)."));
  report.table("Spans set aside", {"run", "from [s]", "to [s]", "channel", "reason"}, spans);
  report.provenance(provenance);
  return report.write();
}

}  // namespace mrd::tools
