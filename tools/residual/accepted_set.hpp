#pragma once

#include <vector>

#include "model/damper_model.hpp"
#include "tools/residual/search_context.hpp"
#include "tools/residual/term_discovery.hpp"

namespace mrd::tools::search {

// The accepted set without one of its effects, refined: what the others explain on their own.
struct Reduced {
  model::DamperModel model;
  double validation = 0.0;
  std::vector<double> predicted;  // its force on the fitting series (empty where not kept)
};

// What the greedy rounds accepted, as the set revision then reconsiders it (step 6): with two or
// more accepted, each is reconsidered beside the others, since the greedy rounds alone never
// revisit an early pick.
struct AcceptedSet {
  Effects effects;
  std::vector<Effects> rivals;  // per effect: the candidates that also passed in its round
  model::DamperModel model;
  double validation = 0.0;
  // Per effect, the others refined without it, as the last revision pass left them (empty when
  // the set never had two effects).
  std::vector<Reduced> without;
  // Step 6a replaced the set by the library's terms, or step 6d put them beside a base that
  // named nothing: `model` is the base identified again beside them and carries them
  // (learned_terms), no longer the base the rounds started from.
  std::vector<DiscoveredTerm> terms_in_model;
  // Among those, the terms their regression could not tell apart, each group led by the one taken.
  std::vector<std::vector<std::string>> terms_ambiguous;
  // Nothing named and no term carried: `model` is the base the rounds started from.
  [[nodiscard]] bool is_the_base() const { return effects.empty() && terms_in_model.empty(); }
};

}  // namespace mrd::tools::search
