// The lists outside the effect registry that name the effects, checked against AllEffects: an
// effect added to the registry and left out of one of them fails here, naming the file (issue
// 30: such a list was silently incomplete). The registry's own walks need no list.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "model/effects/effect_set.hpp"

namespace effect_lists {

std::string text_of(const std::string& relative) {
  std::ifstream in(std::string(MRD_SOURCE_DIR) + "/" + relative);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

std::string config_table(std::string_view name) { return "[damper.effects." + std::string(name) + "]"; }

// The words of a study script's `effects=(...)` line.
std::string effects_line(const std::string& script) {
  const std::string text = text_of(script);
  const std::string opening = "\neffects=(";
  const std::size_t at = text.find(opening);
  if (at == std::string::npos) return {};
  const std::size_t from = at + opening.size();
  return " " + text.substr(from, text.find(')', from) - from) + " ";
}

TEST(EffectLists, EveryListThatNamesTheEffectsNamesEachOne) {
  struct Where {
    const char* file;
    std::string (*pattern)(std::string_view name);
  };
  const Where candidates_everywhere[] = {
      {"etc/mrd/plant.toml", config_table},
      {"fuzz/corpus/config/mrd.toml", config_table},
      {"fuzz/dict/config.dict", +[](std::string_view n) { return "\"" + config_table(n) + "\""; }},
      {"docs/MODEL.md", +[](std::string_view n) { return "### " + std::string(n) + " ("; }},
      {"tests/generator/damper_truth.py", +[](std::string_view n) { return "\"" + std::string(n) + "\""; }},
  };
  const char* studies[] = {"tools/residual/detection-study.sh", "tests/generator/independent-study.sh",
                           "tests/generator/random-damper-study.sh"};
  const std::string config = text_of("etc/mrd/mrd.toml");
  int candidates = 0;
  for (const mrd::model::EffectInfo& e : mrd::model::effect_infos()) {
    EXPECT_NE(config.find(config_table(e.name)), std::string::npos) << e.name << ": not in etc/mrd/mrd.toml";
    if (!e.named_candidate) continue;
    ++candidates;
    for (const Where& w : candidates_everywhere)
      EXPECT_NE(text_of(w.file).find(w.pattern(e.name)), std::string::npos) << e.name << ": not in " << w.file;
    for (const char* study : studies)
      EXPECT_NE(effects_line(study).find(" " + std::string(e.name) + " "), std::string::npos)
          << e.name << ": not in the effects=(...) line of " << study;
  }
  // At least the six the studies and docs name today: a new one adds (tests/layout/add_toy_effect.cmake).
  EXPECT_GE(candidates, 6);
}

}  // namespace effect_lists
