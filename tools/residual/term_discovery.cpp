#include "tools/residual/term_discovery.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "model/effects/learned_terms.hpp"
#include "tools/residual/model_fit.hpp"
#include "tools/signal/zero_phase_velocity.hpp"
#include "tools/text_format.hpp"

namespace mrd::tools {

namespace {

// Mains lines and their harmonics: each a sine and a cosine column, reported as one amplitude.
struct MainsLine {
  std::string name;
  double frequency;  // [Hz]
};

std::vector<MainsLine> mains_lines(double sample_rate) {
  std::vector<MainsLine> lines;
  for (const double mains : {50.0, 60.0}) {
    for (int harmonic = 1; harmonic <= 3; ++harmonic) {
      const double f = mains * harmonic;
      if (f > 0.4 * sample_rate) continue;  // not resolved at this rate
      lines.push_back({format("line_%.0fHz", mains) + (harmonic > 1 ? format("_h%d", harmonic) : ""), f});
    }
  }
  return lines;
}

// The acceleration from the velocity, zero-phase (the same derivative the velocity had), per run.
std::vector<double> zero_phase_acceleration(const FitSeries& s) {
  std::vector<double> a(s.size(), 0.0);
  for (std::size_t r = 0; r < s.run_starts.size(); ++r) {
    const std::size_t begin = s.run_starts[r];
    const std::size_t end = r + 1 < s.run_starts.size() ? s.run_starts[r + 1] : s.size();
    if (end - begin < 8) continue;
    const double rate = 1.0 / s.run_periods[r];
    const std::vector<double> x(s.displacement.begin() + static_cast<std::ptrdiff_t>(begin),
                                s.displacement.begin() + static_cast<std::ptrdiff_t>(end));
    const std::span<const double> v(s.velocity.data() + begin, end - begin);
    const double cutoff = motion_velocity_cutoff(x, rate);
    const std::vector<double> run_a =
        s.timing_of_run(r) == record::RunTiming::kRecorded
            ? zero_phase_velocity_at_times(v, std::span<const double>(s.time.data() + begin, end - begin), rate, cutoff, {})
            : zero_phase_velocity(v, rate, cutoff);
    std::copy(run_a.begin(), run_a.end(), a.begin() + static_cast<std::ptrdiff_t>(begin));
  }
  return a;
}

// One library entry: its columns in the regression and how it is reported.
struct LibraryTerm {
  std::string name;
  std::string unit;
  int sign = 0;        // +1: the coefficient must be >= 0
  bool interference = false;
  int first_column = 0;
  int columns = 1;     // 2 for a mains line (sine, cosine)
};

struct Library {
  std::vector<LibraryTerm> terms;
  std::vector<MainsLine> lines;
  int columns = 0;
};

// Columns 0 and 1 are the model's own linear terms, in every fit (the force scale on the predicted
// force, an extra viscous coefficient along the fluid's shape u(v): v for Bingham): a term that joins can take back what the base fit had absorbed of
// it (a field-dependent viscosity partly hides in c0), instead of fitting only what is left.
constexpr int kBaseColumns = 2;

Library make_library(double sample_rate) {
  Library lib;
  lib.columns = kBaseColumns;
  for (const model::LearnedTermInfo& t : model::kLearnedTerms) {
    lib.terms.push_back({std::string(t.name), std::string(t.unit), t.sign, false, lib.columns, 1});
    ++lib.columns;
  }
  lib.lines = mains_lines(sample_rate);
  for (const MainsLine& line : lib.lines) {
    lib.terms.push_back({line.name, "N", 0, true, lib.columns, 2});
    lib.columns += 2;
  }
  return lib;
}

// Each column's value at sample i.
void fill_row(const Library& lib, const FitSeries& s, const std::vector<double>& predicted, const std::vector<double>& B,
              const std::vector<double>& a, const model::BinghamDamper& fluid, double time, std::size_t i,
              Eigen::VectorXd& row) {
  row[0] = predicted[i];
  // u(v), the viscous force per unit c0: what apply_linear_terms' extra coefficient multiplies.
  const double c0 = fluid.viscous_coefficient();
  row[1] = c0 > 0.0 ? fluid.viscous_force(s.velocity[i]) / c0 : s.velocity[i];
  const model::ForceState state{.displacement = s.displacement[i],
                                .velocity = s.velocity[i],
                                .acceleration = a[i],
                                .coil_current = s.current[i],
                                .B = B[i]};
  for (std::size_t k = 0; k < model::kLearnedTermCount; ++k)
    row[kBaseColumns + static_cast<Eigen::Index>(k)] =
        model::learned_term_value(static_cast<model::LearnedTerm>(k), state);
  Eigen::Index c = kBaseColumns + static_cast<Eigen::Index>(model::kLearnedTermCount);
  for (const MainsLine& line : lib.lines) {
    const double phase = 2.0 * std::numbers::pi * line.frequency * time;
    row[c++] = std::sin(phase);
    row[c++] = std::cos(phase);
  }
}

// The regression's sufficient statistics, on the fitting and on the validation samples.
struct Moments {
  Eigen::MatrixXd gram;  // X' X
  Eigen::VectorXd cross;  // X' r
  double energy = 0.0;   // r' r
  std::size_t count = 0;
};

struct SubsetFit {
  Eigen::VectorXd coefficients;  // over the subset's columns
  double validation_rms = 0.0;
  bool physical = true;
};

std::vector<int> columns_of(const Library& lib, const std::vector<std::size_t>& subset) {
  std::vector<int> cols{0, 1};
  for (const std::size_t t : subset)
    for (int c = 0; c < lib.terms[t].columns; ++c) cols.push_back(lib.terms[t].first_column + c);
  return cols;
}

SubsetFit fit_subset(const Library& lib, const std::vector<std::size_t>& subset, const Moments& fit,
                     const Moments& validation, const Eigen::VectorXd& scale, double viscous_coefficient) {
  const std::vector<int> cols = columns_of(lib, subset);
  const auto n = static_cast<Eigen::Index>(cols.size());
  Eigen::MatrixXd g(n, n), gv(n, n);
  Eigen::VectorXd b(n), bv(n);
  for (Eigen::Index r = 0; r < n; ++r) {
    b[r] = fit.cross[cols[r]] / scale[cols[r]];
    bv[r] = validation.cross[cols[r]] / scale[cols[r]];
    for (Eigen::Index c = 0; c < n; ++c) {
      g(r, c) = fit.gram(cols[r], cols[c]) / (scale[cols[r]] * scale[cols[c]]);
      gv(r, c) = validation.gram(cols[r], cols[c]) / (scale[cols[r]] * scale[cols[c]]);
    }
  }
  for (Eigen::Index r = 0; r < n; ++r) g(r, r) += 1e-12 * (g(r, r) + 1.0);
  SubsetFit out;
  const Eigen::VectorXd scaled = g.ldlt().solve(b);
  const double sse = std::max(validation.energy - 2.0 * scaled.dot(bv) + scaled.dot(gv * scaled), 0.0);
  out.validation_rms = std::sqrt(sse / static_cast<double>(std::max<std::size_t>(validation.count, 1)));
  out.coefficients.resize(n);
  for (Eigen::Index r = 0; r < n; ++r) out.coefficients[r] = scaled[r] / scale[cols[r]];
  Eigen::Index c = kBaseColumns;
  // A negative force scale, or a negative viscosity once the extra viscous term is added.
  if (out.coefficients[0] < 0.0 || out.coefficients[0] * viscous_coefficient + out.coefficients[1] < 0.0)
    out.physical = false;
  for (const std::size_t t : subset) {
    if (lib.terms[t].sign > 0 && out.coefficients[c] < 0.0) out.physical = false;
    c += lib.terms[t].columns;
  }
  return out;
}

// Sample i's time from its run's start: its recorded time on a run kept at the times its
// samples were taken unevenly, else its index in periods.
double time_of(const FitSeries& s, std::size_t i, std::size_t& run) {
  while (run + 1 < s.run_starts.size() && i >= s.run_starts[run + 1]) ++run;
  if (s.timing_of_run(run) == record::RunTiming::kRecorded) return s.time[i] - s.time[s.run_starts[run]];
  return static_cast<double>(i - s.run_starts[run]) * s.run_periods[run];
}

}  // namespace

std::vector<std::string> term_library(double sample_rate) {
  std::vector<std::string> names;
  for (const LibraryTerm& t : make_library(sample_rate).terms) names.push_back(t.name);
  return names;
}

double carried_coefficient(const model::DamperModel& model, const std::string& term) {
  const auto& learned = model.effects.get<model::LearnedTermsEffect>();
  for (std::size_t k = 0; k < model::kLearnedTermCount; ++k)
    if (model::kLearnedTerms[k].name == term) return learned.coefficients[k];
  return 0.0;
}

model::DamperModel without_terms(model::DamperModel model) {
  model.effects.get<model::LearnedTermsEffect>() = {};
  return model;
}

void TermDiscovery::add_to(model::DamperModel& model) const {
  if (terms.empty()) return;
  LinearTerms base;
  base.force_scale = force_scale;
  base.extra_viscous = extra_viscous;
  model = apply_linear_terms(model, base);
  auto& learned = model.effects.get<model::LearnedTermsEffect>();
  for (const DiscoveredTerm& t : terms) {
    if (t.interference) continue;
    for (std::size_t k = 0; k < model::kLearnedTermCount; ++k)
      if (model::kLearnedTerms[k].name == t.term) learned.coefficients[k] += t.coefficient;
    learned.enabled = true;
  }
}

namespace {

// The library's columns over the kept samples of a series (the screening's excluded ones are
// in no sum), given the model's force, its induction and the acceleration per sample.
struct LibraryRows {
  const Library& lib;
  const FitSeries& s;
  const std::vector<double>& predicted;
  const std::vector<double>& B;
  const std::vector<double>& a;
  const model::BinghamDamper& fluid;

