// Procedural stoves: freestanding and slide-in ranges with ovens, drop-in cooktops, hobs set in
// a counter block and small hot plates; 1-6 burners in varied layouts and looks, knobs or touch
// buttons in varied places. Ground truth: a heatsource at the centre of each burner's cooking
// surface, a togglebutton at the centre of each knob or button.
#pragma once

#include <string>
#include <vector>

#include "core/generate/generated_object.h"
#include "core/generate/random.h"

namespace sagrid::gen {

// The values each recorded parameter can take, for tests and variety tables.
const std::vector<std::string>& stoveKinds();
const std::vector<std::string>& stoveLayouts();
const std::vector<std::string>& stoveBurnerLooks();
const std::vector<std::string>& stoveControlPlacements();

struct StoveOptions {
  // A built-in glass hob on its own (kind "glass_slab", never drawn otherwise): one thin sheet
  // whose zones and touch controls (controls "printed") exist only in its texture.
  bool glassSlab = false;
};

// generator fields: kind, layout, burners, burner_look, controls, knobs, knob_style, finish,
// width_m, extras.
GeneratedObject generateStove(Rng& rng, const StoveOptions& options = {});

}  // namespace sagrid::gen
