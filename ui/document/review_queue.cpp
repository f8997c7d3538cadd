#include "ui/document/review_queue.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <system_error>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/log.h"
#include "core/mesh/mesh_import.h"

namespace sagrid::ui {

namespace fs = std::filesystem;

const char* toString(QueueState state) {
  switch (state) {
    case QueueState::Accepted:
      return "accepted";
    case QueueState::Edited:
      return "edited";
    case QueueState::Skipped:
      return "skipped";
    case QueueState::InProgress:
      return "in progress";
    case QueueState::Unreviewed:
      break;
  }
  return "unreviewed";
}

QueueState parseQueueState(const std::string& text) {
  if (text == "accepted") return QueueState::Accepted;
  if (text == "edited") return QueueState::Edited;
  if (text == "skipped") return QueueState::Skipped;
  if (text == "in progress") return QueueState::InProgress;
  return QueueState::Unreviewed;
}

fs::path labelsPathFor(const fs::path& mesh) {
  const fs::path dir = mesh.parent_path();
  int meshes = 0;
  std::error_code ec;
  for (const auto& item : fs::directory_iterator(dir.empty() ? fs::path(".") : dir, ec)) {
    if (item.is_regular_file(ec) && isMeshFile(item.path())) ++meshes;
  }
  if (meshes <= 1) return dir / "labels.json";
  return dir / (mesh.stem().string() + ".labels.json");
}

namespace {

std::vector<fs::path> meshesIn(const fs::path& dir) {
  std::vector<fs::path> found;
  std::error_code ec;
  fs::directory_iterator it(dir, ec);
  if (ec) throw FileError(dir, "cannot list folder: " + ec.message());
  for (const auto& item : it) {
    if (item.is_regular_file(ec) && isMeshFile(item.path())) {
      found.push_back(item.path());
    } else if (item.is_directory(ec) && item.path().filename().string().front() != '.') {
      for (const auto& inner : fs::directory_iterator(item.path(), ec)) {
        if (inner.is_regular_file(ec) && isMeshFile(inner.path())) found.push_back(inner.path());
      }
    }
  }
  std::sort(found.begin(), found.end());
  return found;
}

// An entry's "geometry" in the state file; none where absent or damaged (an outline is only
// compared, so a damaged one just finds no twin; the object gets its outline again when opened).
std::optional<GeometryOutline> geometryIn(const nlohmann::json& item) {
  const auto it = item.find("geometry");
  if (it == item.end() || !it->is_object()) return std::nullopt;
  const auto triangles = it->find("triangles"), size = it->find("size");
  if (triangles == it->end() || !triangles->is_number_unsigned()) return std::nullopt;
  if (size == it->end() || !size->is_array() || size->size() != 3) return std::nullopt;
  GeometryOutline outline;
  outline.triangles = triangles->get<std::size_t>();
  for (int a = 0; a < 3; ++a) {
    if (!(*size)[std::size_t(a)].is_number()) return std::nullopt;
    outline.size[a] = (*size)[std::size_t(a)].get<double>();
  }
  return outline;
}

QueueEntry entryFor(const fs::path& mesh) {
  QueueEntry entry;
  entry.mesh = fs::absolute(mesh).lexically_normal();
  entry.labels = labelsPathFor(entry.mesh);
  entry.confidence = recordedObjectConfidence(entry.labels);
  return entry;
}

}  // namespace

std::optional<double> recordedObjectConfidence(const fs::path& labels) {
  std::error_code ec;
  if (!fs::is_regular_file(labels, ec)) return std::nullopt;
  try {
    const auto json = nlohmann::json::parse(readFileBytes(labels));
    const auto* prediction = json.is_object() && json.contains("prediction") ? &json["prediction"]
                                                                              : nullptr;
    if (prediction && prediction->is_object() && prediction->contains("object_confidence") &&
        (*prediction)["object_confidence"].is_number())
      return (*prediction)["object_confidence"].get<double>();
  } catch (const std::exception&) {
    // Unreadable labels are reported when the object is opened; here they just have no confidence.
  }
  return std::nullopt;
}

void ReviewQueue::setConfidence(std::size_t index, std::optional<double> confidence) {
  m_entries.at(index).confidence = confidence;
}

void ReviewQueue::orderLeastSureFirst() {
  if (m_entries.empty()) return;
  const fs::path current = m_entries.at(static_cast<std::size_t>(m_current)).mesh;
  std::stable_sort(m_entries.begin(), m_entries.end(), [](const QueueEntry& a, const QueueEntry& b) {
    return a.confidence.value_or(-1.0) < b.confidence.value_or(-1.0);
  });
  for (std::size_t i = 0; i < m_entries.size(); ++i)
    if (m_entries[i].mesh == current) m_current = static_cast<int>(i);
  save();
}

void ReviewQueue::setGeometry(std::size_t index, std::optional<GeometryOutline> geometry) {
  if (m_entries.at(index).geometry == geometry) return;
  m_entries.at(index).geometry = std::move(geometry);
  save();
}

std::vector<std::size_t> ReviewQueue::curatedTwinCandidatesOf(std::size_t index) const {
  std::vector<std::size_t> twins;
  const auto& geometry = m_entries.at(index).geometry;
  if (!geometry) return twins;
  for (std::size_t i = 0; i < m_entries.size(); ++i) {
    const QueueEntry& e = m_entries[i];
    const bool curated = e.state == QueueState::Accepted || e.state == QueueState::Edited ||
                         e.state == QueueState::InProgress;
    if (i != index && curated && e.geometry && sameOutline(*e.geometry, *geometry))
      twins.push_back(i);
  }
  return twins;
}

std::vector<std::size_t> ReviewQueue::unreviewedAtOrAbove(double threshold) const {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < m_entries.size(); ++i)
    if (m_entries[i].state == QueueState::Unreviewed && m_entries[i].confidence &&
        *m_entries[i].confidence >= threshold)
      out.push_back(i);
  return out;
}

