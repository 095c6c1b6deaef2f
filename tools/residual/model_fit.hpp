#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "model/damper_model.hpp"
#include "tools/optimisation/optimiser.hpp"
#include "tools/optimisation/worker_pool.hpp"
#include "tools/residual/fit_series.hpp"

namespace mrd::tools {

// The gap induction B [T] of one model over a series (Eq. 1-10 after its coil lag). Most of a
// fit's trials vary only what acts after B (every effect but coil_lag): they reuse this B and
// skip the J-A integration, which is most of an observer pass on a switched current.
class InductionTrace {
 public:
  InductionTrace(const model::DamperModel& model, const FitSeries& series);
  // Whether `model`'s B over the series is this one: the same J-A parameters, circuit,
  // integration and effects that change B.
  [[nodiscard]] bool serves(const model::DamperModel& model) const;
  [[nodiscard]] const std::vector<double>& induction() const { return B_; }

 private:
  model::DamperModel magnetics_;
  std::vector<double> B_;
};

// The force [N] the observer predicts over the series: model::Observer with the series'
// velocity as its velocity sensor, from a demagnetised core at each run start. A recorded
// temperature is handed to the observer (it matters only with thermal_drift on). With a trace
// that serves the model, B comes from it; the force is the same to the last bit.
void predict_force(const model::DamperModel& model, const FitSeries& series,
                   std::vector<double>& force, const InductionTrace* trace = nullptr);

// The same, with the induction [T] of each sample.
void predict_force_and_induction(const model::DamperModel& model, const FitSeries& series,
                                 std::vector<double>& force, std::vector<double>& B);

// RMS [N] of measured - predicted over the fitting samples, the validation samples and all;
// under a robust loss (the searches' series with --robust-fit), sqrt(mean rho(r)) of it.
struct ResidualRms {
  double fitting = 0.0;
  double validation = 0.0;
  double all = 0.0;
  double max = 0.0;  // max |residual| over all samples
};
ResidualRms residual_rms(const FitSeries& series, const std::vector<double>& predicted);

// Terms fitted by least squares on the fitting samples on top of a model's force F_m:
//   F = a F_m + b u(v) [+ f s(v)] [+ c_j column_j for the linear columns of `effects`]
// a rescales the yield and viscous forces together (the damper's size), b corrects the
// viscous coefficient (u(v) the viscous force per unit c0: v for Bingham, the Herschel-Bulkley
// shape otherwise), f the seal friction along the model's sign term s(v), and an effect whose
// parameters enter the force linearly (a gas spring's F0 + k x) has them solved here too (its
// descriptor's kLinear). They make the search over the nonlinear parameters cheap: each trial
// point costs one observer pass.
using LinearEffects = std::vector<const model::EffectInfo*>;
struct LinearTerms {
  double force_scale = 1.0;    // a [-], >= 0
  double extra_viscous = 0.0;  // b [N s/m]; a c0 + b >= 0
  double extra_friction = 0.0;  // f [N]; a F_s + f >= 0 (only with the model's shapes)
  LinearEffects effects;
  std::vector<double> coefficients;  // c_j, the effects' columns in order
  // The model's viscous and sign shapes; without them the columns are F_m, v and the effects'.
  std::optional<model::BinghamDamper> shapes;
  bool friction_column = true;  // with the shapes: false at a constant current
};
// With `present` (the model that predicted the force), the viscous column takes its shape and,
// where the current varies, the friction column its sign term (at a constant current the
// friction and the force scale are one direction), and a coefficient whose parameter must stay >= 0 (the viscous coefficient, the
// seal friction, and an effect's kLinearNonNegative) is held where it makes that parameter 0
// when the unconstrained solve would make it negative: a physical fit of the others, not a
// rejected one.
LinearTerms fit_linear_terms(const FitSeries& series, const std::vector<double>& predicted,
                             const LinearEffects& effects, const model::DamperModel* present = nullptr);
// F_fit - (a F_m + ...) as above, over the fitting samples: the search's fitness [N RMS;
// sqrt(mean rho(r)) under the series' robust loss].
double linear_fit_rms(const FitSeries& series, const std::vector<double>& predicted,
                      const LinearTerms& terms);

// The model the terms describe: the pole length times a (yield and viscous force scale with
// it), the viscosity set so that c0 becomes a c0 + b, the seal friction a F_s + f, force-valued effect parameters times a
// (each descriptor's scale_force), and the effects' coefficients added. The observer then
// predicts a F_m + b v + ... exactly for the base model, and closely with effects on
// (some effects scale b v too); the reports always evaluate the model itself, never this
// approximation.
model::DamperModel apply_linear_terms(model::DamperModel model, const LinearTerms& terms);

// Changes a model at search coordinates p: sets a base parameter or an effect's.
using ModelEdit = std::function<model::DamperModel(model::DamperModel, const Point&)>;

// A family of models over a few nonlinear parameters, in search coordinates: edit(origin, p).
struct ParameterSpace {
  std::string name;
  std::vector<std::string> parameters;  // names of the search coordinates, for reports
  Bounds bounds;                         // may have dimension 0: only the linear terms
  model::DamperModel origin;
  ModelEdit edit;
  LinearEffects linear;  // effects whose linear columns join the linear terms
  // B of the origin over the fitting series, for the trials whose magnetics equal the origin's.
  std::shared_ptr<const InductionTrace> induction;

