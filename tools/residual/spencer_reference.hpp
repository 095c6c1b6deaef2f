#pragma once

#include <string>
#include <vector>

#include "record/recorded_run.hpp"
#include "tools/replay/replay.hpp"
#include "tools/residual/fit_series.hpp"

namespace mrd::tools {

// Spencer et al. (1997)'s modified Bouc-Wen model with the published parameters of Dyke's
// prototype damper (model/spencer_bouc_wen.hpp), run over a recorded run as the reference
// the closing-the-loop table and the report compare our model with: its force, sample by
// sample. It takes the driver's command voltage, as the paper's model does, and the series'
// velocity (the same one our fits use). Throws InputError for a run that logged a current
// instead of the voltage.
[[nodiscard]] std::vector<double> spencer_dyke_prediction(const record::RecordedRun& run, const FitSeries& series);

}  // namespace mrd::tools
