#include "model/damper_model.hpp"

namespace mrd::model {

namespace {
ValidationReport validate(const JilesAthertonSettings& s) {
  ValidationReport report;
  report.require_in_range("max_field_step_fraction", s.max_field_step_fraction, 1e-6, 1.0, false);
  if (s.max_substeps < 1) report.error("max_substeps", "must be at least 1");
  report.require_in_range("field_step_growth", s.field_step_growth, 0.0, 1.0, true);
  report.require_in_range("denominator_floor", s.denominator_floor, 1e-9, 1.0, true);
  return report;
}
}  // namespace

ValidationReport validate(const DamperModel& model) {
  ValidationReport report;
  report.merge(validate(model.jiles_atherton), "jiles_atherton");
  report.merge(validate(model.circuit), "circuit");
  report.merge(validate(model.integration), "integration");
  report.merge(validate(model.fluid), "fluid");
  report.merge(validate(model.geometry), "geometry");
  report.merge(validate(model.effects), "effects");
  return report;
}

}  // namespace mrd::model