  // `use(i, row)` for each kept sample i.
  template <typename Use>
  void each_kept(Use use) const {
    Eigen::VectorXd row(lib.columns);
    std::size_t run = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const double t = time_of(s, i, run);
      if (s.role[i] == SampleRole::kExcluded) continue;
      fill_row(lib, s, predicted, B, a, fluid, t, i, row);
      use(i, row);
    }
  }
};

// The library's moments over the fitting samples (moments[0]) and the validation samples (moments[1]).
void accumulate_moments(const LibraryRows& rows, Moments (&moments)[2]) {
  for (Moments& m : moments) {
    m.gram = Eigen::MatrixXd::Zero(rows.lib.columns, rows.lib.columns);
    m.cross = Eigen::VectorXd::Zero(rows.lib.columns);
  }
  rows.each_kept([&](std::size_t i, const Eigen::VectorXd& row) {
    const double r = rows.s.force[i];
    Moments& m = moments[static_cast<std::size_t>(rows.s.role[i])];
    m.gram.selfadjointView<Eigen::Lower>().rankUpdate(row);
    m.cross += r * row;
    m.energy += r * r;
    ++m.count;
  });
  for (Moments& m : moments) m.gram = m.gram.selfadjointView<Eigen::Lower>();
}

// The regression's force per sample: `fit`'s coefficients on the columns of `subset`.
std::vector<double> subset_force(const LibraryRows& rows, const std::vector<std::size_t>& subset, const SubsetFit& fit) {
  const std::vector<int> cols = columns_of(rows.lib, subset);
  std::vector<double> force(rows.s.size(), 0.0);
  rows.each_kept([&](std::size_t i, const Eigen::VectorXd& row) {
    for (std::size_t c = 0; c < cols.size(); ++c) force[i] += fit.coefficients[static_cast<Eigen::Index>(c)] * row[cols[c]];
  });
  return force;
}

}  // namespace

