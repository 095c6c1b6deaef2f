#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "record/recorded_run.hpp"
#include "tools/report/force_fit.hpp"
#include "tools/residual/fit_series.hpp"
#include "tools/residual/residual_search.hpp"

namespace mrd::tools {

// The human summary: the runs, the base fit, the error before, each round's candidates with
// their verdicts, the accepted effects and their parameters, the error after, what remains.
std::string residual_summary(const std::vector<record::RecordedRun>& runs, const ResidualResult& r);

// The JSON of docs/CLOSING-THE-LOOP.md, exactly these keys (forces in N): samples,
// rms_before_N, max_before_N, effects, effect, rms_after_N, max_after_N, effect_params,
// candidates [{effect, rms_after_N, validation_rms_N, accepted}] (each candidate once: its
// last round), unexplained.
// With `fit` (force_fit_figures of residual_traces), also "fit" (force_fit_json).
std::string residual_json(const ResidualResult& r, const ForceFitFigures* fit = nullptr);

// The series and the final model's prediction (the base model's as the baseline, the screened
// samples marked) as the report's force-fit section reads them.
ForceFitTraces residual_traces(const std::vector<record::RecordedRun>& runs, const FitSeries& series,
                               const ResidualResult& r);

// `config_text` (the config the analysis started from) with its damper tables replaced by the
// final model, the accepted effects enabled in [damper.effects.*]: mrd-controller --config and
// mrd-replay --config load it as it is. Throws std::runtime_error if the text does not parse.
std::string updated_config(std::string_view config_text, const ResidualResult& r);

// residual_force_displacement.png (measured, base and final model against displacement),
// residual_time.png (residual before and after against time) and residual_phase.png (the
// residual against displacement and velocity). Returns "" or why not.
std::string plot_residual(const FitSeries& series, const ResidualResult& r, const std::string& name,
                          const std::string& directory);

// --report DIR: report.html with the fit (measured against the base and the final model over
// time, displacement and velocity), the residual's structure, the parameters with their
// standard deviations, every candidate with its validation figures, the screening's spans and
// the provenance; the plots' .dat and .gp beside it. `traces` are residual_traces' (with a
// reference model's prediction when one was asked for). Returns "" or why not.
std::string write_residual_report(const std::vector<record::RecordedRun>& runs, const FitSeries& series,
                                  const ResidualResult& r, const ForceFitTraces& traces, const Provenance& provenance,
                                  const std::string& directory);

}  // namespace mrd::tools
