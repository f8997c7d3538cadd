// Ensembles of one model: more networks of the same card (architecture, mode, features, grid),
// trained apart, whose distance fields AffordanceModel averages (ModelCard::ensemble). The shipped
// stove.togglebutton is the bench-trained network plus one trained on 300 more generated stoves:
// each alone puts spurious minima where the other does not (README of resources/models).
#pragma once

#include <filesystem>

namespace sagrid::model {

// Adds the network of `memberCard` (a card written by `sagrid train` and its weights) to the model
// of `card`: its weights are copied beside `card` as <name>.member<N>.pt (N = 1, 2, ...; the
// sha256 checked against its card), listed in weights.ensemble and its training record appended
// to training.ensemble; the card is rewritten atomically, its point-extraction settings kept.
// Returns the copied weights' path. Throws FileError naming the file (unreadable cards or
// weights, a sha256 that differs) and ModelError naming what differs when the member is not the
// same model (name, architecture, mode, feature backend, config or channels, descriptor or grid
// size) or is itself an ensemble.
std::filesystem::path addEnsembleMember(const std::filesystem::path& card,
                                        const std::filesystem::path& memberCard);

}  // namespace sagrid::model
