#include "core/corpus/sweethome3d_corpus.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/common/ascii_case.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/sha256.h"
#include "core/common/staged_folder.h"
#include "core/io/zip_archive.h"
#include "core/labels/labels.h"

namespace sagrid {
namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

constexpr const char* kPluginCatalog = "PluginFurnitureCatalog.properties";
constexpr const char* kDefaultCatalog =
    "com/eteks/sweethome3d/io/DefaultFurnitureCatalog.properties";

// ---- archive paths and references

// "a/b/../c" -> "a/c"; nullopt when the path is absolute or climbs above the archive root.
std::optional<std::string> normalizeArchivePath(std::string path) {
  std::replace(path.begin(), path.end(), '\\', '/');
  if (path.empty() || path.front() == '/' || (path.size() >= 2 && path[1] == ':'))
    return std::nullopt;
  std::vector<std::string> parts;
  std::stringstream stream(path);
  for (std::string part; std::getline(stream, part, '/');) {
    if (part.empty() || part == ".") continue;
    if (part == "..") {
      if (parts.empty()) return std::nullopt;
      parts.pop_back();
    } else {
      parts.push_back(part);
    }
  }
  std::string out;
  for (const auto& p : parts) out += (out.empty() ? "" : "/") + p;
  return out;
}

std::string directoryOf(const std::string& entry) {
  const auto at = entry.find_last_of('/');
  return at == std::string::npos ? std::string() : entry.substr(0, at + 1);
}

// File names an OBJ (mtllib) or MTL (map_*, bump, ...) refers to, as written.
std::vector<std::string> references(const std::string& text, bool isMtl) {
  std::vector<std::string> names;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream tokens(line);
    std::string keyword;
    tokens >> keyword;
    std::vector<std::string> rest;
    for (std::string t; tokens >> t;) rest.push_back(t);
    if (rest.empty()) continue;
    if (!isMtl && keyword == "mtllib") {
      names.insert(names.end(), rest.begin(), rest.end());
    } else if (isMtl) {
      const std::string k = asciiLower(keyword);
      if (k.rfind("map_", 0) == 0 || k == "bump" || k == "disp" || k == "decal" || k == "refl" ||
          k == "norm") {
        names.push_back(rest.back());  // options (-s 1 1 1, -bm 0.5 ...) come first
      }
    }
  }
  return names;
}

struct ObjectFiles {
  std::vector<std::pair<std::string, std::string>>
      files;  // name in the object folder, archive entry
  std::vector<std::string> warnings;
};

// Which archive entries make up an object. `root` is the object folder's prefix in the archive
// ("scopia/cooker/"); with `wholeFolder` every entry under it is taken (a plugin model's folder),
// else only the OBJ and what it references. References resolving outside `root` are refused.
ObjectFiles collectObjectFiles(const ZipArchive& zip, const std::string& objEntry,
                               const std::string& root, bool wholeFolder) {
  ObjectFiles result;
  std::set<std::string> taken;
  auto add = [&](const std::string& entry) {
    if (taken.insert(entry).second) result.files.emplace_back(entry.substr(root.size()), entry);
  };
  if (wholeFolder) {
    for (const ZipEntry& e : zip.entries()) {
      if (e.isDirectory() || e.name.rfind(root, 0) != 0) continue;
      const auto normal = normalizeArchivePath(e.name);
      if (!normal || *normal != e.name) {
        result.warnings.push_back("refused archive entry '" + e.name +
                                  "': not a plain relative path");
        continue;
      }
      add(e.name);
    }
  }
  add(objEntry);
  // Follow OBJ -> MTL -> textures, checking every reference.
  std::vector<std::pair<std::string, bool>> pending = {{objEntry, false}};
  std::set<std::string> visited;
  while (!pending.empty()) {
    const auto [entry, isMtl] = pending.back();
    pending.pop_back();
    if (!visited.insert(entry).second) continue;
    for (const std::string& ref : references(zip.read(entry), isMtl)) {
      const auto resolved = normalizeArchivePath(directoryOf(entry) + ref);
      const bool absolute = !ref.empty() && (ref.front() == '/' || ref.front() == '\\' ||
                                             (ref.size() >= 2 && ref[1] == ':'));
      if (absolute || !resolved || resolved->rfind(root, 0) != 0) {
        result.warnings.push_back("refused reference '" + ref + "' in " +
                                  entry.substr(root.size()) +
                                  ": it resolves outside the object folder");
        continue;
      }
      if (!zip.contains(*resolved)) {
        result.warnings.push_back("missing file '" + ref + "' referenced by " +
                                  entry.substr(root.size()));
        continue;
      }
      add(*resolved);
      if (!isMtl) pending.emplace_back(*resolved, true);
    }
  }
  return result;
}

