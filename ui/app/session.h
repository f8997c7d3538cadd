// The curator's session: the review queue, the open document, the camera and view settings, the
// type new points get, pending error messages, and the prediction worker. Panels and input
// handlers read it and call its actions; every point edit still goes through the document's
// commands (execute/undo/redo). Errors from core are caught here and queued for the modal.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/curation/curation_log.h"
#include "ui/app/control_edit.h"
#include "ui/app/prediction_worker.h"
#include "ui/app/recent_files.h"
#include "ui/document/annotation_document.h"
#include "ui/document/mass_estimate.h"
#include "ui/document/review_queue.h"
#include "ui/render/camera.h"
#include "ui/render/view_settings.h"

namespace sagrid::ui {

// Finds a prediction job for a document, or returns nothing when no model covers its category
// (the object then opens normally and points are placed by hand).
using PredictorLookup = std::function<std::optional<PredictionJob>(const AnnotationDocument&)>;

struct ViewportRect {
  float x = 0, y = 0, width = 1, height = 1;  // window coordinates
  bool contains(float px, float py) const {
    return px >= x && py >= y && px < x + width && py < y + height;
  }
};

// Units a curator set on another object of the source are not shown over the object's own size
// guess where only one unit fits its size and it is more than 2x from them (session_units.cpp).
bool carriedUnitsDisagree(double carried, const UnitGuess& own);

class Session {
 public:
  explicit Session(std::filesystem::path recentFilesPath = {});

  // Opening ------------------------------------------------------------------------------------
  void openPaths(const std::vector<std::filesystem::path>& paths);  // replaces the queue
  void addPaths(
      const std::vector<std::filesystem::path>& paths);  // drag-and-drop: adds, opens first
  // An object without curated labels whose geometry a curated object of the queue shares opens
  // with that object's points, category and units, to confirm (session_twin.cpp), not predicted.
  void openEntry(int index);
  // One object with an explicit labels file (sagrid render --labels, tests).
  void openObject(const std::filesystem::path& mesh, const std::filesystem::path& labels);
  bool next();
  bool previous();
  // N / P: next() or previous() as the curator's own move (logged as "navigate").
  bool navigate(int step);

  // Review ---------------------------------------------------------------------------------------
  // A: accepts the selected point; with none selected accepts every point, marks the object
  // accepted and moves on — one keypress for an object whose predictions are right.
  void accept();
  void skip();
  // "Accept automatically above X": every unreviewed queued object (not the open one) whose
  // prediction's confidence is at least `threshold` gets its predicted points accepted and its
  // review marked done in its labels.json. Returns how many.
  std::size_t acceptAutomaticallyAbove(double threshold);
  void orderQueueLeastSureFirst();
  double autoAcceptThreshold = 0.9;  // the queue panel's setting
  void execute(std::unique_ptr<Command> command);  // on the open document, with error handling
  void undo();
  void redo();
  void deleteSelected();
  // Deletes the selected point and every point of its type listed after it (a model's points are
  // listed most probable first, so these are the tail of a count that took too many): one
  // undoable step, logged as "delete_rest". Returns how many.
  int deleteRestOfSelected();
  // Adds the selected point's type on every copy of the part it lies on where no point of that
  // type is yet (pointsOnCopies): one undoable step, logged as "copies". Returns how many.
  int addOnCopiesOfSelected();
  // Adds the point one step past the selected one along its row (nextPointInRow: the step from
  // its nearest point of the type) and selects it, so E again goes on: one undoable step, logged
  // as "extend". Returns whether a point was added (else one error saying why not).
  bool extendRowOfSelected();
  void changeSelectedType(const std::string& type);
  // The types keys 1..9 choose, in order: the open object's category's own (its default models':
  // a stove's heatsource and togglebutton, a sink's fluidsource and togglebutton), then the other
  // known types; so 2 is a knob on a stove and on a sink alike.
  std::vector<std::string> typesForKeys() const;
  // Switches the open object's category (one undoable step) and, when its points are all still
  // predicted, drops them and predicts again for the new category. `how`: what the curation log
  // records (Category: the Object panel's list; CategoryKey: Shift+1..3). The suggested category
  // of a rejected object is taken as C takes it, with its points.
  void switchCategory(const std::string& category, CurationAction how = CurationAction::Category);
  // C: a rejected object's suggested category, taken with its suggested points (one undoable
  // step); nothing when the object has no suggestions.
  void confirmSuggestedCategory();
  void saveNow();
  // The open object's units set by the curator (one undoable step): `metersPerUnit` metres per
  // file unit, a finite number above 0, else one error naming it and nothing changed. Units the
  // curator sets are remembered per source (core/dataset/object_source.h: a repository, a
  // library): another object of that source whose units are only guessed opens with them, as a
  // guess that says so (a kit's files share their units, which the size guess cannot tell from
  // metres).
  bool setUnits(double metersPerUnit);

