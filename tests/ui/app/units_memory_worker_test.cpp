// The Train panel's "Grow units memory" (issues 40 and 41): the units curated in the GUI's
// training set join the loaded models' memory of real sizes, guarded leaving each source out
// against the named units; the loaded memory is never overwritten, a refused one goes to refused/
// with its report, and objects whose units are an unconfirmed guess are left out.
#include <gtest/gtest.h>

#include "core/annotate/size_memory.h"
#include "core/annotate/units_record.h"
#include "core/common/atomic_file.h"
#include "core/dataset/dataset.h"
#include "core/generate/dataset_generator.h"
#include "core/labels/labels.h"
#include "support/test_paths.h"
#include "training_worker_support.h"
#include "ui/app/training_worker.h"

namespace sagrid::ui {
namespace {
namespace fs = std::filesystem;

const fs::path kShipped = fs::path(SAGRID_SOURCE_DIR) / "resources" / "models";

TrainingStatus grow(const fs::path& dir) {
  TrainingRequest request = test::requestIn(dir);
  request.unitsMemory = true;
  return test::runToEnd(std::move(request), 300);
}

// Three generated objects in metres; the first one's units left as a guess nobody confirmed.
void curate(const fs::path& dir) {
  gen::generateDataset({{"stove", 2, 61}, {"sink", 1, 62}}, gen::MeshFormat::Obj, dir / "curated");
  const auto entries = readDataset(dir / "curated");
  ObjectLabels guessed = readLabels(entries.front().labels);
  recordUnitGuess(guessed.object, guessMetersPerUnit(90.0, "stove"));
  writeLabels(entries.front().labels, guessed);
}

TEST(UnitsMemoryWorker, TheShippedMemoryGrowsWithCuratedUnitsAndTheLoadedOneStays) {
  const fs::path dir = test::freshTempDir();
  fs::copy(kShipped, dir / "loaded", fs::copy_options::recursive);
  curate(dir);
  const std::string before = readFileBytes(dir / "loaded" / kSizeMemoryFile);
  const auto shipped = readSizeMemory(dir / "loaded");
  ASSERT_TRUE(shipped);

  const TrainingStatus status = grow(dir);
  ASSERT_TRUE(status.error.empty()) << status.error;
  ASSERT_EQ(status.verdicts.size(), 1u);
  EXPECT_NE(status.verdicts[0].find("units memory adopted"), std::string::npos) << status.verdicts[0];
  EXPECT_NE(status.finished.find("grown with 2 object(s)"), std::string::npos) << status.finished;
  EXPECT_NE(status.finished.find("1 left out: their units are a guess nobody confirmed"), std::string::npos)
      << status.finished;
  const auto grown = readSizeMemory(dir / "out");
  ASSERT_TRUE(grown);
  EXPECT_EQ(grown->entries().size(), shipped->entries().size() + 2);
  EXPECT_TRUE(fs::exists(dir / "out" / "units_memory.md"));
  EXPECT_EQ(readFileBytes(dir / "loaded" / kSizeMemoryFile), before);
  // The folder the GUI predicts from afterwards is whole.
  EXPECT_TRUE(fs::exists(dir / "out" / "category.json"));
}

TEST(UnitsMemoryWorker, AMemoryOfOneSourceCannotBeatTheNamedUnitsAndIsRefused) {
  const fs::path dir = test::freshTempDir();
  fs::copy(kShipped, dir / "loaded", fs::copy_options::recursive);
  fs::remove(dir / "loaded" / kSizeMemoryFile);
  curate(dir);
  const TrainingStatus status = grow(dir);
  ASSERT_TRUE(status.error.empty()) << status.error;
  ASSERT_EQ(status.verdicts.size(), 1u);
  EXPECT_NE(status.verdicts[0].find("units memory refused"), std::string::npos) << status.verdicts[0];
  EXPECT_NE(status.finished.find("refused: "), std::string::npos) << status.finished;
  EXPECT_FALSE(fs::exists(dir / "out" / kSizeMemoryFile));
  EXPECT_TRUE(fs::exists(dir / "out" / "refused" / "units_memory.md"));
}

}  // namespace
}  // namespace sagrid::ui