ReviewQueue ReviewQueue::openFolder(const fs::path& dir) {
  ReviewQueue queue;
  for (const auto& mesh : meshesIn(dir)) queue.m_entries.push_back(entryFor(mesh));
  queue.m_stateFile = fs::absolute(dir).lexically_normal() / kQueueStateFile;
  queue.loadState();
  return queue;
}

ReviewQueue ReviewQueue::open(const std::vector<fs::path>& paths) {
  if (paths.size() == 1 && fs::is_directory(paths[0])) return openFolder(paths[0]);
  ReviewQueue queue;
  queue.add(paths);
  queue.m_current = 0;
  return queue;
}

void ReviewQueue::loadState() {
  std::error_code ec;
  if (!fs::exists(m_stateFile, ec)) return;
  try {
    const auto json = nlohmann::json::parse(readFileBytes(m_stateFile));
    const fs::path base = m_stateFile.parent_path();
    for (const auto& item : json.value("objects", nlohmann::json::array())) {
      const fs::path mesh = (base / item.at("mesh").get<std::string>()).lexically_normal();
      for (auto& entry : m_entries) {
        if (entry.mesh != mesh) continue;
        entry.state = parseQueueState(item.value("state", ""));
        entry.geometry = geometryIn(item);
      }
    }
    const std::string currentMesh = json.value("current", "");
    for (std::size_t i = 0; i < m_entries.size(); ++i) {
      if ((base / currentMesh).lexically_normal() == m_entries[i].mesh)
        m_current = static_cast<int>(i);
    }
  } catch (const nlohmann::json::exception& e) {
    // A damaged state file must not block review: start over, and say so.
    logger()->warn("{}: ignoring unreadable review state ({})", m_stateFile.string(), e.what());
  }
}

void ReviewQueue::save() const {
  if (m_stateFile.empty()) return;
  const fs::path base = m_stateFile.parent_path();
  nlohmann::json objects = nlohmann::json::array();
  for (const auto& entry : m_entries) {
    objects.push_back({{"mesh", entry.mesh.lexically_relative(base).generic_string()},
                       {"state", toString(entry.state)}});
    if (entry.geometry)
      objects.back()["geometry"] = {
          {"triangles", entry.geometry->triangles},
          {"size", {entry.geometry->size.x(), entry.geometry->size.y(), entry.geometry->size.z()}}};
  }
  nlohmann::json json = {{"schema", "sagrid.review-queue/1"}, {"objects", objects}};
  json["current"] =
      m_entries.empty()
          ? std::string()
          : m_entries[std::size_t(m_current)].mesh.lexically_relative(base).generic_string();
  writeFileAtomic(m_stateFile, json.dump(2) + "\n");
}

std::size_t ReviewQueue::reviewedCount() const {
  return static_cast<std::size_t>(
      std::count_if(m_entries.begin(), m_entries.end(),
                    [](const QueueEntry& e) {
                      return e.state != QueueState::Unreviewed && e.state != QueueState::InProgress;
                    }));
}

void ReviewQueue::setCurrent(int index) {
  if (m_entries.empty()) return;
  m_current = std::clamp(index, 0, static_cast<int>(m_entries.size()) - 1);
  save();
}

bool ReviewQueue::next() {
  if (m_current + 1 >= static_cast<int>(m_entries.size())) return false;
  setCurrent(m_current + 1);
  return true;
}

bool ReviewQueue::previous() {
  if (m_current <= 0) return false;
  setCurrent(m_current - 1);
  return true;
}

void ReviewQueue::setState(std::size_t index, QueueState state) {
  m_entries.at(index).state = state;
  save();
}

void ReviewQueue::setError(std::size_t index, std::string error) {
  m_entries.at(index).error = std::move(error);
}

int ReviewQueue::add(const std::vector<fs::path>& paths) {
  std::vector<fs::path> meshes;
  for (const auto& path : paths) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
      for (auto& m : meshesIn(path)) meshes.push_back(m);
    } else {
      meshes.push_back(path);  // unsupported files are queued too: opening them shows the error
    }
  }
  int first = -1;
  std::size_t insertAt = m_entries.empty() ? 0 : std::size_t(m_current) + 1;
  for (const auto& mesh : meshes) {
    QueueEntry entry = entryFor(mesh);
    auto existing = std::find_if(m_entries.begin(), m_entries.end(),
                                 [&](const QueueEntry& e) { return e.mesh == entry.mesh; });
    int index;
    if (existing != m_entries.end()) {
      index = static_cast<int>(existing - m_entries.begin());
    } else {
      m_entries.insert(m_entries.begin() + static_cast<long>(insertAt), std::move(entry));
      index = static_cast<int>(insertAt++);
    }
    if (first < 0) first = index;
  }
  save();
  return first;
}

}  // namespace sagrid::ui
