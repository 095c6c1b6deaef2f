#include "tools/residual/term_rivalry.hpp"

#include <algorithm>

namespace mrd::tools {

TermRivalry weigh_terms_against_effect(double effect_validation, double terms_validation, double both_validation,
                                       double threshold) {
  if (terms_validation < (1.0 - threshold) * effect_validation) {
    const double removal_cost = 1.0 - both_validation / std::max(terms_validation, 1e-300);
    return removal_cost < threshold ? TermRivalry::kTermsReplace : TermRivalry::kEffectStays;
  }
  const double margin = 1.0 - std::min(terms_validation, effect_validation) / std::max(terms_validation, effect_validation);
  return margin < threshold ? TermRivalry::kAmbiguous : TermRivalry::kEffectStays;
}

}  // namespace mrd::tools
