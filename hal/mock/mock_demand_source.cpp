#include "hal/mock/mock_demand_source.hpp"

#include <limits>

namespace mrd::hal::mock {

std::optional<DemandSample> MockDemandSource::latest_demand() {
  const Timestamp now = clock_.now();
  if (script_.is_active(FaultKind::kDemandMissing, now)) return std::nullopt;
  if (last_ && script_.is_active(FaultKind::kDemandStale, now)) return last_;
  DemandSample s{demand_, now, ++sequence_, kSampleValid};
  if (script_.is_active(FaultKind::kDemandNotFinite, now)) s.value = std::numeric_limits<double>::quiet_NaN();
  if (const ScriptedFault* f = script_.active(FaultKind::kDemandOutOfRange, now)) s.value = f->parameter;
  last_ = s;
  return s;
}

}  // namespace mrd::hal::mock
