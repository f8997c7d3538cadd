// What real bathroom and kitchen assets ship on the wall behind a sink: a mirror (framed, or a
// mirror cabinet), a light bar or wall lamps above it, a shelf with bottles under it, a tiled back
// panel, a towel bar. Sweet Home 3D's vanities come with theirs, and the models, trained on bare
// generated sinks, put the spout on the mirror's top edge or its lamps (30-120 cm off). None of
// these parts carries an affordance: added to generated sinks they are hard negatives.
#pragma once

#include <string>
#include <vector>

#include "core/generate/generated_object.h"
#include "core/generate/random.h"

namespace sagrid::gen {

// Dresses the wall behind `object` (z-up metres, the faucet side at +y as the sink generator
// builds it): every part lies behind the object's back face or above its highest point, except
// a towel bar in front of (or beside) it, so the ground truth and the parts it belongs to are
// unchanged. Records the parts in object.generator["wall_fixtures"]; returns their names.
std::vector<std::string> addWallFixtures(GeneratedObject& object, Rng& rng);

// Whether a generated object of this category and generator record can take wall fixtures: sinks
// set in a counter, vanity or basin (not bare faucets).
bool acceptsWallFixtures(const GeneratedObject& object);

}  // namespace sagrid::gen