// How many OBJ entries lie under `root` (at any depth).
std::size_t objEntriesUnder(const ZipArchive& zip, const std::string& root) {
  std::size_t count = 0;
  for (const ZipEntry& e : zip.entries()) {
    if (e.isDirectory() || e.name.rfind(root, 0) != 0 || e.name.size() < 4) continue;
    count += asciiLower(e.name.substr(e.name.size() - 4)) == ".obj";
  }
  return count;
}

// ---- shipped labels

struct ShippedLabels {
  fs::path dir;
  std::map<std::string, std::string> split;  // id -> "real-train" | "real-val"
  bool hasSplit = false;
};

ShippedLabels readShippedLabels(const fs::path& dir) {
  ShippedLabels shipped;
  shipped.dir = dir;
  const fs::path splitFile = dir / "split.json";
  if (dir.empty() || !fs::is_regular_file(splitFile)) return shipped;
  shipped.hasSplit = true;
  try {
    const auto j = nlohmann::json::parse(readFileBytes(splitFile));
    for (const char* name : {"real-train", "real-val"}) {
      if (!j.contains(name)) continue;
      for (const auto& id : j.at(name)) shipped.split[id.get<std::string>()] = name;
    }
  } catch (const nlohmann::json::exception& e) {
    throw FileError(splitFile, std::string("expected {\"real-train\":[ids],\"real-val\":[ids]} (") +
                                   e.what() + ")");
  }
  return shipped;
}

}  // namespace

std::vector<double> objVertexExtent(std::string_view text) {
  std::array<double, 3> low{}, high{};
  bool any = false;
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t end = text.find('\n', at);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(at, end - at);
    at = end + 1;
    if (line.size() < 2 || line[0] != 'v' || (line[1] != ' ' && line[1] != '\t')) continue;
    std::string copy(line.substr(2));
    const char* p = copy.c_str();
    char* next = nullptr;
    std::array<double, 3> v{};
    int count = 0;
    for (; count < 3; ++count) {
      v[count] = std::strtod(p, &next);
      if (next == p) break;
      p = next;
    }
    if (count < 3) continue;
    for (int k = 0; k < 3; ++k) {
      low[k] = any ? std::min(low[k], v[k]) : v[k];
      high[k] = any ? std::max(high[k], v[k]) : v[k];
    }
    any = true;
  }
  return {high[0] - low[0], high[1] - low[1], high[2] - low[2]};
}

double estimateMetersPerUnit(const std::vector<double>& catalogSizeCm,
                             const std::vector<double>& meshExtent) {
  std::vector<double> catalog = catalogSizeCm, mesh = meshExtent;
  std::sort(catalog.begin(), catalog.end());
  std::sort(mesh.begin(), mesh.end());
  std::vector<double> ratios;
  for (std::size_t i = 0; i < std::min(catalog.size(), mesh.size()); ++i) {
    // A flat side (a cooktop's thickness, a 2D decal) carries no scale.
    if (catalog[i] > 0 && mesh[i] > 1e-9 * mesh.back())
      ratios.push_back(catalog[i] / 100.0 / mesh[i]);
  }
  if (ratios.empty()) return 0;
  std::sort(ratios.begin(), ratios.end());
  const std::size_t n = ratios.size();
  return n % 2 ? ratios[n / 2] : 0.5 * (ratios[n / 2 - 1] + ratios[n / 2]);
}

