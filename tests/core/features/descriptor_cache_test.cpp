#include "core/features/descriptor_cache.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/common/atomic_file.h"
#include "core/mesh/mesh_export.h"
#include "core/mesh/mesh_import.h"
#include "support/analytic_meshes.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;

FeatureOptions smallOptions(const fs::path& cache) {
  FeatureOptions o;
  o.resolution = 16;
  o.views = 24;
  o.renderSize = 48;
  o.cacheDir = cache;
  return o;
}

fs::path writeBoxObj(const fs::path& dir) {
  const auto path = dir / "box.obj";
  exportMesh(test::box({-1, -0.5f, 0}, {1, 0.5f, 0.5f}), path);
  return path;
}

std::vector<fs::path> descriptorEntries(const fs::path& cache) {
  std::vector<fs::path> entries;
  for (const auto& e : fs::directory_iterator(cache))
    if (e.path().string().find(".descriptor.json") != std::string::npos)
      entries.push_back(e.path());
  return entries;
}

TEST(DescriptorCache, ComputesOnceThenReadsTheSmallEntryOnly) {
  const fs::path dir = test::freshTempDir();
  const fs::path mesh = writeBoxObj(dir);
  const auto options = smallOptions(dir / "cache");
  DescriptorSource source{};
  const auto computed = extractDescriptor(mesh, options, &source);
  EXPECT_EQ(source, DescriptorSource::Computed);
  EXPECT_EQ(computed.size(), static_cast<std::size_t>(kEmbeddedDescriptorSize));
  // Only the descriptor is stored, not the grid.
  ASSERT_EQ(descriptorEntries(options.cacheDir).size(), 1u);
  EXPECT_EQ(std::distance(fs::directory_iterator(options.cacheDir), fs::directory_iterator()), 1);

  const auto cached = extractDescriptor(mesh, options, &source);
  EXPECT_EQ(source, DescriptorSource::DescriptorCache);
  EXPECT_EQ(cached, computed);
  // The same as the full pipeline's descriptor.
  FeatureOptions full = options;
  full.cacheDir.clear();
  EXPECT_EQ(extractFeatures(mesh, full).descriptor, computed);
}

TEST(DescriptorCache, TakesTheDescriptorOfAFullFeatureEntryAndRewritesADamagedEntry) {
  const fs::path dir = test::freshTempDir();
  const fs::path mesh = writeBoxObj(dir);
  const auto options = smallOptions(dir / "cache");
  // annotate with the same cache: the features in the frame of the detected up axis
  FeatureOptions framed = options;
  framed.up = importMesh(mesh, ImportOptions(std::nullopt, /*detect=*/true)).fileUp;
  const auto grid = extractFeatures(mesh, framed);
  DescriptorSource source{};
  EXPECT_EQ(extractDescriptor(mesh, options, &source), grid.descriptor);
  EXPECT_EQ(source, DescriptorSource::FeatureCache);

  const auto entries = descriptorEntries(options.cacheDir);
  ASSERT_EQ(entries.size(), 1u);
  writeFileAtomic(entries[0], "{\"mesh_sha256\": \"x\", \"descr");  // truncated by hand
  for (const auto& e : fs::directory_iterator(options.cacheDir))
    if (e.path().extension() == ".npz") fs::remove(e.path());
  EXPECT_EQ(extractDescriptor(mesh, options, &source), grid.descriptor);
  EXPECT_EQ(source, DescriptorSource::Computed);
  EXPECT_EQ(extractDescriptor(mesh, options, &source), grid.descriptor);
  EXPECT_EQ(source, DescriptorSource::DescriptorCache);
}

// Makes the cache's one descriptor entry look written before it kept `key`; false when the cache
// does not hold exactly one entry.
bool eraseFromTheOnlyEntry(const fs::path& cache, const std::string& key) {
  const auto entries = descriptorEntries(cache);
  if (entries.size() != 1) return false;
  auto j = nlohmann::json::parse(readFileBytes(entries[0]));
  j.erase(key);
  writeFileAtomic(entries[0], j.dump());
  return true;
}

