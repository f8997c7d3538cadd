#include "ui/app/control_edit.h"

#include <algorithm>
#include <memory>

#include "core/controls/control_part_edit.h"
#include "core/controls/control_record.h"
#include "core/controls/control_symmetry.h"
#include "core/geometry/point_grid.h"
#include "core/geometry/surface_scene.h"
#include "ui/app/session.h"
#include "ui/document/command.h"
#include "ui/document/control_commands.h"

namespace sagrid::ui {

namespace {

// The control the point shows, or a new one without a part for a toggle button that has none.
std::optional<ShownControl> controlToEdit(const AnnotationDocument& doc, int index) {
  if (index < 0 || index >= static_cast<int>(doc.points().size())) return std::nullopt;
  if (doc.points()[std::size_t(index)].type != "togglebutton") return std::nullopt;
  if (auto shown = shownControl(doc, index)) return shown;
  return ShownControl{};
}

// The command that writes `shown` as point `index`'s record, confirmed by the curator.
std::unique_ptr<SetControlCommand> confirmCommand(const AnnotationDocument& doc, int index,
                                                  const ShownControl& shown, const std::string& what) {
  const ControlRecord record{shown.part, shown.drives, /*confirmed=*/true};
  return std::make_unique<SetControlCommand>(index, controlJson(record, doc.mesh().fileUp), what);
}

}  // namespace

void setControlRecord(Session& session, int index, const ShownControl& shown, const std::string& what) {
  session.execute(confirmCommand(*session.document(), index, shown, what));
}

std::size_t confirmEveryControl(Session& session, int axisOf) {
  const AnnotationDocument* doc = session.document();
  if (!doc) return 0;
  std::optional<ShownControl> axisSource;
  if (axisOf >= 0) {
    axisSource = shownControl(*doc, axisOf);
    if (!axisSource) return 0;
  }
  std::vector<std::unique_ptr<Command>> steps;
  for (int i = 0; i < static_cast<int>(doc->points().size()); ++i) {
    std::optional<ShownControl> shown = shownControl(*doc, i);
    if (!shown) continue;
    if (axisSource) {
      if (shown->part.motion != axisSource->part.motion) continue;
      shown->part.axis = axisSource->part.axis;
    }
    steps.push_back(confirmCommand(*doc, i, *shown, "control of point " + std::to_string(i + 1)));
  }
  const std::size_t written = steps.size();
  if (written > 0)
    session.execute(std::make_unique<CommandGroup>(
        axisSource ? "this axis for every " + std::string(toString(axisSource->part.motion))
                   : "every control kept",
        std::move(steps)));
  return written;
}

bool setControlMotion(Session& session, int index, ControlMotion motion) {
  const AnnotationDocument* doc = session.document();
  if (!doc) return false;
  std::optional<ShownControl> shown = shownControl(*doc, index);
  if (!shown) return false;
  if (shown->part.motion == motion) return true;
  shown->part.motion = motion;
  // A knob turns and a button slides about the part's middle; a lever's held end stays the
  // curator's to set (Pivot at the point).
  if (motion != ControlMotion::Lever && !shown->part.triangles.empty())
    shown->part.pivot = partCentre(doc->mesh(), shown->part.triangles);
  setControlRecord(session, index, *shown, std::string("moves as a ") + toString(motion));
  return true;
}

bool setOwnAxis(Session& session, int index) {
  const AnnotationDocument* doc = session.document();
  if (!doc) return false;
  std::optional<ShownControl> shown = shownControl(*doc, index);
  if (!shown || shown->part.motion != ControlMotion::Knob) return false;
  const auto own = revolutionAxis(doc->mesh(), shown->part.triangles);
  if (!own) return false;
  const Eigen::Vector3f axis = facingWay(own->axis, shown->part.axis);
  if (shown->confirmed && axis.isApprox(shown->part.axis)) return true;  // no empty undo step
  shown->part.axis = axis;
  setControlRecord(session, index, *shown, "its own axis");
  return true;
}

bool reshapeControlPart(Session& session, int index, std::vector<int> triangles,
                        const std::string& what) {
  const AnnotationDocument* doc = session.document();
  if (!doc) return false;
  std::optional<ShownControl> shown = controlToEdit(*doc, index);
  if (!shown || triangles.empty() || triangles == shown->part.triangles) return false;
  shown->part = describeControlPart(doc->mesh(), std::move(triangles), PartOrigin::Marked);
  setControlRecord(session, index, *shown, what);
  return true;
}

bool brushApplies(const Session& session) {
  const AnnotationDocument* doc = session.document();
  return doc && controlToEdit(*doc, doc->selected()).has_value();
}

bool brushControlPart(Session& session, const SurfaceHit& hit, BrushMode mode) {
  const AnnotationDocument* doc = session.document();
  if (!doc) return false;
  const int index = doc->selected();
  const std::optional<ShownControl> shown = controlToEdit(*doc, index);
  if (!shown) return false;
  const float radius = session.partBrush.radiusCm * 0.01f / std::max(doc->metersPerUnit(), 1e-9f);
  const std::vector<int> start =
      mode == BrushMode::Replace ? std::vector<int>{} : shown->part.triangles;
  return reshapeControlPart(
      session, index,
      brushedPart(doc->partEditSurface(), start, hit.triangle, hit.position, radius,
                  mode != BrushMode::Away),
      mode == BrushMode::Away ? "part brushed away"
      : mode == BrushMode::Replace ? "part brushed anew" : "part brushed");
}

}  // namespace sagrid::ui
