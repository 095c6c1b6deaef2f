#pragma once

namespace mrd::tools {

// Step 6b's rule for a named effect against the library terms that explain the residual in its
// place (validation RMS of the effect alone, of the terms alone, of both): the terms replace the
// effect when they validate better by more than the threshold and the effect's removal beside
// them costs less than it; within the threshold of each other the run cannot decide (the
// named effect stays); otherwise the effect stays. `both_validation` is read only when the terms
// are better by more than the threshold.
enum class TermRivalry { kEffectStays, kAmbiguous, kTermsReplace };
TermRivalry weigh_terms_against_effect(double effect_validation, double terms_validation, double both_validation,
                                       double threshold);

}  // namespace mrd::tools
