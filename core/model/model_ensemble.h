// Ensembles of one model: more networks of the same card (architecture, mode, features, grid),
// trained apart, whose distance fields AffordanceModel averages (ModelCard::ensemble). The shipped
// stove.togglebutton is the bench-trained network plus one trained on 300 more generated stoves:
// each alone puts spurious minima where the other does not (README of resources/models).
#pragma once

#include <filesystem>

namespace sagrid::model {

// Adds the network of `memberCard` (a card written by `sagrid train` and its weights) to the model
// of `card`: the member is loaded first (AffordanceModel::load: its weights against its card),
// then its weights are copied beside `card` as <name>.member<N>.pt (N = 1, 2, ...), listed in
// weights.ensemble and its training record appended to training.ensemble; the card is rewritten
// atomically, its point-extraction settings kept. Returns the copied weights' path. Throws as
// AffordanceModel::load does for an unusable member (the file named), and ModelError naming what
// differs when the member is not the same model (name, architecture, mode, feature backend,
// config or channels, descriptor or grid size), is itself an ensemble, or has the model's own or
// a member's weights. Nothing is written when it throws.
std::filesystem::path addEnsembleMember(const std::filesystem::path& card,
                                        const std::filesystem::path& memberCard);

}  // namespace sagrid::model
