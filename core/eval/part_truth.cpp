#include "core/eval/part_truth.h"

#include <algorithm>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/sha256.h"
#include "core/controls/control_record.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh_import.h"

namespace sagrid {

PartTruth partTruthOf(const std::vector<DatasetEntry>& entries) {
  PartTruth truth;
  for (const DatasetEntry& entry : entries) {
    const ObjectLabels labels = readLabels(entry.labels);
    const UpAxis up = upAxisOrZ(labels.object.up);
    MarkedObject object;
    for (std::size_t i = 0; i < labels.affordances.size(); ++i) {
      const AffordancePoint& point = labels.affordances[i];
      if (point.type != "togglebutton") continue;
      const auto record = readControlRecord(point, up, entry.labels);  // validates it
      if (record && record->confirmed)
        object.controls[static_cast<int>(i) + 1] = point.extra.at(kControlField);
    }
    if (object.controls.empty()) continue;
    if (truth.objects.count(entry.id))
      throw FileError(entry.labels, "object folder " + entry.id + " is among the data twice");
    object.meshSha256 = sha256Hex(readFileBytes(entry.mesh));
    truth.objects[entry.id] = std::move(object);
  }
  return truth;
}

std::string partTruthText(const PartTruth& truth) {
  std::string text = "{\"objects\": {";
  const char* objectSeparator = "\n";
  for (const auto& [id, object] : truth.objects) {
    text += objectSeparator + nlohmann::json(id).dump() + ": {\"mesh_sha256\": " +
            nlohmann::json(object.meshSha256).dump() + ", \"points\": {";
    const char* pointSeparator = "\n  ";
    for (const auto& [point, control] : object.controls) {
      text += pointSeparator + nlohmann::json(std::to_string(point)).dump() + ": " + control.dump();
      pointSeparator = ",\n  ";
    }
    text += "}}";
    objectSeparator = ",\n";
  }
  return text + "\n}}\n";
}

PartTruth readPartTruth(const std::filesystem::path& file) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(readFileBytes(file, kMaxJsonFileBytes));
  } catch (const nlohmann::json::exception& e) {
    throw FileError(file, std::string("not JSON: ") + e.what());
  }
  if (!j.is_object() || !j.contains("objects") || !j["objects"].is_object())
    throw FileError(file, "not a part truth file: {\"objects\": {...}}");
  PartTruth truth;
  truth.file = file;
  for (const auto& [id, object] : j["objects"].items()) {
    if (!object.is_object() || !object.contains("mesh_sha256") || !object["mesh_sha256"].is_string() ||
        !object.contains("points") || !object["points"].is_object())
      throw FileError(file, "object " + id + ": needs \"mesh_sha256\" and \"points\"");
    MarkedObject marked;
    marked.meshSha256 = object["mesh_sha256"].get<std::string>();
    for (const auto& [point, control] : object["points"].items()) {
      // A point is a whole number from 1, written plainly (no sign, space or leading zero).
      const bool plain = !point.empty() && point.size() <= 6 && point[0] != '0' &&
                         std::all_of(point.begin(), point.end(), [](char c) { return c >= '0' && c <= '9'; });
      if (!plain) throw FileError(file, "object " + id + ": point \"" + point + "\" is no number from 1");
      if (!control.is_object())
        throw FileError(file, "object " + id + " point " + point + ": a control is an object");
      marked.controls[std::stoi(point)] = control;
    }
    if (marked.controls.empty()) throw FileError(file, "object " + id + ": no points");
    truth.objects[id] = std::move(marked);
  }
  return truth;
}

PartTruth readPartTruths(const std::vector<std::filesystem::path>& files) {
  PartTruth all;
  for (const auto& file : files) {
    PartTruth one = readPartTruth(file);
    for (auto& [id, object] : one.objects)
      if (!all.objects.emplace(id, std::move(object)).second)
        throw FileError(file, "object " + id + " is marked in " + all.file.string() + " too");
    all.file = all.file.empty() ? file : std::filesystem::path(all.file.string() + ", " + file.string());
  }
  return all;
}

}  // namespace sagrid
