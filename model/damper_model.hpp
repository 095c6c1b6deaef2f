#pragma once

#include "model/bingham_damper.hpp"
#include "model/effects/effect_set.hpp"
#include "model/jiles_atherton.hpp"
#include "model/mr_fluid.hpp"

namespace mrd::model {

// Everything the observer needs to know about one damper: its magnetic circuit (Eq. 1-10),
// its fluid (Eq. 13), its geometry (Eq. 12) and the optional effects the base model lacks
// (all off by default). The defaults are the lumped 50 kN class damper documented in
// docs/MODEL.md.
struct DamperModel {
  JilesAthertonParams jiles_atherton;
  MagneticCircuit circuit;
  JilesAthertonSettings integration;
  MrFluid fluid;
  DamperGeometry geometry;
  EffectSet effects;
};

// All issues of all parts, with field paths such as "jiles_atherton.c".
ValidationReport validate(const DamperModel& model);

}  // namespace mrd::model
