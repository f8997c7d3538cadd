// `sagrid ensemble CARD --add MEMBER_CARD`: average another trained network of the same model into
// its predictions (core/model/model_ensemble.h).
#include <CLI/CLI.hpp>
#include <cstdio>

#include "app/command_registry.h"
#include "core/model/affordance_model.h"
#include "core/model/model_ensemble.h"

namespace {

void setupEnsemble(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "ensemble",
      "Add a network trained apart (same model, architecture and features; e.g. `sagrid train` on "
      "other data or with another seed) to a model: annotate, eval and the GUI then average the "
      "networks' distance fields. Its weights are copied beside the card as "
      "<model>.member<N>.pt and the card lists them (weights.ensemble). Refit the count "
      "(`eval --fit-counts`) and the evidence gate (`category evidence`) after it, as after "
      "training");
  struct Options {
    std::string card, member;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("card", o->card, "The model's card (<category>.<type>.json), rewritten")
      ->required();
  cmd->add_option("--add", o->member, "The card of the network to add (its .pt beside it)")
      ->required();
  cmd->callback([o] {
    const auto copied = sagrid::model::addEnsembleMember(o->card, o->member);
    // Loading it now checks every network against the card before the user relies on it.
    const auto model = sagrid::model::AffordanceModel::load(o->card);
    std::printf("%s: %zu networks (added %s)\n", o->card.c_str(), model.networkCount(),
                copied.filename().string().c_str());
  });
}

}  // namespace

SAGRID_REGISTER_COMMAND("ensemble", setupEnsemble);
