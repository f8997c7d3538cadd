#include "ui/app/session.h"

#include <algorithm>
#include <chrono>

#include "core/annotate/category_classifier.h"
#include "core/annotate/suggested_points.h"
#include "core/common/error.h"
#include "core/common/joined.h"
#include "core/common/log.h"
#include "core/export/mjcf_export.h"
#include "core/export/omnigibson_export.h"
#include "core/export/training_set.h"
#include "core/training/dataset_training.h"
#include "ui/document/category_commands.h"
#include "ui/document/object_loader.h"
#include "ui/document/point_commands.h"
#include "ui/document/point_copies.h"
#include "ui/document/point_row.h"
#include "ui/document/twin_points.h"
#include "ui/document/up_axis_commands.h"
#include "ui/render/type_colors.h"

namespace {
double nowSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

namespace sagrid::ui {

namespace {
// "; by its shape alone: a sink" where the file's name changed the category, else nothing.
std::string byShapeAlone(const PredictionResult& result) {
  if (result.categoryByShapeAlone.empty()) return "";
  return "; by its shape alone: " + (result.categoryByShapeAlone == kRejectedCategory
                                         ? std::string("not a known category")
                                         : "a " + result.categoryByShapeAlone);
}
}  // namespace

namespace fs = std::filesystem;

Session::Session(fs::path recentFilesPath) : m_recent(std::move(recentFilesPath)) {}

void Session::reportError(const std::string& message) {
  if (logErrors) logger()->error("{}", message);
  m_errors.push_back(message);
}

void Session::dismissError() {
  if (!m_errors.empty()) m_errors.erase(m_errors.begin());
}

void Session::openPaths(const std::vector<fs::path>& paths) {
  try {
    m_queue = ReviewQueue::open(paths);
  } catch (const Error& e) {
    reportError(e.what());
    return;
  }
  for (const auto& p : paths) m_recent.add(p);
  if (m_queue.empty()) {
    reportError(
        "no meshes found in the given paths (supported: glb, gltf, obj, fbx, ply, stl, off, dae, "
        "3ds)");
    m_document.reset();
    return;
  }
  openEntry(m_queue.current());
}

void Session::addPaths(const std::vector<fs::path>& paths) {
  int first = -1;
  try {
    first = m_queue.add(paths);
  } catch (const Error& e) {
    reportError(e.what());
    return;
  }
  for (const auto& p : paths) m_recent.add(p);
  if (first >= 0) openEntry(first);
}

void Session::openObject(const fs::path& mesh, const fs::path& labels) {
  m_queue = ReviewQueue();
  QueueEntry entry;
  entry.mesh = mesh;
  entry.labels = labels;
  m_queue.addEntry(std::move(entry));
  openEntry(0);
}

void Session::openEntry(int index) {
  if (m_queue.empty()) return;
  m_worker.cancel();
  m_queue.setCurrent(index);
  const std::size_t i = static_cast<std::size_t>(m_queue.current());
  const QueueEntry& entry = m_queue.entry(i);
  m_document.reset();
  m_predictionNote.clear();
  try {
    m_document = openDocument(entry.mesh, entry.labels);
    m_document->setAutosave(!readOnly);
    m_queue.setError(i, "");
  } catch (const Error& e) {
    // The queue goes on: the entry shows its error, the curator moves to the next one.
    m_queue.setError(i, e.what());
    reportError(e.what());
    return;
  }
  logger()->info("opened {} ({} of {})", m_document->displayName(), i + 1, m_queue.size());
  const std::string carriedFrom = carryTwinPoints();
  logAction(CurationAction::Open, entry.mesh.filename().string(), carriedFrom);
  if (carriedFrom.empty()) carryCuratedUnits();  // a twin's units are this object's own
  else m_unitsCarried = false;
  chooseNewPointType();
  applyDefaultFieldSettings();
  frameObject();
  addModeArmed = false;
  if (autoPredict && carriedFrom.empty()) runPrediction();
}

bool Session::next() {
  if (m_queue.current() + 1 >= static_cast<int>(m_queue.size())) return false;
  openEntry(m_queue.current() + 1);
  return true;
}

bool Session::navigate(int step) {
  if (m_queue.empty()) return false;
  logAction(CurationAction::Navigate, step > 0 ? "next" : "previous");
  return step > 0 ? next() : previous();
}

bool Session::previous() {
  if (m_queue.current() <= 0) return false;
  openEntry(m_queue.current() - 1);
  return true;
}

void Session::execute(std::unique_ptr<Command> command) { applyCommand(std::move(command), true); }

void Session::applyCommand(std::unique_ptr<Command> command, bool logged) {
  if (!m_document) return;
  const CurationAction action = command->curationAction();
  const std::string what = command->description();
  try {
    m_document->execute(std::move(command));
  } catch (const Error& e) {
    reportError(e.what());
  }
  if (logged) logAction(action, what);
  if (logged && action == CurationAction::Units && m_document) {
    const std::string source = sourceOfOpenObject();
    if (!source.empty()) m_curatedUnits[source] = sagrid::metersPerUnit(m_document->labels());
  }
  updateQueueState();
}

void Session::undo() {
  if (!m_document) return;
  const bool carried = pointsCarriedFrom(m_document->labels()).has_value();
  try {
    if (m_document->undo()) logAction(CurationAction::Undo);
  } catch (const Error& e) {
    reportError(e.what());
  }
  updateQueueState();
  // The twin's points undone from an object that had none: the model's prediction instead.
  if (carried && !pointsCarriedFrom(m_document->labels()) && m_document->points().empty() && autoPredict)
    runPrediction();
}

void Session::redo() {
  if (!m_document) return;
  try {
    if (m_document->redo()) logAction(CurationAction::Redo);
  } catch (const Error& e) {
    reportError(e.what());
  }
  updateQueueState();
}

void Session::setCurationLog(const fs::path& path, bool replayed) {
  if (path.empty()) m_curationLog.reset();
  else m_curationLog.emplace(path, replayed);
}

void Session::logAction(CurationAction action, const std::string& detail, const std::string& carriedFrom) {
  if (!m_curationLog || !m_document) return;
  const std::string& id = m_document->labels().object.id;
  const std::string object = id.empty() ? m_document->meshPath().stem().string() : id;
  const std::string problem = m_curationLog->record(object, action, detail, carriedFrom);
  if (!problem.empty()) reportError(problem);
}

void Session::noteLook(const std::string& what) {
  const double now = nowSeconds();
  if (now - m_lastLookSeconds > 1.0) logAction(CurationAction::Look, what);
  m_lastLookSeconds = now;
}

void Session::confirmSuggestedCategory() {
  if (!m_document || !suggestedCategory(m_document->labels())) return;
  execute(SettleSuggestionsCommand::confirm());
  m_predictionNote.clear();
  chooseNewPointType();
}

void Session::switchCategory(const std::string& category, CurationAction how) {
  if (!m_document || m_document->labels().object.category == category) return;
  if (suggestedCategory(m_document->labels()) == category) {
    confirmSuggestedCategory();
    return;
  }
  const bool allPredicted = std::all_of(m_document->points().begin(), m_document->points().end(),
                                        [](const AffordancePoint& p) { return p.status == AffordanceStatus::Predicted; });
  const bool dropsPoints = allPredicted && !m_document->points().empty();
  std::vector<std::unique_ptr<Command>> steps;
  steps.push_back(std::make_unique<SetCategoryCommand>(category, how));
  if (dropsPoints) {
    steps.push_back(std::make_unique<ReplacePointsCommand>(std::vector<AffordancePoint>{},
                                                           "drop the points of the old category"));
  }
  execute(std::make_unique<CommandGroup>("Category " + category, std::move(steps)));
  // The old category's fields go with its points (the viewport showed them over an object left
  // with none); a new prediction brings its own.
  if (dropsPoints) m_document->setPredictedFields({});
  m_predictionNote.clear();
  chooseNewPointType();
  if (allPredicted && autoPredict) runPrediction();
}

void Session::accept() {
  if (!m_document) return;
  // A selected point still as predicted is accepted alone; one the curator already placed, moved
  // or accepted needs nothing, so A goes on as with none selected (no Esc first after an edit).
  const int selected = m_document->selected();
  if (selected >= 0 &&
      m_document->points()[std::size_t(selected)].status == AffordanceStatus::Predicted) {
    execute(std::make_unique<AcceptPointCommand>(selected));
    return;
  }
  // Accepting a rejected object keeps "none": its suggested points go.
  if (suggestedCategory(m_document->labels())) applyCommand(SettleSuggestionsCommand::drop(), false);
  auto all = makeAcceptAllCommand(m_document->labels());
  if (!all->empty()) applyCommand(std::move(all), false);
  logAction(CurationAction::AcceptAll);
  try {
    m_document->setReviewState(ReviewState::Done);
  } catch (const Error& e) {
    reportError(e.what());
  }
  if (!m_queue.empty()) {
    const auto state = m_document->editedByHand() ? QueueState::Edited : QueueState::Accepted;
    m_queue.setState(std::size_t(m_queue.current()), state);
  }
  next();
}

std::size_t Session::acceptAutomaticallyAbove(double threshold) {
  std::size_t accepted = 0;
  for (std::size_t i : m_queue.unreviewedAtOrAbove(threshold)) {
    if (static_cast<int>(i) == m_queue.current() && m_document) continue;  // open: the curator's
    const QueueEntry& entry = m_queue.entry(i);
    try {
      ObjectLabels labels = readLabels(entry.labels);
      for (auto& a : labels.affordances)
        if (a.status == AffordanceStatus::Predicted) a.status = AffordanceStatus::Accepted;
      labels.reviewState = ReviewState::Done;
      labels.reviewUpdated = currentUtcTimestamp();
      labels.reviewExtra["accepted_automatically_above"] = threshold;
      writeLabels(entry.labels, labels);
      m_queue.setState(i, QueueState::Accepted);
      ++accepted;
    } catch (const Error& e) {
      m_queue.setError(i, e.what());
      reportError(e.what());
    }
  }
  logger()->info("accepted {} object(s) automatically at confidence >= {:.2f}", accepted,
                 threshold);
  return accepted;
}

void Session::orderQueueLeastSureFirst() {
  try {
    m_queue.orderLeastSureFirst();
  } catch (const Error& e) {
    reportError(e.what());
  }
}

void Session::skip() {
  if (!m_document) return;
  logAction(CurationAction::Skip);
  try {
    m_document->setReviewState(ReviewState::Skipped);
  } catch (const Error& e) {
    reportError(e.what());
  }
  if (!m_queue.empty()) m_queue.setState(std::size_t(m_queue.current()), QueueState::Skipped);
  next();
}

void Session::deleteSelected() {
  if (m_document && m_document->selected() >= 0)
    execute(std::make_unique<DeletePointCommand>(m_document->selected()));
}

int Session::deleteRestOfSelected() {
  if (!m_document || m_document->selected() < 0) return 0;
  const int from = m_document->selected();
  const auto& points = m_document->points();
  const std::string type = points[std::size_t(from)].type;
  std::vector<std::unique_ptr<Command>> deletes;
  for (int i = static_cast<int>(points.size()) - 1; i >= from; --i)  // from the back
    if (points[std::size_t(i)].type == type) deletes.push_back(std::make_unique<DeletePointCommand>(i));
  const int deleted = static_cast<int>(deletes.size());
  execute(std::make_unique<CommandGroup>("Delete " + std::to_string(deleted) + " " + type +
                                             " points from the selected one on",
                                         std::move(deletes), CurationAction::DeleteRest));
  return deleted;
}

int Session::addOnCopiesOfSelected() {
  if (!m_document || m_document->selected() < 0) return 0;
  const AffordancePoint& source = m_document->points()[std::size_t(m_document->selected())];
  std::vector<std::unique_ptr<Command>> adds;
  for (AffordancePoint& point : pointsForCopies(*m_document, source))
    adds.push_back(std::make_unique<AddPointCommand>(std::move(point)));
  const int added = static_cast<int>(adds.size());
  if (added == 0) {
    reportError("no copy of the selected point's part without a " + source.type + " point");
    return 0;
  }
  const std::string what =
      "Copy " + source.type + " to " + std::to_string(added) + " alike parts";
  execute(std::make_unique<CommandGroup>(what, std::move(adds), CurationAction::Copies));
  return added;
}

bool Session::extendRowOfSelected() {
  if (!m_document || m_document->selected() < 0) return false;
  const int selected = m_document->selected();
  std::optional<AffordancePoint> next = nextPointInRow(*m_document, selected);
  if (!next) {
    reportError("no row to extend: the step from the nearest other " +
                m_document->points()[std::size_t(selected)].type +
                " point to the selected one must land on the object, where no point of its "
                "type is");
    return false;
  }
  execute(std::make_unique<AddPointCommand>(std::move(*next), CurationAction::Extend));
  return true;
}

namespace {
// The types of a category's default models (stove.heatsource, sink.fluidsource, ...), in order.
std::vector<std::string> categoryTypes(const std::string& category) {
  std::vector<std::string> types;
  for (const auto& name : defaultModelNames())
    if (name.rfind(category + ".", 0) == 0) types.push_back(name.substr(category.size() + 1));
  return types;
}

// The types new points of an object take: its category's, or, for an object judged "none" that
// carries suggestions, its likeliest category's (the points the curator adds before pressing C).
std::vector<std::string> objectTypes(const ObjectLabels& labels) {
  std::vector<std::string> types = categoryTypes(labels.object.category);
  if (types.empty())
    if (const auto suggested = suggestedCategory(labels)) types = categoryTypes(*suggested);
  return types;
}
}  // namespace

void Session::chooseNewPointType() {
  // Keep the curator's choice when this category has that type (a stove has no fluidsource);
  // else its first type.
  const std::vector<std::string> types = objectTypes(m_document->labels());
  if (types.empty() || std::find(types.begin(), types.end(), m_currentType) != types.end()) return;
  m_currentType = types.front();
}

std::vector<std::string> Session::typesForKeys() const {
  std::vector<std::string> types =
      m_document ? objectTypes(m_document->labels()) : std::vector<std::string>{};
  for (const auto& type : knownTypes())
    if (std::find(types.begin(), types.end(), type) == types.end()) types.push_back(type);
  return types;
}

void Session::changeSelectedType(const std::string& type) {
  m_currentType = type;
  if (m_document && m_document->selected() >= 0 &&
      m_document->points()[std::size_t(m_document->selected())].type != type) {
    execute(std::make_unique<ChangeTypeCommand>(m_document->selected(), type));
  }
}

void Session::saveNow() {
  if (!m_document) return;
  try {
    m_document->save();
    logger()->info("saved {}", m_document->labelsPath().string());
  } catch (const Error& e) {
    reportError(e.what());
  }
}

void Session::updateQueueState() {
  if (!m_document || m_queue.empty()) return;
  const std::size_t i = std::size_t(m_queue.current());
  if (m_document->editedByHand()) {
    // Reviewed once the curator says it is done (A); an object finished before and edited again
    // stays reviewed.
    const QueueState now = m_queue.entry(i).state;
    const QueueState state =
        now == QueueState::Accepted || now == QueueState::Edited ? QueueState::Edited : QueueState::InProgress;
    if (now != state) m_queue.setState(i, state);
  } else if (!m_document->points().empty() && m_document->allAccepted()) {
    if (m_queue.entry(i).state != QueueState::Accepted) m_queue.setState(i, QueueState::Accepted);
  }
}

void Session::frameObject() {
  if (m_document) m_camera.frame(m_document->mesh().bounds());
}

void Session::viewFrom(ViewSide side) {
  if (!m_document) return;
  constexpr float kHalfPi = 1.5707963f;
  const float yaw = side == ViewSide::Right ? 0.0f : -kHalfPi;
  const float pitch = side == ViewSide::Top ? kHalfPi : 0.0f;
  m_camera.frameFrom(m_document->mesh().bounds(), yaw, pitch);
  noteLook("view");
}

void Session::frameSelection() {
  if (!m_document) return;
  const int selected = m_document->selected();
  const Eigen::AlignedBox3f bounds = m_document->mesh().bounds();
  if (selected < 0) return frameObject();
  const Eigen::Vector3f point = m_document->pointInView(selected);
  // A box a tenth of the object's diagonal around the point (at least 5 cm where units are
  // known), unless the view already shows that close-up.
  const float diagonal = bounds.diagonal().norm();
  float half = 0.05f * diagonal;
  if (m_document->unitsKnown()) half = std::max(half, 0.025f / m_document->metersPerUnit());
  half = std::min(half, 0.5f * diagonal);
  const Eigen::Vector3f corner = Eigen::Vector3f::Constant(half);
  const Eigen::Vector3f low = point - corner, high = point + corner;
  const Eigen::AlignedBox3f closeUp(low, high);
  const bool alreadyClose = (m_camera.target() - point).norm() < 1e-3f * diagonal &&
                            m_camera.distance() < 0.5f * diagonal;
  if (alreadyClose) return frameObject();
  const float yaw = m_camera.yaw(), pitch = m_camera.pitch();
  m_camera.frame(closeUp);
  m_camera.set(m_camera.target(), m_camera.distance(), yaw, pitch);  // keep the viewing direction
}

void Session::setViewport(const ViewportRect& rect) {
  m_viewport = rect;
  m_camera.setViewport(std::max(1, int(rect.width)), std::max(1, int(rect.height)));
}

void Session::applyDefaultFieldSettings() {
  // Show the voxels within a quarter of the object's size, coloured over that range: the field
  // shows where the points are without hiding the mesh.
  const Eigen::Vector3f size = m_document->mesh().bounds().sizes();
  const float extent = std::max({size.x(), size.y(), size.z()});
  m_view.field.threshold = 0.25f * extent;
  m_view.field.colorMax = 0.25f * extent;
  m_view.field.typeMask = ~0u;
}

void Session::runPrediction() {
  if (!m_document) return;
  m_predictionNote.clear();
  std::optional<PredictionJob> job;
  if (m_predictorLookup) {
    try {
      job = m_predictorLookup(*m_document);
    } catch (const Error& e) {
      reportError(e.what());
      return;
    }
  }
  if (!job) {
    logger()->info(
        "{}: no model for category '{}': place the points by hand", m_document->displayName(),
        m_document->labels().object.category.empty() ? "unknown"
                                                     : m_document->labels().object.category);
    return;
  }
  m_worker.start(m_document->labelsPath().string(), std::move(*job));
}

void Session::turnUpAxis(UpAxis up) {
  if (!m_document || m_document->mesh().fileUp == up) return;
  if (m_worker.running()) m_worker.cancel();  // its points would be for the old axis
  try {
    m_document->execute(std::make_unique<TurnUpAxisCommand>(*m_document, up));
  } catch (const Error& e) {
    reportError(e.what());
    return;
  }
  frameObject();
  runPrediction();
}

void Session::pollPrediction() {
  auto outcome = m_worker.poll();
  if (!outcome) return;
  if (outcome->cancelled) {
    logger()->info("prediction cancelled");
    return;
  }
  if (!outcome->error.empty()) {
    reportError("prediction failed: " + outcome->error);
    return;
  }
  if (!m_document || outcome->objectKey != m_document->labelsPath().string()) return;  // moved on
  PredictionResult& result = *outcome->result;
  if (!m_queue.empty() && !result.rejected)
    m_queue.setConfidence(std::size_t(m_queue.current()), result.objectConfidence);
  if (m_document->labels().object.category.empty() && !result.category.empty()) {
    m_document->setCategory(result.category);
    chooseNewPointType();  // a sink's first type, not the previous stove's
  }
  // The object's own guess, unless units are known; over units carried from another object of
  // its source where only one unit fits its size, far from them (see carryCuratedUnits).
  if (result.units && (!m_document->unitsKnown() ||
                       (m_unitsCarried &&
                        carriedUnitsDisagree(m_document->metersPerUnit(), *result.units)))) {
    m_document->setUnitGuess(*result.units);
    m_unitsCarried = false;
  }
  if (result.rejected) {
    // Opened as "none"; its likeliest category's points, if any, are suggestions: C takes them.
    const std::string points = result.points.empty()
                                   ? "no points"
                                   : "its points are suggestions: C takes " + result.closestCategory + ", A keeps none";
    m_predictionNote =
        result.rejectedByEvidence
            ? "shaped like a " + result.closestCategory + ", but the " + result.closestCategory +
                  " models find none of its parts on it: " + points
            : "not a known category (closest: " + result.closestCategory + "): " + points;
    if (!result.categoryNameWords.empty())
      m_predictionNote += " (read from its file's name too: " + joined(result.categoryNameWords) +
                          byShapeAlone(result) + ")";
    logger()->info("{}: {}; pick the category and run SAGrid, or place the points by hand",
                   m_document->displayName(), m_predictionNote);
  } else if (!result.categoryByShapeAlone.empty()) {
    // Filed by its name where its shape says otherwise: where a misleading name errs.
    m_predictionNote = "filed as a " + result.category + " by its file's name (" +
                       joined(result.categoryNameWords) + byShapeAlone(result) + ")";
  }
  // Predictions fill an object with no points yet; existing (reviewed) points are never replaced.
  if (m_document->points().empty() && !result.points.empty()) {
    try {
      // With edits applied (e.g. a turned up axis) the prediction is one more undoable step;
      // otherwise (none, or all undone: a twin's carried points) it is the starting point of the
      // review.
      if (m_document->canUndo()) {
        m_document->execute(
            std::make_unique<ReplacePointsCommand>(std::move(result.points), "predicted points"));
      } else {
        m_document->adoptPredictedPoints(std::move(result.points));
      }
    } catch (const Error& e) {
      reportError(e.what());
    }
  }
  if (result.suggestedCategory &&
      std::any_of(m_document->points().begin(), m_document->points().end(), isSuggestion)) {
    m_document->setSuggestedCategory(*result.suggestedCategory);
  }
  m_document->setPredictedFields(std::move(result.fields));
  logger()->info("prediction done: {} points", m_document->points().size());
}

void Session::exportCurrent(const std::string& format, const fs::path& outDir) {
  if (!m_document) return;
  try {
    const SimulatorExport result =
        format == "mjcf"
            ? exportMjcf(m_document->labels(), m_document->meshPath(), outDir, {},
                         m_document->labelsPath())
            : exportOmniGibson(m_document->labels(), m_document->meshPath(), outDir, {},
                               m_document->labelsPath());
    for (const auto& w : result.warnings) logger()->warn("{}", w);
    logger()->info("exported {}", result.mainFile.string());
  } catch (const Error& e) {
    reportError(e.what());
  }
}

void Session::addCurrentToTrainingSet(const fs::path& datasetDir) {
  if (!m_document) return;
  try {
    const auto entry = addToTrainingSet(m_document->labels(), m_document->meshPath(),
                                        m_document->labelsPath(), datasetDir);
    logger()->info("added {} to training set {}", entry.id, datasetDir.string());
  } catch (const Error& e) {
    reportError(e.what());
  }
}

}  // namespace sagrid::ui
