// The Session's same-geometry twins: the open object's geometry outline kept in the queue, and the
// points, category and units of a curated twin carried to an object that has no curated labels
// yet (ui/document/twin_points.h), moved by the offset between the two copies' geometry origins
// (a twin may sit elsewhere in its file). A curated object of the same outline is a candidate; its
// mesh is imported to confirm it (matchGeometry), so an object without candidates costs one pass
// over its own mesh. Only at opening: a twin curated later changes nothing already open or opened.
#include <algorithm>
#include <system_error>

#include "core/annotate/units_record.h"
#include "core/common/error.h"
#include "core/common/log.h"
#include "core/mesh/geometry_identity.h"
#include "core/mesh/mesh_import.h"
#include "ui/app/session.h"
#include "ui/document/twin_points.h"
#include "ui/document/up_axis_commands.h"

namespace sagrid::ui {

namespace fs = std::filesystem;

namespace {

// Nothing a curator or a twin gave yet: points only as a model predicted them, review not begun.
bool hasCuratedLabels(const ObjectLabels& labels, QueueState state) {
  const bool allPredicted =
      std::all_of(labels.affordances.begin(), labels.affordances.end(),
                  [](const AffordancePoint& p) { return p.status == AffordanceStatus::Predicted; });
  return state != QueueState::Unreviewed || labels.reviewState != ReviewState::Unreviewed ||
         !allPredicted || pointsCarriedFrom(labels);
}

fs::file_time_type writtenAt(const fs::path& path) {
  std::error_code ec;
  const auto time = fs::last_write_time(path, ec);
  return ec ? fs::file_time_type::min() : time;
}

}  // namespace

std::string Session::carryTwinPoints() {
  if (!m_document || m_queue.empty()) return {};
  const std::size_t index = std::size_t(m_queue.current());
  try {
    m_queue.setGeometry(index, geometryOutline(m_document->mesh()));
  } catch (const Error& e) {
    logger()->warn("{}: no geometry outline ({}): no twin is looked for", m_document->displayName(),
                   e.what());
    return {};
  }
  if (!m_queue.entry(index).geometry) return {};
  if (hasCuratedLabels(m_document->labels(), m_queue.entry(index).state)) return {};

  // The twin curated last, where several are: its labels are the curator's latest word.
  std::vector<std::size_t> twins = m_queue.curatedTwinCandidatesOf(index);
  std::stable_sort(twins.begin(), twins.end(), [&](std::size_t a, std::size_t b) {
    return writtenAt(m_queue.entry(a).labels) > writtenAt(m_queue.entry(b).labels);
  });
  for (std::size_t t : twins) {
    const QueueEntry& twin = m_queue.entry(t);
    std::optional<GeometryMatch> match;
    ObjectLabels labels;
    try {
      // Any up axis: the match is in the files' own frames.
      match = matchGeometry(importMesh(twin.mesh, ImportOptions(UpAxis::Z)), m_document->mesh());
      if (!match) {
        logger()->info("{}: the outline of {}, not its geometry", m_document->displayName(),
                       twin.mesh.string());
        continue;
      }
      labels = readLabels(twin.labels);
    } catch (const Error& e) {
      logger()->warn("same-geometry twin not carried: {}", e.what());
      continue;
    }
    const std::string id = labels.object.id.empty() ? twin.mesh.stem().string() : labels.object.id;
    const bool sameOrder = match->sameTriangleOrder;
    const Eigen::Vector3f offset = match->offset.cast<float>();
    // The twin's units, as a guess that names it, where this object's are unknown or guessed.
    std::optional<UnitGuess> units;
    if (unitsKnown(labels) &&
        (!m_document->unitsKnown() || recordedUnitGuess(m_document->labels().object))) {
      units.emplace();
      units->metersPerUnit = metersPerUnit(labels);
      units->unit = unitName(units->metersPerUnit);
      units->reason = "as curated for " + id + ", an object of the same geometry";
    }
    // The twin's up axis too: the same file coordinates (moved) stand the same way up.
    std::vector<std::unique_ptr<Command>> steps;
    const UpAxis up = upAxisOrZ(labels.object.up);
    if (up != m_document->mesh().fileUp)
      steps.push_back(std::make_unique<TurnUpAxisCommand>(*m_document, up));
    steps.push_back(
        std::make_unique<CarryTwinPointsCommand>(labels, id, sameOrder, units, offset));
    const std::string what = steps.back()->description();
    try {
      m_document->startReviewWith(std::make_unique<CommandGroup>(what, std::move(steps)));
    } catch (const Error& e) {
      reportError(e.what());
    }
    return pointsCarriedFrom(m_document->labels()) ? id
                                                   : std::string();  // the autosave may fail alone
  }
  return {};
}

}  // namespace sagrid::ui
