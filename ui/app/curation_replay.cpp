#include "ui/app/curation_replay.h"

#include <chrono>
#include <memory>
#include <thread>

#include "core/curation/curation_plan.h"
#include "ui/app/session.h"
#include "ui/document/point_commands.h"
#include "ui/document/units_commands.h"

namespace sagrid::ui {

namespace {
void takeStep(Session& session, const CurationStep& step, bool repredict) {
  switch (step.action) {
    case CurationAction::ConfirmCategory:
      session.confirmSuggestedCategory();
      break;
    case CurationAction::Category:
      session.autoPredict = repredict;
      session.switchCategory(step.category);
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
    if (!steps.empty() && steps.front().action == CurationAction::Category) {
      takeStep(session, steps.front(), repredict);
      awaitPrediction(session);
      steps = curationPlan(session.document()->labels(), *truth);  // from what the switch left
    }
    for (const CurationStep& step : steps) takeStep(session, step, repredict);
    session.document()->select(-1);
    session.accept();
    ++summary.objects;
  }
  return summary;
}

}  // namespace sagrid::ui
