// Procedural sinks and faucets: single, double and farmhouse basins (round or rectangular) set
// in a counter segment or a vanity cabinet, bare basins, and bare faucets with no basin at all;
// gooseneck, straight, pull-down, wall-mounted, bridge, compact and Meta-World-style arm faucets
// with top or side levers, twin cross or knob handles, joysticks; soap dispensers and sprayers as
// distractors. Ground truth: a fluidsource at the centre of the spout outlet, a togglebutton at
// the centre of each handle grip.
#pragma once

#include <string>
#include <vector>

#include "core/generate/generated_object.h"
#include "core/generate/random.h"

namespace sagrid::gen {

const std::vector<std::string>& sinkKinds();
const std::vector<std::string>& sinkBasinShapes();
const std::vector<std::string>& faucetTypes();
const std::vector<std::string>& faucetHandleTypes();

// generator fields: kind, basins, basin_shape, faucet, handle, handles, reach_m, spout_height_m,
// finish, distractors.
GeneratedObject generateSink(Rng& rng);

}  // namespace sagrid::gen