namespace {

// The regression's sufficient statistics and scaling, and its fits of a subset of terms.
struct Regression {
  const Library& lib;
  Moments moments[2];
  Eigen::VectorXd scale;  // columns to unit RMS on the fitting samples, for the solve's conditioning
  double viscous_coefficient;

  [[nodiscard]] SubsetFit fit(const std::vector<std::size_t>& subset) const {
    return fit_subset(lib, subset, moments[0], moments[1], scale, viscous_coefficient);
  }
};

std::vector<std::size_t> with(std::vector<std::size_t> subset, std::size_t term) {
  subset.push_back(term);
  return subset;
}

// The term that, joined to `chosen`, validates best with every coefficient's sign physical, and
// how many terms were tried (the claim's family).
struct NextTerm {
  std::size_t term;  // lib.terms.size(): none
  SubsetFit fit;
  int tried = 0;
};
NextTerm best_next_term(const Regression& r, const std::vector<std::size_t>& chosen) {
  NextTerm next{r.lib.terms.size(), {}, 0};
  for (std::size_t t = 0; t < r.lib.terms.size(); ++t) {
    if (std::ranges::find(chosen, t) != chosen.end()) continue;
    if (r.moments[0].gram(r.lib.terms[t].first_column, r.lib.terms[t].first_column) <= 0.0) continue;  // all zero
    ++next.tried;
    SubsetFit fit = r.fit(with(chosen, t));
    if (!fit.physical) continue;
    if (next.term == r.lib.terms.size() || fit.validation_rms < next.fit.validation_rms) {
      next.term = t;
      next.fit = std::move(fit);
    }
  }
  return next;
}

// Terms that would have done as well as `next`: the run cannot tell them from it (on a single
// sine, a mass and a negative stiffness are the same column). Led by `next`'s own name.
std::vector<std::string> look_alike_terms(const Regression& r, const std::vector<std::size_t>& chosen,
                                          const NextTerm& next, double current, double threshold) {
  std::vector<std::string> alike{r.lib.terms[next.term].name};
  for (std::size_t t = 0; t < r.lib.terms.size(); ++t) {
    if (t == next.term || std::ranges::find(chosen, t) != chosen.end()) continue;
    const SubsetFit other = r.fit(with(chosen, t));
    const bool passes = other.physical && 1.0 - other.validation_rms / std::max(current, 1e-300) >= threshold;
    if (passes && 1.0 - next.fit.validation_rms / std::max(other.validation_rms, 1e-300) < threshold)
      alike.push_back(r.lib.terms[t].name);
  }
  return alike;
}

// A mains line's fitted sine and cosine (its columns from `c`) added to `interference` per sample;
// returns its amplitude.
double add_mains_line(const Library& lib, const LibraryTerm& term, const SubsetFit& fit, Eigen::Index c,
                      const FitSeries& s, std::vector<double>& interference) {
  const double sine = fit.coefficients[c], cosine = fit.coefficients[c + 1];
  const double f =
      lib.lines[static_cast<std::size_t>(term.first_column - kBaseColumns - static_cast<int>(model::kLearnedTermCount)) / 2]
          .frequency;
  std::size_t run = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double phase = 2.0 * std::numbers::pi * f * time_of(s, i, run);
    interference[i] += sine * std::sin(phase) + cosine * std::cos(phase);
  }
  return std::hypot(sine, cosine);
}

}  // namespace