CorpusSummary buildSweetHome3dCorpus(const SweetHome3dCorpusOptions& options) {
  if (options.out.empty()) throw InvalidArgument("corpus: --out is required");
  const ShippedLabels shipped = readShippedLabels(options.labelsDir);

  // Select every object first, so the progress total is known and nothing is written when a
  // catalog is unreadable.
  struct Pending {
    const SweetHome3dSource* source;
    std::shared_ptr<ZipArchive> zip;
    FurnitureCatalog catalog;  // library-level fields only are used from here
    FurnitureCatalogEntry entry;
    CorpusRole role;
    std::string id;
  };
  std::vector<Pending> pending;
  std::set<std::string> ids;
  CorpusSummary summary;
  std::vector<const SweetHome3dSource*> ordered;
  for (const auto& s : options.sources) ordered.push_back(&s);
  std::stable_sort(ordered.begin(), ordered.end(), [](const auto* a, const auto* b) {
    return std::make_pair(a->isJar, a->library) < std::make_pair(b->isJar, b->library);
  });
  for (const SweetHome3dSource* source : ordered) {
    auto zip = std::make_shared<ZipArchive>(ZipArchive::open(source->archive));
    const std::string catalogEntry = source->isJar ? kDefaultCatalog : kPluginCatalog;
    if (!zip->contains(catalogEntry)) {
      throw FileError(source->archive, std::string("holds no ") + catalogEntry +
                                           (source->isJar ? " (is it the Sweet Home 3D jar?)"
                                                          : " (is it a furniture library?)"));
    }
    FurnitureCatalog catalog = parseFurnitureCatalog(zip->read(catalogEntry),
                                                     source->archive.string() + ":" + catalogEntry);
    for (const auto& entry : catalog.entries) {
      const auto role = selectCorpusRole(entry);
      if (!role) continue;
      const std::string base = corpusObjectId(entry.id);
      std::string id = base;
      for (int n = 2; ids.count(id); ++n) id = base + "_" + std::to_string(n);
      ids.insert(id);
      FurnitureCatalog header = catalog;
      header.entries.clear();
      pending.push_back({source, zip, std::move(header), entry, *role, id});
    }
  }

  requireReplaceableFolder(options.out, "corpus.json");
  StagedFolder staged(options.out);
  const fs::path& temp = staged.path();
  std::map<std::string, std::string> manifests;  // dataset -> manifest.jsonl text
  for (const char* d : {"real-train", "real-val", "distractors", "unlabelled"}) {
    fs::create_directories(temp / d);
    manifests[d];
  }
  json byLibrary = json::object();
  std::map<std::string, std::string> packages;

  for (std::size_t i = 0; i < pending.size(); ++i) {
    const Pending& p = pending[i];
    if (options.progress) options.progress(i, pending.size(), p.id);
    CorpusObjectRecord record;
    record.id = p.id;
    record.library = p.source->library;
    record.catalogId = p.entry.id;
    record.name = p.entry.name;
    record.role = p.role;

    const auto objEntry = normalizeArchivePath(
        p.entry.model.rfind('/', 0) == 0 ? p.entry.model.substr(1) : p.entry.model);
    const std::string lowerModel = asciiLower(p.entry.model);
    if (!objEntry || lowerModel.size() < 4 ||
        lowerModel.compare(lowerModel.size() - 4, 4, ".obj") != 0 || !p.zip->contains(*objEntry)) {
      summary.warnings.push_back(p.id + ": skipped, model '" + p.entry.model +
                                 "' is not an OBJ entry of " +
                                 p.source->archive.filename().string());
      continue;
    }
    const std::string root = directoryOf(*objEntry);
    // A plugin model's folder is its own where it holds no other model; the jar's resources
    // folder and a library's top folder (the non-free Contributions keeps some models there,
    // beside every other model's folder) hold many.
    const bool wholeFolder =
        !p.source->isJar && !root.empty() && objEntriesUnder(*p.zip, root) == 1;
    ObjectFiles files = collectObjectFiles(*p.zip, *objEntry, root, wholeFolder);
    record.warnings = files.warnings;

    const std::string objBytes = p.zip->read(*objEntry);
    const std::string sha = sha256Hex(objBytes);
    const std::vector<double> extent = objVertexExtent(objBytes);
    std::vector<double> catalogSize;
    for (const auto& v : {p.entry.width, p.entry.depth, p.entry.height}) {
      if (v) catalogSize.push_back(*v);
    }
    record.metersPerUnit = estimateMetersPerUnit(catalogSize, extent);
    if (record.metersPerUnit <= 0)
      record.warnings.push_back("no usable size: meters_per_unit unknown");

    // Which dataset: shipped labels decide for stoves and sinks.
    const fs::path shippedLabels =
        shipped.dir.empty() ? fs::path() : shipped.dir / p.id / "labels.json";
    const bool labelled =
        p.role != CorpusRole::None && !shippedLabels.empty() && fs::is_regular_file(shippedLabels);
    if (p.role == CorpusRole::None) {
      record.dataset = "distractors";
    } else if (!labelled) {
      record.dataset = "unlabelled";
    } else if (const auto it = shipped.split.find(p.id); it != shipped.split.end()) {
      record.dataset = it->second;
    } else {
      record.dataset = "real-train";
      record.warnings.push_back(std::string("labelled but not listed in ") +
                                (shipped.hasSplit ? "split.json" : "a split.json (none found)") +
                                "; put in real-train");
    }

    const fs::path objectDir = temp / record.dataset / p.id;
    for (const auto& [name, entry] : files.files) {
      const fs::path target = objectDir / name;
      fs::create_directories(target.parent_path());
      writeFileAtomic(target, p.zip->read(entry));
    }
    const std::string meshName = objEntry->substr(root.size());
    record.mesh = p.id + "/" + meshName;

    if (labelled) {
      const ObjectLabels labels = readLabels(shippedLabels);
      if (labels.object.sha256 != sha) {
        throw FileError(shippedLabels,
                        "object " + p.id + ": object.sha256 " + labels.object.sha256 +
                            " does not match the extracted mesh " + meshName + " (" + sha +
                            "); the Sweet Home 3D package changed, so these labels need review");
      }
      writeFileAtomic(objectDir / "labels.json", readFileBytes(shippedLabels));
    } else if (p.role == CorpusRole::None) {
      ObjectLabels labels;
      labels.object.id = p.id;
      labels.object.mesh = meshName;
      labels.object.sha256 = sha;
      labels.object.category = "none";
      labels.object.up = "y";
      if (record.metersPerUnit > 0) labels.object.extra["meters_per_unit"] = record.metersPerUnit;
      labels.reviewState = ReviewState::Done;
      labels.reviewUpdated = currentUtcTimestamp();
      labels.extra["source"] = "sagrid corpus sweethome3d: appliance distractor, no affordances";
      writeLabels(objectDir / "labels.json", labels);
    }

    json provenance = json::object();
    provenance["package"] = p.source->package;
    provenance["package_version"] =
        p.source->packageVersion.empty() ? json(nullptr) : json(p.source->packageVersion);
    provenance["archive"] = p.source->archive.filename().string();
    provenance["library"] = p.source->library;
    if (!p.catalog.name.empty()) provenance["library_name"] = p.catalog.name;
    provenance["catalog_id"] = p.entry.id;
    provenance["name"] = p.entry.name;
    provenance["category"] = p.entry.category;
    provenance["creator"] = p.entry.creator;
    provenance["license"] = p.catalog.license.empty() ? json(nullptr) : json(p.catalog.license);
    provenance["path_in_archive"] = *objEntry;
    provenance["catalog_size_cm"] = {
        {"width", p.entry.width ? json(*p.entry.width) : json(nullptr)},
        {"depth", p.entry.depth ? json(*p.entry.depth) : json(nullptr)},
        {"height", p.entry.height ? json(*p.entry.height) : json(nullptr)}};
    if (p.entry.modelRotation) provenance["model_rotation"] = *p.entry.modelRotation;
    provenance["mesh"] = meshName;
    provenance["mesh_sha256"] = sha;
    provenance["mesh_extent"] = extent;
    provenance["up"] = "y";
    provenance["meters_per_unit"] =
        record.metersPerUnit > 0 ? json(record.metersPerUnit) : json(nullptr);
    provenance["role"] = toString(p.role);
    provenance["dataset"] = record.dataset;
    json fileList = json::array();
    for (const auto& f : files.files) fileList.push_back(f.first);
    provenance["files"] = fileList;
    provenance["warnings"] = record.warnings;
    writeFileAtomic(objectDir / "provenance.json", provenance.dump(2) + "\n");

    json line = {{"id", p.id},
                 {"category", toString(p.role)},
                 {"mesh", record.mesh},
                 {"labels", p.id + "/labels.json"}};
    manifests[record.dataset] += line.dump() + "\n";
    for (const auto& w : record.warnings) summary.warnings.push_back(p.id + ": " + w);
    ++summary.countsByRole[toString(p.role)];
    ++summary.countsByDataset[record.dataset];
    auto& lib = byLibrary[record.library];
    if (lib.is_null()) lib = {{"stove", 0}, {"sink", 0}, {"none", 0}};
    lib[toString(p.role)] = lib[toString(p.role)].get<int>() + 1;
    packages[p.source->package] = p.source->packageVersion;
    summary.objects.push_back(std::move(record));
  }
  if (options.progress) options.progress(pending.size(), pending.size(), "");
  // Shipped labels that match no extracted stove or sink: a renamed catalog id or a typo.
  std::set<std::string> used;
  for (const auto& r : summary.objects) {
    if (r.role != CorpusRole::None) used.insert(r.id);
  }
  if (!shipped.dir.empty() && fs::is_directory(shipped.dir)) {
    // Labels of a package this run did not read (object.provenance.package) are not orphans.
    auto ofPackageNotRead = [&](const std::string& id) {
      const fs::path file = shipped.dir / id / "labels.json";
      if (!fs::is_regular_file(file)) return false;
      const auto j = nlohmann::json::parse(readFileBytes(file), nullptr, false);
      if (j.is_discarded()) return false;
      const auto package = j.value("/object/provenance/package"_json_pointer, std::string());
      return !package.empty() && std::none_of(options.sources.begin(), options.sources.end(),
                                              [&](const SweetHome3dSource& source) {
                                                return source.package == package;
                                              });
    };
    std::vector<std::string> orphans;
    for (const auto& e : fs::directory_iterator(shipped.dir)) {
      const std::string id = e.path().filename().string();
      if (e.is_directory() && fs::is_regular_file(e.path() / "labels.json") && !used.count(id) &&
          !ofPackageNotRead(id)) {
        orphans.push_back(id);
      }
    }
    for (const auto& [id, split] : shipped.split) {
      if (!used.count(id) && !ofPackageNotRead(id)) orphans.push_back(id + " (in split.json)");
    }
    std::sort(orphans.begin(), orphans.end());
    for (const auto& id : orphans) {
      summary.warnings.push_back("shipped labels " + id + " match no extracted stove or sink");
    }
  }

  for (const auto& [dataset, text] : manifests)
    writeFileAtomic(temp / dataset / "manifest.jsonl", text);
  json corpus = json::object();
  corpus["source"] =
      "Debian sweethome3d-furniture and sweethome3d (Sweet Home 3D furniture catalogs)";
  json packageJson = json::object();
  for (const auto& [name, version] : packages)
    packageJson[name] = version.empty() ? json(nullptr) : json(version);
  corpus["packages"] = packageJson;
  corpus["counts_by_role"] = summary.countsByRole;
  corpus["counts_by_dataset"] = summary.countsByDataset;
  corpus["counts_by_library"] = byLibrary;
  json objects = json::array();
  for (const auto& r : summary.objects) {
    objects.push_back({{"id", r.id},
                       {"role", toString(r.role)},
                       {"dataset", r.dataset},
                       {"library", r.library},
                       {"catalog_id", r.catalogId},
                       {"name", r.name}});
  }
  corpus["objects"] = objects;
  corpus["warnings"] = summary.warnings;
  writeFileAtomic(temp / "corpus.json", corpus.dump(2) + "\n");

  staged.commit();
  return summary;
}

}  // namespace sagrid
