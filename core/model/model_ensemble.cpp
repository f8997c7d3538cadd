#include "core/model/model_ensemble.h"

#include <nlohmann/json.hpp>
#include <string>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/sha256.h"
#include "core/model/affordance_model.h"
#include "core/model/model_card.h"

namespace sagrid::model {
namespace fs = std::filesystem;

namespace {
void requireSame(const ModelCard& model, const ModelCard& member, const fs::path& memberCard) {
  if (const auto d = networkDifference(model, member))
    throw ModelError(memberCard.string() + ": the " + d->what + " is " + d->b + " but the model " +
                     model.name + " has " + d->a + "; an ensemble's networks share one card");
  if (!member.ensemble.empty())
    throw ModelError(memberCard.string() + ": is itself an ensemble; add its networks one by one");
}

// <name>.member<N>.pt with the first N not yet listed nor on disk.
std::string freeMemberFile(const ModelCard& card, const fs::path& dir) {
  for (int n = 1;; ++n) {
    const std::string file = card.name + ".member" + std::to_string(n) + ".pt";
    bool listed = false;
    for (const auto& m : card.ensemble) listed = listed || m.file == file;
    if (!listed && !fs::exists(dir / file)) return file;
  }
}
}  // namespace

fs::path addEnsembleMember(const fs::path& cardFile, const fs::path& memberCardFile,
                           const std::string& role) {
  ModelCard card = readModelCard(cardFile);
  const ModelCard member = readModelCard(memberCardFile);
  requireSame(card, member, memberCardFile);
  // Loading the member checks its weights against its card (sha256, every tensor's shape) before
  // the model's card is touched.
  AffordanceModel::load(memberCardFile);
  const std::string bytes = readFileBytes(memberCardFile.parent_path() / member.weightsFile);
  const std::string sha = sha256Hex(bytes);
  if (sha == card.weightsSha256)
    throw ModelError(memberCardFile.string() + ": its weights are the model's own");
  for (const auto& m : card.ensemble)
    if (m.sha256 == sha)
      throw ModelError(memberCardFile.string() + ": its weights are already member " + m.file);
  const std::string file = freeMemberFile(card, cardFile.parent_path());
  const fs::path copied = cardFile.parent_path() / file;
  writeFileAtomic(copied, bytes);
  card.ensemble.push_back({file, sha});
  nlohmann::json record = member.training;
  record["file"] = file;
  record["final_train_loss"] = member.metrics.value("final_train_loss", nlohmann::json());
  if (!role.empty()) record["role"] = role;
  card.training["ensemble"].push_back(record);
  writeModelCard(cardFile, card);
  return copied;
}

fs::path keepInitNetworks(const fs::path& initCardFile, const fs::path& fineTunedCardFile,
                          const fs::path& outDir) {
  ModelCard card = readModelCard(initCardFile);
  const ModelCard fineTuned = readModelCard(fineTunedCardFile);
  requireSame(card, fineTuned, fineTunedCardFile);
  AffordanceModel::load(fineTunedCardFile);  // its weights against its card, before any write
  // The init's networks but an earlier fine-tune's (its record names it by file and role).
  const nlohmann::json records = card.training.value("ensemble", nlohmann::json::array());
  auto roleOf = [&](const std::string& file) {
    for (const auto& r : records)
      if (r.value("file", "") == file) return r.value("role", "");
    return std::string();
  };
  std::vector<WeightsFile> kept, dropped;
  for (const auto& m : card.ensemble) (roleOf(m.file) == kFineTuneRole ? dropped : kept).push_back(m);
  nlohmann::json keptRecords = nlohmann::json::array();
  for (const auto& r : records)
    if (r.value("role", "") != kFineTuneRole) keptRecords.push_back(r);
  card.ensemble = kept;
  if (card.training.contains("ensemble")) card.training["ensemble"] = keptRecords;

  const fs::path fromDir = fs::absolute(initCardFile).parent_path();
  const std::string sha = sha256Hex(readFileBytes(fineTunedCardFile.parent_path() / fineTuned.weightsFile));
  bool known = sha == card.weightsSha256;
  for (const auto& m : kept) known = known || m.sha256 == sha;
  if (known)
    throw ModelError(fineTunedCardFile.string() + ": its weights are the init model's own (" +
                     initCardFile.string() + "): nothing was fine-tuned");

  fs::create_directories(outDir);
  const bool inPlace = fs::equivalent(fromDir, outDir);
  if (!inPlace) {
    std::vector<std::string> files{card.weightsFile};
    for (const auto& m : kept) files.push_back(m.file);
    for (const auto& f : files) writeFileAtomic(outDir / f, readFileBytes(fromDir / f));
  }
  // The dropped fine-tune's weights (or a copy of them) would only be mistaken for a member.
  for (const auto& m : dropped) {
    std::error_code ignored;
    fs::remove(outDir / m.file, ignored);
  }
  const fs::path outCard = outDir / (card.name + ".json");
  writeModelCard(outCard, card);
  addEnsembleMember(outCard, fineTunedCardFile, kFineTuneRole);
  return outCard;
}

}  // namespace sagrid::model
