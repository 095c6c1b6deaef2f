#include "model/effects/effect_set.hpp"

#include <algorithm>

namespace mrd::model {

bool EffectSet::any_enabled() const {
  bool any = false;
  for_each([&]<typename E>(const typename E::Params& p) { any = any || p.enabled; });
  return any;
}

ValidationReport validate(const EffectSet& effects) {
  ValidationReport report;
  effects.for_each([&]<typename E>(const typename E::Params& p) { report.merge(validate(p), E::kName); });
  return report;
}

namespace {

template <typename E>
EffectInfo info_of() {
  using P = typename E::Params;
  EffectInfo info;
  info.name = E::kName;
  info.separated_by = E::kSeparatedBy;
  info.term_forms = E::kTermForms;
  info.changes_induction = E::kChangesInduction;
  info.sized_by_dissipated_energy = E::kSizedByDissipatedEnergy;
  info.named_candidate = E::kNamedCandidate;
  info.search = E::kSearch;
  info.linear = E::kLinear;
  info.linear_non_negative = E::kLinearNonNegative;
  static_assert(E::kLinearNonNegative.empty() || E::kLinearNonNegative.size() == E::kLinear.size());
  info.enabled = [](const EffectSet& s) { return s.get<E>().enabled; };
  info.disable = [](EffectSet& s) { s.get<E>().enabled = false; };
  info.apply = [](EffectSet& s, std::span<const double> x, const RunScales& scales) {
    E::apply(s.get<E>(), x, scales);
  };
  info.coordinates = [](const EffectSet& s, const RunScales& scales, std::span<double> x) {
    E::coordinates(s.get<E>(), scales, x);
  };
  info.add_linear = [](EffectSet& s, std::span<const double> c) { E::add_linear(s.get<E>(), c); };
  info.linear_values = [](const EffectSet& s, std::span<double> v) {
    if (s.get<E>().enabled) E::linear_values(s.get<E>(), v);
  };
  info.scale_force = [](EffectSet& s, double a) { E::scale_force(s.get<E>(), a); };
  info.implausible = [](const EffectSet& s, const RunScales& scales) { return E::implausible(s.get<E>(), scales); };
  info.report = [](const EffectSet& s) {
    std::vector<std::pair<std::string, double>> out;
    E::report(s.get<E>(), [&](std::string_view key, double value) { out.emplace_back(std::string(key), value); });
    return out;
  };
  info.same = [](const EffectSet& a, const EffectSet& b) { return a.get<E>() == b.get<E>(); };
  info.set_nominal = [](EffectSet& s, DamperClassId damper) { s.get<E>() = E::nominal(damper); };
  info.resize = [](EffectSet& s, const EffectSet& nominal, double size, double energy) {
    P p = nominal.get<E>();
    E::resize(p, size, energy);
    s.get<E>() = p;
  };
  info.size_summary = [](const EffectSet& nominal) {
    P p = nominal.get<E>();
    E::resize(p, 1.0, 0.0);
    return E::size_summary(p);
  };
  return info;
}

const std::array<EffectInfo, AllEffects::size>& infos() {
  static const auto table = [] {
    std::array<EffectInfo, AllEffects::size> t{};
    std::size_t i = 0;
    for_each_effect_type([&]<typename E>() { t[i++] = info_of<E>(); });
    return t;
  }();
  return table;
}

}  // namespace

std::span<const EffectInfo> effect_infos() { return infos(); }

const EffectInfo* find_effect(std::string_view name) {
  const auto& t = infos();
  const auto it = std::find_if(t.begin(), t.end(), [&](const EffectInfo& e) { return e.name == name; });
  return it == t.end() ? nullptr : &*it;
}

}  // namespace mrd::model
