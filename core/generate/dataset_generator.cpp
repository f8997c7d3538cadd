#include "core/generate/dataset_generator.h"

#include <cmath>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/sha256.h"
#include "core/generate/distractor_generator.h"
#include "core/generate/random.h"
#include "core/generate/realism.h"
#include "core/generate/sink_generator.h"
#include "core/generate/stove_generator.h"
#include "core/generate/wall_fixtures.h"
#include "core/mesh/mesh_export.h"

namespace sagrid::gen {

namespace fs = std::filesystem;

MeshFormat parseMeshFormat(const std::string& text) {
  if (text == "obj") return MeshFormat::Obj;
  if (text == "glb") return MeshFormat::Glb;
  if (text == "mixed") return MeshFormat::Mixed;
  throw InvalidArgument("unknown mesh format '" + text + "' (expected obj, glb or mixed)");
}

namespace {
GeneratedObject makeBareObject(const std::string& category, std::uint64_t seed, int index,
                               const GeneratorOptions& options) {
  Rng rng(deriveSeed(seed, category, static_cast<std::uint64_t>(index)));
  if (category == "stove") {
    StoveOptions stove;
    if (options.glassSlabHobs > 0.0) {
      Rng choice(deriveSeed(seed, category + "/glass_slab", static_cast<std::uint64_t>(index)));
      stove.glassSlab = choice.chance(options.glassSlabHobs);
    }
    return generateStove(rng, stove);
  }
  if (category == "sink") return generateSink(rng);
  if (category == kDistractorCategory) return generateDistractor(rng, options.applianceDistractors);
  throw InvalidArgument("unknown category '" + category + "' (expected stove, sink or none)");
}
}  // namespace

GeneratedObject makeRawObject(const std::string& category, std::uint64_t seed, int index,
                              const GeneratorOptions& options) {
  if (!(options.wallFixtures >= 0.0 && options.wallFixtures <= 1.0)) {
    throw InvalidArgument("the wall fixture share must be in [0, 1]");
  }
  if (!(options.glassSlabHobs >= 0.0 && options.glassSlabHobs <= 1.0)) {
    throw InvalidArgument("the glass hob share must be in [0, 1]");
  }
  GeneratedObject object = makeBareObject(category, seed, index, options);
  if (options.wallFixtures > 0.0 && acceptsWallFixtures(object)) {
    Rng rng(deriveSeed(seed, category + "/wall_fixtures", static_cast<std::uint64_t>(index)));
    if (rng.chance(options.wallFixtures)) addWallFixtures(object, rng);
  }
  return object;
}

namespace {
std::string objectId(const std::string& category, std::uint64_t seed, int index) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%s_s%llu_%05d", category.c_str(),
                static_cast<unsigned long long>(seed), index);
  return buffer;
}

// Rounds to 6 significant digits so labels read the same as the written mesh text.
float tidy(float v) {
  if (v == 0.0f || !std::isfinite(v)) return 0.0f;
  const double digits = 6 - std::ceil(std::log10(std::abs(static_cast<double>(v))));
  const double f = std::pow(10.0, digits);
  return static_cast<float>(std::round(v * f) / f);
}
}  // namespace

FinishedObject makeObject(const std::string& category, std::uint64_t seed, int index,
                          MeshFormat format, const GeneratorOptions& options) {
  GeneratedObject raw = makeRawObject(category, seed, index, options);
  // Realism has its own stream so shape choices do not shift when realism options change.
  Rng rng(deriveSeed(seed, category + "/realism", static_cast<std::uint64_t>(index)));
  const bool glb = format == MeshFormat::Glb || (format == MeshFormat::Mixed && rng.chance(0.5));
  const UpAxis up = glb ? UpAxis::Y : UpAxis::Z;
  const RealismResult realism = applyRealism(raw, rng, up);

  FinishedObject out;
  out.id = objectId(category, seed, index);
  out.category = category;
  out.meshFileName = glb ? "mesh.glb" : "mesh.obj";
  out.metersPerUnit = realism.metersPerUnit;

  ObjectLabels& labels = out.labels;
  labels.object.id = out.id;
  labels.object.mesh = out.meshFileName;
  labels.object.category = category;
  labels.object.up = glb ? "y" : "z";
  labels.object.extra["units"] = realism.units;
  labels.object.extra["meters_per_unit"] = realism.metersPerUnit;
  nlohmann::json generator = raw.generator;
  generator["version"] = kGeneratorVersion;
  generator["seed"] = seed;
  generator["index"] = index;
  generator["realism"] = realism.record;
  generator["triangles"] = raw.mesh.triangleCount();
  labels.object.extra["generator"] = generator;
  for (const auto& g : raw.points) {
    AffordancePoint p;
    p.type = g.type;
    const Eigen::Vector3f pos = zUpToFile(g.position, up);
    const Eigen::Vector3f nrm = zUpToFile(g.normal, up).normalized();
    p.position = Eigen::Vector3f(tidy(pos.x()), tidy(pos.y()), tidy(pos.z()));
    p.normal = Eigen::Vector3f(tidy(nrm.x()), tidy(nrm.y()), tidy(nrm.z()));
    p.status = AffordanceStatus::Accepted;
    p.source = std::string("sagrid.generate@") + kGeneratorVersion;
    labels.affordances.push_back(p);
  }
  labels.reviewState = ReviewState::Done;
  out.mesh = std::move(raw.mesh);
  return out;
}

