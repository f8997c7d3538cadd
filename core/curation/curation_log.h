// The curation log (issue 41): every action a curator takes in the GUI, appended as one JSON line
// to a log beside the dataset ({"time", "seconds", "object", "action", "detail"}, and on an open
// whose points were carried from an object of the same geometry "carried_from"), so curator
// throughput is measured from what people did, not estimated from evaluations. The GUI writes it
// (ui/app/session.cpp); `sagrid eval --curation LOG` reads it (curation_report.h).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sagrid {

enum class CurationAction {
  Open,       // an object shown (by a move through the queue, a click in the queue, a file)
  Look,       // one orbit, pan or zoom gesture, or a close-up
  Accept,     // the selected point accepted
  AcceptAll,  // every point accepted and the object done (one key)
  Drag,       // a point moved
  Add,        // a point added
  Delete,     // a point deleted
  DeleteRest,  // the selected point and every point of its type after it deleted (one key)
  Copies,     // the selected point carried onto every copy of its part (core/geometry/points_on_copies.h)
  Extend,     // a point one step past the selected one along its row (ui/document/point_row.h)
  Retype,     // a point's type changed
  Category,   // the object's category switched from the Object panel's list
  CategoryKey,  // the object's category switched by its key (Shift+1 stove, Shift+2 sink, Shift+3 none)
  ConfirmCategory,  // the suggested category of a rejected object taken, with its points (one key)
  Units,      // the object's units set
  Edit,       // another edit (mass, up axis)
  Undo,
  Redo,
  Skip,       // the object skipped
  Navigate,   // next / previous object without accepting
};

const char* toString(CurationAction action);
std::optional<CurationAction> parseCurationAction(const std::string& text);
const std::vector<CurationAction>& allCurationActions();

struct CurationEvent {
  double seconds = 0;  // since the Unix epoch, millisecond resolution
  std::string object;  // the object's id (labels' object.id, else the mesh file's stem)
  CurationAction action = CurationAction::Open;
  std::string detail;  // e.g. the command's description
  bool replayed = false;  // taken by `sagrid replay-curation`, not a person: its times are the machine's
  // An open whose points were carried from this object of the same geometry, not predicted.
  std::string carriedFrom;
};

// Appends events to a log file, one flushed line each, so a crash loses at most the line being
// written. A log that cannot be written (read-only folder, full disk) turns the writer off after
// one warning returned to the caller; curation itself goes on.
class CurationLogWriter {
 public:
  explicit CurationLogWriter(std::filesystem::path path, bool replayed = false)
      : m_path(std::move(path)), m_replayed(replayed) {}
  // Returns an error message the first time a write fails, else empty. `carriedFrom`: see
  // CurationEvent (written only when not empty).
  std::string record(const std::string& object, CurationAction action, const std::string& detail = "",
                     const std::string& carriedFrom = "");
  const std::filesystem::path& path() const { return m_path; }

 private:
  std::filesystem::path m_path;
  bool m_replayed = false;
  bool m_failed = false;
};

// Reads a log. Throws FileError naming the file and line for a line that is not an event.
std::vector<CurationEvent> readCurationLog(const std::filesystem::path& path);

}  // namespace sagrid
