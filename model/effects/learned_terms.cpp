#include "model/effects/learned_terms.hpp"

#include <cstdio>

namespace mrd::model {

ValidationReport validate(const LearnedTermsParams& p) {
  ValidationReport report;
  for (std::size_t k = 0; k < kLearnedTermCount; ++k) {
    const LearnedTermInfo& term = kLearnedTerms[k];
    const double c = p.coefficients[k];
    if (!std::isfinite(c)) {
      report.error(std::string(term.name), "must be finite");
    } else if (term.sign > 0 && c < 0.0) {
      report.error(std::string(term.name), "must be >= 0 [" + std::string(term.unit) + "]: a negative value " +
                                               "would feed energy into the motion");
    }
  }
  return report;
}

std::string LearnedTermsEffect::size_summary(const Params& p) {
  std::string text;
  for (std::size_t k = 0; k < kLearnedTermCount; ++k) {
    if (p.coefficients[k] == 0.0) continue;
    char term[96];
    std::snprintf(term, sizeof term, "%s%s %.4g %s", text.empty() ? "" : ", ", kLearnedTerms[k].name.data(),
                  p.coefficients[k], kLearnedTerms[k].unit.data());
    text += term;
  }
  return text.empty() ? "no terms" : text;
}

}  // namespace mrd::model
