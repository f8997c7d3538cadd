#include "ui/app/part_marks_replay.h"

#include <cmath>
#include <set>

#include "core/common/error.h"
#include "core/geometry/surface_scene.h"
#include "ui/app/control_edit.h"
#include "ui/app/session.h"
#include "ui/document/control_view.h"

namespace sagrid::ui {

namespace {

Eigen::Vector3f vectorAt(const nlohmann::json& j, const std::string& source) {
  if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() || !j[2].is_number())
    throw FileError(source, "a stroke's \"at\" must be [x, y, z]");
  return {j[0].get<float>(), j[1].get<float>(), j[2].get<float>()};
}

// One stroke of the brush at the surface point nearest `at` (file frame); `where` names the
// object and point for errors.
bool stroke(Session& session, const nlohmann::json& s, const std::string& source, const std::string& where) {
  AnnotationDocument& doc = *session.document();
  const ClosestPoint near = doc.surface().closestPoint(doc.toView(vectorAt(s.at("at"), source + ": " + where)));
  if (near.triangle < 0) return false;
  SurfaceHit hit;
  hit.triangle = near.triangle;
  hit.position = near.position;
  hit.normal = near.normal;
  const double radius = s.value("radius_cm", static_cast<double>(PartBrush{}.radiusCm));
  if (!std::isfinite(radius) || radius <= 0)
    throw FileError(source, where + ": a stroke's radius_cm must be a number above 0");
  session.partBrush.radiusCm = static_cast<float>(radius);
  const std::string mode = s.value("mode", "add");
  if (mode != "add" && mode != "away" && mode != "replace")
    throw FileError(source, where + ": a stroke's mode must be add, away or replace, not " + mode);
  return brushControlPart(session, hit, mode == "away" ? BrushMode::Away
                                        : mode == "replace" ? BrushMode::Replace
                                                            : BrushMode::Add);
}

// Gives point `index` the mark's axis; what kept it from applying, or empty.
std::string setAxis(Session& session, int index, const std::string& axis, const std::string& source) {
  std::optional<ShownControl> shown = shownControl(*session.document(), index);
  if (axis != "own" && axis != "flip" && axis != "x" && axis != "y" && axis != "z")
    throw FileError(source, "an axis must be flip, x, y, z or own, not " + axis);
  if (!shown) return "no part to give the axis";
  if (axis == "own") {
    if (shown->part.motion != ControlMotion::Knob)
      return std::string("\"own\" is a knob's axis, and this control is a ") + toString(shown->part.motion);
    return setOwnAxis(session, index) ? "" : "no surface to find its own axis on";
  }
  if (axis == "flip") shown->part.axis = -shown->part.axis;
  else shown->part.axis = Eigen::Vector3f::Unit(axis[0] - 'x');
  setControlRecord(session, index, *shown, "axis " + axis);
  return "";
}

}  // namespace

PartMarksSummary replayPartMarks(Session& session, const nlohmann::json& marks,
                                 const std::string& source) {
  if (!marks.is_object() || !marks.contains("objects") || !marks["objects"].is_object())
    throw FileError(source, "not a part marks file: {\"objects\": {...}}");
  PartMarksSummary summary;
  session.autoPredict = false;
  std::set<std::string> unseen;
  for (const auto& [id, marksOfObject] : marks["objects"].items()) unseen.insert(id);
  for (std::size_t i = 0; i < session.queue().size(); ++i) {
    if (session.queue().current() != static_cast<int>(i) || !session.document())
      session.openEntry(static_cast<int>(i));
    AnnotationDocument* doc = session.document();
    if (!doc) continue;
    const std::string id = doc->meshPath().parent_path().filename().string();
    const auto object = marks["objects"].find(id);
    if (object == marks["objects"].end()) continue;
    unseen.erase(id);
    ++summary.objects;
    try {
      for (const auto& mark : *object) {
        if (mark.value("keep_all", false)) {
          summary.parts += confirmEveryControl(session);
          continue;
        }
        if (!mark.contains("point") || !mark.at("point").is_number_integer())
          throw FileError(source, "object " + id + ": a mark needs \"point\", a whole number");
        const int point = mark.at("point").get<int>();
        const int index = point - 1;
        const std::string name = id + " point " + std::to_string(point);
        if (index < 0 || index >= static_cast<int>(doc->points().size()) ||
            doc->points()[std::size_t(index)].type != "togglebutton") {
          summary.problems.push_back(name + ": not a toggle button");
          continue;
        }
        doc->select(index);
        if (mark.value("keep", false)) {
          const std::optional<ShownControl> shown = shownControl(*doc, index);
          if (!shown) {
            summary.problems.push_back(name + ": no part was found to keep");
            continue;
          }
          setControlRecord(session, index, *shown, "part kept");
        }
        for (const auto& s : mark.value("strokes", nlohmann::json::array()))
          if (!stroke(session, s, source, name))
            summary.problems.push_back(name + ": a stroke changed nothing (or would empty the part)");
        if (mark.contains("motion")) {
          const auto motion = parseControlMotion(mark.at("motion").get<std::string>());
          if (!motion)
            throw FileError(source, name + ": a motion must be knob, lever or button, not " +
                                        mark.at("motion").get<std::string>());
          if (!setControlMotion(session, index, *motion)) {
            summary.problems.push_back(name + ": no part to give the motion");
            continue;
          }
          // Already moving so, the mark still confirms it.
          if (const auto shown = shownControl(*doc, index); shown && !shown->confirmed)
            setControlRecord(session, index, *shown, "part kept");
        }
        if (mark.contains("axis")) {
          const std::string problem = setAxis(session, index, mark.at("axis").get<std::string>(), source);
          if (!problem.empty()) {
            summary.problems.push_back(name + ": " + problem);
            continue;
          }
        }
        if (mark.value("for_all", false)) {
          const std::size_t written = confirmEveryControl(session, index);
          if (written == 0) summary.problems.push_back(name + ": no control to give its axis to");
          summary.parts += written;
          continue;
        }
        ++summary.parts;
      }
    } catch (const nlohmann::json::exception& e) {
      throw FileError(source, "object " + id + ": " + e.what());
    }
    session.document()->select(-1);
  }
  for (const std::string& id : unseen)
    summary.problems.push_back(id + ": no such object among those opened");
  return summary;
}

}  // namespace sagrid::ui