ManifestLine writeDatasetObject(FinishedObject& object, const fs::path& outDir) {
  const fs::path dir = outDir / object.id;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw FileError(dir, "cannot create directory: " + ec.message());
  if (object.meshFileName == "mesh.glb") {
    const std::string bytes = encodeGlb(object.mesh);
    object.labels.object.sha256 = sha256Hex(bytes);
    writeFileAtomic(dir / object.meshFileName, bytes);
  } else {
    const EncodedMeshFiles files = encodeObj(object.mesh, "mesh");
    object.labels.object.sha256 = sha256Hex(files.mainBytes());
    writeEncodedMeshFiles(files, dir);
  }
  writeLabels(dir / "labels.json", object.labels);
  return {object.id, object.category, object.id + "/" + object.meshFileName, object.id + "/labels.json"};
}

void writeManifest(const std::vector<ManifestLine>& lines, const fs::path& outDir) {
  std::string manifest;
  for (const auto& l : lines) {
    nlohmann::json j = {{"id", l.id}, {"category", l.category}, {"mesh", l.mesh}, {"labels", l.labels}};
    manifest += j.dump() + "\n";
  }
  writeFileAtomic(outDir / "manifest.jsonl", manifest);
}

std::vector<ManifestLine> generateDataset(const std::vector<GenerateRequest>& requests, MeshFormat format,
                                          const fs::path& outDir, const ProgressCallback& progress) {
  for (const auto& r : requests) {
    if (r.category != "stove" && r.category != "sink" && r.category != kDistractorCategory) {
      throw InvalidArgument("unknown category '" + r.category + "' (expected stove, sink or none)");
    }
    if (r.count < 0) throw InvalidArgument("--count must be >= 0");
  }
  std::error_code ec;
  fs::create_directories(outDir, ec);
  if (ec) throw FileError(outDir, "cannot create directory: " + ec.message());
  int total = 0;
  for (const auto& r : requests) total += r.count;
  std::vector<ManifestLine> lines;
  int done = 0;
  for (const auto& r : requests) {
    for (int i = 0; i < r.count; ++i) {
      FinishedObject object = makeObject(r.category, r.seed, i, format, r.options);
      lines.push_back(writeDatasetObject(object, outDir));
      ++done;
      if (progress) progress(done, total);
    }
  }
  writeManifest(lines, outDir);
  return lines;
}

const std::vector<BenchSplit>& benchPreset() {
  static const std::vector<BenchSplit> preset = {
      {"train", {{"stove", 200, 1001}, {"sink", 200, 1002}}},
      {"val", {{"stove", 50, 2001}, {"sink", 50, 2002}}},
  };
  return preset;
}

const std::vector<BenchSplit>& distractorPreset() {
  // Seeds of their own: the bench split's streams are untouched.
  static const std::vector<BenchSplit> preset = {
      {"train", {{kDistractorCategory, 150, 3001}}},
      {"val", {{kDistractorCategory, 50, 4001}}},
  };
  return preset;
}

const std::vector<BenchSplit>& applianceDistractorPreset() {
  GeneratorOptions appliances;
  appliances.applianceDistractors = true;
  static const std::vector<BenchSplit> preset = {
      {"train", {{kDistractorCategory, 150, 3001, appliances}}},
      {"val", {{kDistractorCategory, 50, 4001, appliances}}},
  };
  return preset;
}

const std::vector<BenchSplit>& wallFixturePreset() {
  static const std::vector<BenchSplit> preset = {
      {"wall-fixtures", {{"sink", 300, 5001, GeneratorOptions{0.8}}}},
  };
  return preset;
}

const std::vector<BenchSplit>& glassHobPreset() {
  static const std::vector<BenchSplit> preset = {
      {"glass-hobs", {{"stove", 300, 6001, GeneratorOptions{0.0, 0.5}}}},
  };
  return preset;
}

const std::vector<BenchSplit>& decisionPreset() {
  static const std::vector<BenchSplit> preset = {
      {"decision",
       {{"stove", 40, 8101}, {"sink", 40, 8102}, {"stove", 40, 8110, GeneratorOptions{0.0, 0.5}}}},
  };
  return preset;
}

void generatePreset(const std::vector<BenchSplit>& preset, const fs::path& outDir,
                    const ProgressCallback& progress) {
  int total = 0;
  for (const auto& split : preset)
    for (const auto& r : split.requests) total += r.count;
  int offset = 0;
  for (const auto& split : preset) {
    int splitCount = 0;
    for (const auto& r : split.requests) splitCount += r.count;
    generateDataset(split.requests, MeshFormat::Mixed, outDir / split.name, [&](int done, int) {
      if (progress) progress(offset + done, total);
    });
    offset += splitCount;
  }
}

void generateBenchPreset(const fs::path& outDir, const ProgressCallback& progress) {
  generatePreset(benchPreset(), outDir, progress);
}

}  // namespace sagrid::gen