  // Curation log (issue 41): every curator action of this session, appended as JSON lines to
  // `path` (the GUI: curation.jsonl beside the dataset). Empty: no log.
  void setCurationLog(const std::filesystem::path& path, bool replayed = false);
  const std::optional<CurationLogWriter>& curationLog() const { return m_curationLog; }
  // An orbit, pan, zoom or close-up: logged as one "look" per gesture (repeats within a second
  // of the last, like the steps of a wheel or held arrow key, count once).
  void noteLook(const std::string& what);

  // View -----------------------------------------------------------------------------------------
  void frameObject();
  // The whole object from above, the front (-y) or the right (+x): keypad 7, 1, 3 and the View
  // menu (a top view took four to six arrow presses).
  enum class ViewSide { Top, Front, Right };
  void viewFrom(ViewSide side);
  // F: a close-up of the selected point (a tap on a 2 m counter fills the view); pressed again,
  // or with nothing selected, the whole object.
  void frameSelection();
  Camera& camera() { return m_camera; }
  const Camera& camera() const { return m_camera; }
  ViewSettings& view() { return m_view; }
  const ViewSettings& view() const { return m_view; }
  void setViewport(const ViewportRect& rect);
  const ViewportRect& viewport() const { return m_viewport; }

  // Prediction
  // -------------------------------------------------------------------------------------
  void setPredictorLookup(PredictorLookup lookup) { m_predictorLookup = std::move(lookup); }
  void runPrediction();  // no-op with a message when no model covers the category
  void cancelPrediction() { m_worker.cancel(); }
  const PredictionWorker& worker() const { return m_worker; }
  MassEstimate& massEstimate() { return m_massEstimate; }  // the Object panel's mass (export)
  bool autoPredict = true;
  // Whether the category classifier reads the words of the mesh file's name beside the shape, for
  // the predictions from now on (the Object panel's checkbox; `sagrid gui --no-file-name` starts
  // with it off): a collection named for something else than it holds is decided by the shape.
  bool categoryReadsFileName = true;
  void pollPrediction();  // applies a finished prediction (UI thread, once per frame)
  // Turns the object to another file up axis (an undoable command that drops the predicted
  // points of the old axis) and predicts again.
  void turnUpAxis(UpAxis up);

  // Export ---------------------------------------------------------------------------------------
  void exportCurrent(const std::string& format, const std::filesystem::path& outDir);
  void addCurrentToTrainingSet(const std::filesystem::path& datasetDir);

  // State
  // ------------------------------------------------------------------------------------------
  AnnotationDocument* document() { return m_document.get(); }
  const AnnotationDocument* document() const { return m_document.get(); }
  const ReviewQueue& queue() const { return m_queue; }
  const std::string& currentType() const { return m_currentType; }
  // Why the last prediction of the open object gave no points (the category was rejected), for
  // the object panel; empty otherwise.
  const std::string& predictionNote() const { return m_predictionNote; }
  void setCurrentType(const std::string& type) { m_currentType = type; }
  const RecentFiles& recent() const { return m_recent; }
  bool addModeArmed = false;  // next click on the surface adds a point
  PartBrush partBrush;        // while armed, clicks brush the selected control's part
  bool showHelp = false;
  bool showFileBrowser = false;
  bool screenshotRequested = false;  // F12: the app saves the next frame to a PNG
  std::filesystem::path trainingSetDir;
  bool readOnly = false;  // documents never write labels.json (previews, sagrid render)
  bool logErrors = true;  // false: errors only queue (sagrid render prints the one line itself)

  void reportError(const std::string& message);
  const std::vector<std::string>& pendingErrors() const { return m_errors; }
  void dismissError();

 private:
  // On opening an object: a new-point type its category has (see session.cpp).
  void chooseNewPointType();

  void updateQueueState();
  void applyDefaultFieldSettings();
  void logAction(CurationAction action, const std::string& detail = "", const std::string& carriedFrom = "");
  void applyCommand(std::unique_ptr<Command> command, bool logged);
  // The open object's source, empty where its labels and folder name none.
  std::string sourceOfOpenObject() const;
  // On opening: units the curator set for the object's source this session, where its own are
  // only guessed (session_units.cpp).
  void carryCuratedUnits();
  // On opening: records the object's geometry outline in the queue and, where the object has no
  // curated labels yet, starts it from the labels of a curated object of the same geometry (one
  // undoable step; session_twin.cpp). Returns that object's id, empty when nothing was carried.
  std::string carryTwinPoints();

  ReviewQueue m_queue;
  std::unique_ptr<AnnotationDocument> m_document;
  Camera m_camera;
  ViewSettings m_view;
  ViewportRect m_viewport;
  std::string m_currentType = "heatsource";
  std::string m_predictionNote;
  RecentFiles m_recent;
  std::vector<std::string> m_errors;
  PredictionWorker m_worker;
  PredictorLookup m_predictorLookup;
  MassEstimate m_massEstimate;
  std::optional<CurationLogWriter> m_curationLog;
  double m_lastLookSeconds = -1e9;
  std::map<std::string, double> m_curatedUnits;  // per source: the units the curator last set
  bool m_unitsCarried = false;  // the open object shows units carried from another of its source
};

}  // namespace sagrid::ui
