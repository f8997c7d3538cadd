// The review queue: the objects of a folder (or the files given on the command line) with each
// one's review state and the position the curator reached. A folder's queue state lives in
// DIR/.sagrid-review.json (atomic writes), so reopening the folder resumes where it stopped.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/mesh/geometry_identity.h"

namespace sagrid::ui {

// Accepted: every point accepted as predicted; Edited: finished (A) after hand edits; InProgress:
// edited by hand but not finished yet (not counted as reviewed); Skipped: passed over on purpose.
enum class QueueState { Unreviewed, InProgress, Accepted, Edited, Skipped };
const char* toString(QueueState state);
QueueState parseQueueState(const std::string& text);  // unknown text -> Unreviewed

struct QueueEntry {
  std::filesystem::path mesh;
  std::filesystem::path labels;  // where its labels.json is read and autosaved
  QueueState state = QueueState::Unreviewed;
  std::string error;  // last load error, shown in the queue (the queue goes on)
  // P(right with one key) of its prediction (labels' prediction.object_confidence), when predicted.
  std::optional<double> confidence;
  // Its mesh's geometry outline (triangle count and box size), known once the object was
  // opened (kept in the state file), so an object opened later finds its curated twins'
  // candidates without importing anything; only a candidate's mesh is imported, to confirm it.
  std::optional<GeometryOutline> geometry;
};

// The object confidence a labels.json records (prediction.object_confidence); nullopt when the file
// is missing, unreadable or has none (an unreadable file is reported when the object is opened).
std::optional<double> recordedObjectConfidence(const std::filesystem::path& labels);

inline constexpr const char* kQueueStateFile = ".sagrid-review.json";

// labels.json beside the mesh when the mesh is alone in its folder (the dataset layout), else
// <stem>.labels.json, so loose meshes in one folder never share a labels file.
std::filesystem::path labelsPathFor(const std::filesystem::path& mesh);

class ReviewQueue {
 public:
  ReviewQueue() = default;
  // Mesh files in DIR and in its direct subfolders (DIR/<id>/mesh.*), sorted by path; merges the
  // saved states and position of DIR/.sagrid-review.json. Throws FileError if DIR is unreadable.
  static ReviewQueue openFolder(const std::filesystem::path& dir);
  // Loose files and folders in the order given (folders expand as openFolder, without state file
  // unless a single folder is given).
  static ReviewQueue open(const std::vector<std::filesystem::path>& paths);

  bool empty() const { return m_entries.empty(); }
  std::size_t size() const { return m_entries.size(); }
  const std::vector<QueueEntry>& entries() const { return m_entries; }
  const QueueEntry& entry(std::size_t i) const { return m_entries.at(i); }
  int current() const { return m_current; }
  std::size_t reviewedCount() const;  // entries accepted, edited or skipped (the k of k/n)

  void setCurrent(int index);  // clamps; saves
  bool next();                 // false at the end
  bool previous();
  void setState(std::size_t index, QueueState state);  // saves
  void setError(std::size_t index, std::string error);
  void setConfidence(std::size_t index, std::optional<double> confidence);
  void setGeometry(std::size_t index, std::optional<GeometryOutline> geometry);  // saves on change
  // The other entries a curator accepted, edited or began whose outline is `index`'s (sameOutline):
  // candidate twins, to be confirmed on their meshes (matchGeometry).
  std::vector<std::size_t> curatedTwinCandidatesOf(std::size_t index) const;
  // Least sure first: objects without a prediction, then by increasing confidence (stable); the
  // current object stays current. Saves.
  void orderLeastSureFirst();
  // Unreviewed entries whose confidence is at least `threshold` ("accept automatically above X").
  std::vector<std::size_t> unreviewedAtOrAbove(double threshold) const;
  // Adds files (drag-and-drop, File -> Open) after the current entry; returns the first new index
  // or -1 when none was a mesh. Paths already queued are not added twice (their index is returned).
  int add(const std::vector<std::filesystem::path>& paths);

  void addEntry(QueueEntry entry) { m_entries.push_back(std::move(entry)); }

  const std::filesystem::path& stateFile() const { return m_stateFile; }
  void save() const;  // no-op without a state file

 private:
  void loadState();

  std::vector<QueueEntry> m_entries;
  int m_current = 0;
  std::filesystem::path m_stateFile;
};

}  // namespace sagrid::ui
