#include "ui/app/curation_replay.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <set>
#include <thread>

#include "core/curation/curation_plan.h"
#include "ui/app/session.h"
#include "ui/document/point_commands.h"
#include "ui/document/point_copies.h"
#include "ui/document/point_row.h"
#include "ui/document/units_commands.h"

namespace sagrid::ui {

namespace {
void takeStep(Session& session, const CurationStep& step, bool repredict) {
  switch (step.action) {
    case CurationAction::ConfirmCategory:
      session.confirmSuggestedCategory();
      break;
    case CurationAction::Category:
    case CurationAction::CategoryKey:
      session.autoPredict = repredict;
      session.switchCategory(step.category, step.action);
      session.autoPredict = false;
      break;
    case CurationAction::Units:
      session.execute(std::make_unique<SetUnitsCommand>(step.metersPerUnit));
      break;
    case CurationAction::Drag:
      session.execute(std::make_unique<MovePointCommand>(step.index, step.point.position, step.point.normal));
      break;
    case CurationAction::Delete:
      session.document()->select(step.index);
      session.deleteSelected();
      break;
    case CurationAction::DeleteRest:
      session.document()->select(step.index);
      session.deleteRestOfSelected();
      break;
    case CurationAction::Add: {
      AffordancePoint point = step.point;
      point.status = AffordanceStatus::Added;
      session.setCurrentType(point.type);
      session.execute(std::make_unique<AddPointCommand>(std::move(point)));
      break;
    }
    default:
      break;
  }
}
// Where the plan adds two or more points of one type and a row of equal parts holds them, the
// curator places one (or selects a right one already there) and presses R (copies): taken when
// the plan that follows, with that action and the place, needs fewer actions than before. Returns
// whether it was taken; the steps then start again from the labels it left.
bool takeCopies(Session& session, const ObjectLabels& truth, std::vector<CurationStep>& steps) {
  AnnotationDocument& doc = *session.document();
  std::map<std::string, std::vector<std::size_t>> addsByType;
  std::set<int> touched;  // points the plan drags or deletes: not right as they are
  for (std::size_t s = 0; s < steps.size(); ++s) {
    if (steps[s].action == CurationAction::Add) addsByType[steps[s].point.type].push_back(s);
    if (steps[s].action == CurationAction::Drag || steps[s].action == CurationAction::Delete)
      touched.insert(steps[s].index);
    if (steps[s].action == CurationAction::DeleteRest)  // the point and its type's later ones
      for (int i = steps[s].index; i < static_cast<int>(doc.points().size()); ++i)
        if (doc.points()[std::size_t(i)].type == doc.points()[std::size_t(steps[s].index)].type)
          touched.insert(i);
  }
  for (const auto& [type, adds] : addsByType) {
    if (adds.size() < 2) continue;
    // The sources: a right point of the type already there, else the first point to add.
    std::vector<std::pair<int, AffordancePoint>> sources;
    for (int i = 0; i < static_cast<int>(doc.points().size()); ++i)
      if (doc.points()[std::size_t(i)].type == type && !touched.count(i))
        sources.push_back({i, doc.points()[std::size_t(i)]});
    sources.push_back({-1, steps[adds.front()].point});
    for (const auto& [index, source] : sources) {
      ObjectLabels after = doc.labels();
      if (index < 0) after.affordances.push_back(source);
      for (const AffordancePoint& p : pointsForCopies(doc, source)) after.affordances.push_back(p);
      const std::size_t cost = (index < 0 ? 2 : 1) + curationPlan(after, truth).size();
      if (cost >= steps.size()) continue;
      if (index < 0) {
        AffordancePoint point = source;
        session.setCurrentType(point.type);
        session.execute(std::make_unique<AddPointCommand>(std::move(point)));
      } else {
        doc.select(index);
      }
      session.addOnCopiesOfSelected();
      steps = curationPlan(session.document()->labels(), truth);
      return true;
    }
  }
  return false;
}

// How many extensions (E) follow point `index` of `labels` while each is a right point the plan
// would add (`stepsLeft`: the plan's length for `labels`).
int extensionsAfter(const AnnotationDocument& doc, ObjectLabels labels, int index,
                    const ObjectLabels& truth, std::size_t stepsLeft) {
  int extensions = 0;
  while (const std::optional<AffordancePoint> next = nextPointInRow(doc, labels.affordances, index)) {
    labels.affordances.push_back(*next);
    const std::size_t left = curationPlan(labels, truth).size();
    if (left >= stepsLeft) break;
    stepsLeft = left;
    index = static_cast<int>(labels.affordances.size()) - 1;
    ++extensions;
  }
  return extensions;
}

// Which of the plan's additions (`steps` holds only additions now) the curator places next: the
// one that starts the longest row of extensions, alone or followed by one more addition (two
// points of a row placed by hand, then E); the plan's first when none starts a row.
std::size_t nextAddition(const AnnotationDocument& doc, const std::vector<CurationStep>& steps,
                         const ObjectLabels& truth) {
  std::size_t best = 0;
  int longest = 0;
  const std::size_t n = steps.size();
  for (std::size_t a = 0; a < n; ++a) {
    ObjectLabels one = doc.labels();
    one.affordances.push_back(steps[a].point);
    const int last = static_cast<int>(one.affordances.size()) - 1;
    int rowFromA = extensionsAfter(doc, one, last, truth, n - 1);
    for (std::size_t b = 0; b < n; ++b) {
      if (b == a || steps[b].point.type != steps[a].point.type) continue;
      ObjectLabels two = one;
      two.affordances.push_back(steps[b].point);
      rowFromA = std::max(rowFromA, extensionsAfter(doc, two, last + 1, truth, n - 2));
    }
    if (rowFromA > longest) {
      longest = rowFromA;
      best = a;
    }
  }
  return best;
}

// The plan's additions, each followed by the extensions of its row (E) while the row's next point
// is a right point the plan would add: each extension replaces an addition.
void takeAdditions(Session& session, const ObjectLabels& truth, std::vector<CurationStep> steps,
                   bool repredict) {
  const auto isAdd = [](const CurationStep& s) { return s.action == CurationAction::Add; };
  while (!steps.empty()) {
    if (!std::all_of(steps.begin(), steps.end(), isAdd)) {  // not a plan's tail: as planned
      for (const CurationStep& step : steps) takeStep(session, step, repredict);
      return;
    }
    const AnnotationDocument& doc = *session.document();
    takeStep(session, steps[nextAddition(doc, steps, truth)], repredict);
    // The row the simulation found is the one E walks: the same steps from the same points.
    for (int row = extensionsAfter(doc, doc.labels(), doc.selected(), truth,
                                   curationPlan(doc.labels(), truth).size());
         row > 0 && session.extendRowOfSelected(); --row) {
    }
    std::vector<CurationStep> left = curationPlan(doc.labels(), truth);
    if (left.size() >= steps.size()) {  // the addition did not take: the rest as planned, once
      for (const CurationStep& step : left) takeStep(session, step, repredict);
      return;
    }
    steps = std::move(left);
  }
}

// A category switch predicts again for the new category (when the session has models): wait for
// it and apply it, as the GUI's frame loop does.
void awaitPrediction(Session& session) {
  while (session.worker().running()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  session.pollPrediction();
}
}  // namespace

CurationReplaySummary replayCuration(Session& session,
                                     const std::function<std::optional<ObjectLabels>(const std::string&)>& truthOf,
                                     bool repredict) {
  CurationReplaySummary summary;
  session.autoPredict = false;
  const std::size_t total = session.queue().size();
  for (std::size_t i = 0; i < total; ++i) {
    // Accepting (A) or skipping (S) the previous object already opened this one.
    if (session.queue().current() != static_cast<int>(i) || !session.document()) session.openEntry(static_cast<int>(i));
    AnnotationDocument* doc = session.document();
    if (!doc) {
      ++summary.failed;
      continue;
    }
    const std::string id = doc->meshPath().parent_path().filename().string();
    const std::optional<ObjectLabels> truth = truthOf(id);
    if (!truth) {
      ++summary.withoutTruth;
      session.skip();
      continue;
    }
    std::vector<CurationStep> steps = curationPlan(doc->labels(), *truth);
    if (!steps.empty() && isCategorySwitch(steps.front().action)) {
      takeStep(session, steps.front(), repredict);
      awaitPrediction(session);
      steps = curationPlan(session.document()->labels(), *truth);  // from what the switch left
    }
    while (takeCopies(session, *truth, steps)) {
    }
    // Additions come last in a plan: the rest go in the order that lets rows be extended.
    const auto firstAdd = std::find_if(steps.begin(), steps.end(), [](const CurationStep& s) {
      return s.action == CurationAction::Add;
    });
    for (auto step = steps.begin(); step != firstAdd; ++step) takeStep(session, *step, repredict);
    takeAdditions(session, *truth, std::vector<CurationStep>(firstAdd, steps.end()), repredict);
    session.document()->select(-1);
    session.accept();
    ++summary.objects;
  }
  return summary;
}

}  // namespace sagrid::ui