  [[nodiscard]] model::DamperModel build(const Point& p) const { return edit(origin, p); }
};

// The coordinates of `first` followed by those of `second`, both edits applied to first's
// origin in that order: a joint refinement of, say, the base parameters and a new effect.
ParameterSpace combine(const ParameterSpace& first, const ParameterSpace& second);

// The search's fitness at p: one observer pass, the linear terms solved, RMS over the fitting
// samples [N]; 1e300 for a model that fails validation. `buffer` is scratch.
double space_fitness(const ParameterSpace& space, const FitSeries& series, const Point& p,
                     std::vector<double>& buffer);

// The same trial's residual over the fitting samples, sign(r) sqrt(rho(r)) each (r under least
// squares), so that their mean square is the fitness squared; false for a model that fails
// validation or a non-finite fit.
bool space_residuals(const ParameterSpace& space, const FitSeries& series, const Point& p, std::vector<double>& buffer,
                     std::vector<double>& residuals);

struct FittedModel {
  Point theta;                // the best search coordinates
  LinearTerms linear;
  model::DamperModel model;   // apply_linear_terms(build(theta), linear)
  double fitting_rms = 0.0;   // of the linear fit at theta [N]
  std::int64_t evaluations = 0;
};

// The fit at theta: one observer pass, the linear terms solved, the model they describe.
FittedModel fitted_at(const ParameterSpace& space, const FitSeries& series, const Point& theta,
                      std::int64_t evaluations);

// The improved PSO (tools/optimisation/particle_swarm.hpp) over the space's coordinates, the
// linear terms solved at each point; `evaluations` per coordinate, one observer pass each, spread
// over `pool` (serial when it is null). Deterministic for the seed.
FittedModel fit_space(const ParameterSpace& space, const FitSeries& series, WorkerPool* pool,
                      std::uint64_t seed, int evaluations_per_parameter = 48);

// The best of `points` by space_fitness (serial), as a fit.
FittedModel best_of(const ParameterSpace& space, const FitSeries& series, const std::vector<Point>& points);

// Nelder-Mead from `start` inside the space's bounds (points are clamped), serial: the local
// joint refinement after a swarm. Initial steps are `step` of each coordinate's range.
FittedModel refine_space(const ParameterSpace& space, const FitSeries& series, const Point& start,
                         int max_evaluations, double step = 0.1);

}  // namespace mrd::tools