TEST(DescriptorCache, KeepsTheTopReliefAndRewritesEntriesWrittenWithoutIt) {
  const fs::path dir = test::freshTempDir();
  const fs::path mesh = writeBoxObj(dir);
  const auto options = smallOptions(dir / "cache");
  FeatureOptions uncached = options;
  uncached.cacheDir.clear();
  const auto grid = extractFeatures(mesh, uncached);
  DescriptorSource source{};
  const auto first = extractObjectDescriptor(mesh, options, &source);
  EXPECT_EQ(source, DescriptorSource::Computed);
  EXPECT_EQ(first.topRelief, topRelief(grid.voxels, grid.resolution));
  EXPECT_GT(first.topRelief[0], 0.5f);  // a box: mostly flat lid
  const auto cached = extractObjectDescriptor(mesh, options, &source);
  EXPECT_EQ(source, DescriptorSource::DescriptorCache);
  EXPECT_EQ(cached.topRelief, first.topRelief);

  // An entry of the earlier format (descriptor only) serves the descriptor alone, and is
  // computed again and rewritten when the relief is asked for.
  ASSERT_TRUE(eraseFromTheOnlyEntry(options.cacheDir, "top_relief"));
  EXPECT_EQ(extractDescriptor(mesh, options, &source), first.descriptor);
  EXPECT_EQ(source, DescriptorSource::DescriptorCache);
  extractObjectDescriptor(mesh, options, &source, /*needTopRelief=*/false);
  EXPECT_EQ(source, DescriptorSource::DescriptorCache);
  EXPECT_EQ(extractObjectDescriptor(mesh, options, &source).topRelief, first.topRelief);
  EXPECT_EQ(source, DescriptorSource::Computed);
  extractObjectDescriptor(mesh, options, &source);
  EXPECT_EQ(source, DescriptorSource::DescriptorCache);
}

TEST(DescriptorCache, KeepsThePartStatisticsAndRewritesEntriesWrittenWithoutThem) {
  const fs::path dir = test::freshTempDir();
  const fs::path mesh = writeBoxObj(dir);
  const auto options = smallOptions(dir / "cache");
  DescriptorSource source{};
  const auto first = extractObjectDescriptor(mesh, options, &source);
  EXPECT_EQ(source, DescriptorSource::Computed);
  ASSERT_TRUE(first.hasPartStatistics);
  EXPECT_EQ(first.partStatistics,
            partStatistics(importMesh(mesh, ImportOptions(std::nullopt, /*detect=*/true))));
  const auto cached = extractObjectDescriptor(mesh, options, &source);
  EXPECT_EQ(source, DescriptorSource::DescriptorCache);
  EXPECT_TRUE(cached.hasPartStatistics);
  EXPECT_EQ(cached.partStatistics, first.partStatistics);

  // An entry written before entries kept them serves whoever does not need them, and is
  // computed again and rewritten for whoever does.
  ASSERT_TRUE(eraseFromTheOnlyEntry(options.cacheDir, "part_statistics"));
  const auto without = extractObjectDescriptor(mesh, options, &source, /*needTopRelief=*/true,
                                               /*needPartStatistics=*/false);
  EXPECT_EQ(source, DescriptorSource::DescriptorCache);
  EXPECT_FALSE(without.hasPartStatistics);
  EXPECT_EQ(extractObjectDescriptor(mesh, options, &source).partStatistics, first.partStatistics);
  EXPECT_NE(source, DescriptorSource::DescriptorCache);
  EXPECT_TRUE(extractObjectDescriptor(mesh, options, &source).hasPartStatistics);
  EXPECT_EQ(source, DescriptorSource::DescriptorCache);
}

TEST(DescriptorCache, ReadsAFileInTheFrameOfItsDetectedUpAxisLikeAnnotate) {
  const fs::path dir = test::freshTempDir();
  // A counter-like slab written y-up: wide in x and z (the file's floor plane), low in y.
  Mesh slab = test::box({-1, 0, -0.5f}, {1, 0.3f, 0.5f});
  const fs::path file = dir / "slab_yup.obj";
  exportMesh(slab, file);
  const auto options = smallOptions(dir / "cache");
  const Mesh detected = importMesh(file, ImportOptions(std::nullopt, /*detect=*/true));
  ASSERT_EQ(detected.fileUp, UpAxis::Y);  // else this test would not tell the frames apart
  FeatureOptions framed = options;
  framed.cacheDir.clear();
  framed.up = detected.fileUp;
  EXPECT_EQ(extractDescriptor(file, options), extractFeatures(file, framed).descriptor);
  DescriptorSource source{};
  EXPECT_EQ(extractDescriptor(file, options, &source), extractFeatures(file, framed).descriptor);
  EXPECT_EQ(source, DescriptorSource::DescriptorCache);
  // An explicit axis is taken as given.
  FeatureOptions zUp = options;
  zUp.up = UpAxis::Z;
  FeatureOptions zUpUncached = zUp;
  zUpUncached.cacheDir.clear();
  EXPECT_EQ(extractDescriptor(file, zUp), extractFeatures(file, zUpUncached).descriptor);
}

}  // namespace
}  // namespace sagrid
