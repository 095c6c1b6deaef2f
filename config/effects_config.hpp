#pragma once

#include <string>

#include "config/toml_reader.hpp"
#include "model/effects/effect_set.hpp"

namespace mrd::config {

// The [damper.effects.<name>] tables of the config (docs/FIRMWARE.md lists every key). One
// list of keys serves both directions, so the reader and the writer cannot drift apart.
void read_effects(TomlReader& in, model::EffectSet& effects);

// The same tables as TOML text, every key stated, in the order the reader reads them. Tools
// that identify effects write their result with it, for mrd-controller --config to load.
std::string effects_toml(const model::EffectSet& effects);

}  // namespace mrd::config
