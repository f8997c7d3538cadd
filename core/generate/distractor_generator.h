// Procedural distractors: kitchen objects that are neither a stove nor a sink but look like one to
// a retrieval that only knows those two (boxes with doors, knobs and handles): microwaves, ovens
// without a hob, dishwashers, range hoods and kitchen cabinets, and on request appliances that
// stand beside them: washing machines and dryers (front and top loaders), toasters, and kettles,
// blenders and coffee makers. They train and test the category
// classifier's rejection ("none"); they have no affordance points.
#pragma once

#include <string>
#include <vector>

#include "core/generate/generated_object.h"
#include "core/generate/random.h"

namespace sagrid::gen {

// The category distractors are labelled with.
inline constexpr const char* kDistractorCategory = "none";

// The kinds, in the order their weights are drawn; the last three (washing_machine, toaster,
// countertop_appliance) only with `appliances`.
const std::vector<std::string>& distractorKinds();

// generator fields: kind, finish, width_m, height_m, depth_m, knobs, extras.
GeneratedObject generateDistractor(Rng& rng, bool appliances = false);

}  // namespace sagrid::gen
