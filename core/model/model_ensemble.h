// Ensembles of one model: more networks of the same card (architecture, mode, features, grid),
// trained apart, whose distance fields AffordanceModel averages (ModelCard::ensemble). The shipped
// stove.togglebutton is the bench-trained network plus one trained on 300 more generated stoves:
// each alone puts spurious minima where the other does not (README of resources/models).
#pragma once

#include <filesystem>
#include <string>

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
// `role`, when given, is recorded with the member's training record (training.ensemble[i].role).
std::filesystem::path addEnsembleMember(const std::filesystem::path& card,
                                        const std::filesystem::path& memberCard,
                                        const std::string& role = {});

// The role of a member a fine-tune added beside the networks it started from.
inline constexpr const char* kFineTuneRole = "fine-tune";

// A fine-tune that keeps what its init model knew (`train --keep-init`): writes into `outDir` the
// init model of `initCard` (its card, point extraction and networks) with the network of
// `fineTunedCard` added as a member of role kFineTuneRole, so the model predicts the mean of the
// init's fields and the fine-tuned one's. A member of that role the init already has (an earlier
// such fine-tune, trained on less of the curated data) is dropped first. `outDir` may be the
// init's own folder. Returns the written card. Throws as addEnsembleMember does; nothing in
// `outDir` changes when the fine-tuned network is refused.
std::filesystem::path keepInitNetworks(const std::filesystem::path& initCard,
                                       const std::filesystem::path& fineTunedCard,
                                       const std::filesystem::path& outDir);

}  // namespace sagrid::model