TermDiscovery discover_terms(const FitSeries& s, const std::vector<double>& predicted, const std::vector<double>& B,
                             const model::BinghamDamper& fluid, double threshold, const TermClaim& claim,
                             std::size_t max_terms) {
  TermDiscovery out;
  out.interference.assign(s.size(), 0.0);
  if (s.size() < 16 || s.run_periods.empty()) return out;
  const Library lib = make_library(1.0 / s.sample_period);
  const std::vector<double> a = zero_phase_acceleration(s);
  const LibraryRows rows{lib, s, predicted, B, a, fluid};
  Regression r{lib, {}, Eigen::VectorXd(lib.columns), fluid.viscous_coefficient()};
  accumulate_moments(rows, r.moments);
  if (r.moments[0].count < 8 || r.moments[1].count < 8) return out;
  for (Eigen::Index c = 0; c < lib.columns; ++c)
    r.scale[c] = std::max(std::sqrt(r.moments[0].gram(c, c) / static_cast<double>(r.moments[0].count)), 1e-300);

  std::vector<std::size_t> chosen;
  std::vector<double> gains;
  std::vector<ClaimEvidence> claims;
  SubsetFit accepted_fit = r.fit(chosen);
  double current = accepted_fit.validation_rms;
  while (chosen.size() < max_terms) {
    NextTerm next = best_next_term(r, chosen);
    if (next.term == lib.terms.size()) break;
    const double gain = 1.0 - next.fit.validation_rms / std::max(current, 1e-300);
    ClaimEvidence evidence;
    if (claim.pieces != nullptr) {
      evidence = weigh_claim(s, *claim.pieces, subset_force(rows, chosen, accepted_fit),
                             subset_force(rows, with(chosen, next.term), next.fit), claim.noise_floor, next.tried,
                             claim.criterion);
      if (!evidence.passes()) break;
    } else if (gain < threshold) {
      break;
    }
    std::vector<std::string> alike = look_alike_terms(r, chosen, next, current, threshold);
    if (alike.size() > 1) out.ambiguous.push_back(std::move(alike));
    chosen.push_back(next.term);
    gains.push_back(gain);
    claims.push_back(evidence);
    current = next.fit.validation_rms;
    accepted_fit = std::move(next.fit);
  }

  if (chosen.empty()) return out;
  out.force_scale = accepted_fit.coefficients[0];
  out.extra_viscous = accepted_fit.coefficients[1];
  Eigen::Index c = kBaseColumns;
  for (std::size_t k = 0; k < chosen.size(); ++k) {
    const LibraryTerm& term = lib.terms[chosen[k]];
    DiscoveredTerm d{term.name, accepted_fit.coefficients[c], term.unit, term.interference, gains[k], claims[k]};
    if (term.interference) d.coefficient = add_mains_line(lib, term, accepted_fit, c, s, out.interference);
    out.terms.push_back(std::move(d));
    c += term.columns;
  }
  return out;
}

}  // namespace mrd::tools
