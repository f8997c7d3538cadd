#include "core/curation/curation_report.h"

#include <algorithm>
#include <cstdio>
#include <map>

namespace sagrid {

std::string klmSequence(CurationAction action) {
  switch (action) {
    case CurationAction::Open: return "M";          // take in the new object
    case CurationAction::Look: return "PBPB";       // an orbit: point, press, drag, release
    case CurationAction::Accept: return "MPBBK";    // select the point, key A
    case CurationAction::AcceptAll: return "MK";    // key A
    case CurationAction::Drag: return "MPBPB";
    case CurationAction::Add: return "MKPBB";       // the type's digit, then click on the surface
    case CurationAction::Delete: return "MPBBK";    // select, Del
    case CurationAction::DeleteRest: return "MPBBKK";  // select the first to go, Shift+Del
    case CurationAction::Copies: return "MPBBK";    // select, key R
    // Key E on the point just placed or extended (the selection it leaves): no pointing.
    case CurationAction::Extend: return "MK";
    case CurationAction::Retype: return "MPBBK";    // select, digit
    case CurationAction::Category: return "MPBBPBB";  // open the list, pick
    case CurationAction::ConfirmCategory: return "MK";  // key C
    case CurationAction::CategoryKey: return "MKK";     // Shift and the category's digit
    case CurationAction::Units: return "MPBBPBB";
    case CurationAction::Edit: return "MPBBPBB";
    case CurationAction::Undo: return "MKK";        // Ctrl+Z
    case CurationAction::Redo: return "MKK";
    case CurationAction::Skip: return "MK";
    case CurationAction::Navigate: return "MK";
  }
  return "M";
}

double klmSeconds(CurationAction action, const KlmOperators& ops) {
  double seconds = 0;
  for (const char op : klmSequence(action)) {
    seconds += op == 'K' ? ops.keystroke : op == 'P' ? ops.point : op == 'B' ? ops.button : ops.mental;
  }
  return seconds;
}

namespace {
bool isEdit(CurationAction a) {
  switch (a) {
    case CurationAction::Drag: case CurationAction::Add: case CurationAction::Delete: case CurationAction::Retype:
    case CurationAction::DeleteRest:
    case CurationAction::Copies: case CurationAction::Extend:
    case CurationAction::Category: case CurationAction::ConfirmCategory: case CurationAction::CategoryKey:
    case CurationAction::Units:
    case CurationAction::Edit:
      return true;
    default:
      return false;
  }
}
}  // namespace

CurationReport curationReport(const std::vector<CurationEvent>& events, const KlmOperators& ops) {
  std::vector<CurationEvent> ordered = events;
  std::stable_sort(ordered.begin(), ordered.end(),
                   [](const CurationEvent& a, const CurationEvent& b) { return a.seconds < b.seconds; });
  std::map<std::string, ObjectCuration> byObject;
  std::vector<std::string> order;
  std::map<std::string, bool> finished;
  for (std::size_t i = 0; i < ordered.size(); ++i) {
    const CurationEvent& e = ordered[i];
    auto [it, inserted] = byObject.try_emplace(e.object);
    ObjectCuration& o = it->second;
    if (inserted) {
      o.object = e.object;
      order.push_back(e.object);
    }
    ++o.actions[e.action];
    if (e.action == CurationAction::Open && !e.carriedFrom.empty()) o.carriedFrom = e.carriedFrom;
    if (isEdit(e.action)) ++o.edits;
    if (e.action == CurationAction::AcceptAll || e.action == CurationAction::Skip) finished[e.object] = true;
    o.klmSeconds += klmSeconds(e.action, ops);
    // The time to the next logged action is spent on this object.
    if (i + 1 < ordered.size()) o.loggedSeconds += std::min(ordered[i + 1].seconds - e.seconds, kMaxLoggedGapSeconds);
  }
  CurationReport report;
  report.operators = ops;
  report.replayed = !events.empty() && std::all_of(events.begin(), events.end(),
                                                   [](const CurationEvent& e) { return e.replayed; });
  for (const std::string& id : order) {
    ObjectCuration& o = byObject[id];
    if (!finished[id] && o.edits == 0) continue;
    int keys = 0;
    for (const auto& [action, n] : o.actions)
      if (action != CurationAction::Open && action != CurationAction::Look) keys += n;
    o.oneKey = keys == 1 && o.actions.count(CurationAction::AcceptAll);
    for (const auto& [action, n] : o.actions) report.actions[action] += n;
    if (!o.carriedFrom.empty()) ++report.carriedObjects;
    report.objects.push_back(o);
  }
  const double n = static_cast<double>(report.objects.size());
  if (n > 0) {
    for (const auto& o : report.objects) {
      report.oneKeyShare += o.oneKey ? 1.0 / n : 0.0;
      report.meanEdits += o.edits / n;
      report.meanLoggedSeconds += o.loggedSeconds / n;
      report.meanKlmSeconds += o.klmSeconds / n;
    }
    if (report.meanLoggedSeconds > 0) report.objectsPerHourLogged = 3600.0 / report.meanLoggedSeconds;
    if (report.meanKlmSeconds > 0) report.objectsPerHourKlm = 3600.0 / report.meanKlmSeconds;
  }
  return report;
}

std::string curationMarkdown(const CurationReport& report, std::size_t slowest) {
  std::string md = "# Curation\n\n";
  char line[512];
  std::snprintf(line, sizeof line,
                "| objects | edits / object | one key | logged s / object | KLM s / object | objects / hour (logged) | objects / hour (KLM) |\n"
                "|---:|---:|---:|---:|---:|---:|---:|\n| %zu | %.2f | %.1f %% | %.1f | %.1f | %.0f | %.0f |\n\n",
                report.objects.size(), report.meanEdits, 100.0 * report.oneKeyShare, report.meanLoggedSeconds,
                report.meanKlmSeconds, report.objectsPerHourLogged, report.objectsPerHourKlm);
  md += line;
  if (report.replayed)
    md += "Replayed by `sagrid replay-curation`: the logged times are the machine's; the KLM times are a person's.\n\n";
  if (report.carriedObjects > 0)
    md += std::to_string(report.carriedObjects) +
          " object(s) opened with the points of a curated object of the same geometry, not a prediction.\n\n";
  md += "Actions:";
  for (const CurationAction a : allCurationActions()) {
    const auto it = report.actions.find(a);
    if (it != report.actions.end()) md += std::string(" ") + toString(a) + " " + std::to_string(it->second) + ";";
  }
  const KlmOperators& ops = report.operators;
  std::snprintf(line, sizeof line, "\n\nKLM operators (Card, Moran & Newell 1980): K %.2f s, P %.2f s, B %.2f s, M %.2f s; per action:",
                ops.keystroke, ops.point, ops.button, ops.mental);
  md += line;
  for (const CurationAction a : allCurationActions()) md += std::string(" ") + toString(a) + " " + klmSequence(a) + ";";
  md += "\n\n## Slowest objects (KLM)\n\n| object | actions | edits | logged s | KLM s |\n|---|---:|---:|---:|---:|\n";
  std::vector<const ObjectCuration*> sorted;
  for (const auto& o : report.objects) sorted.push_back(&o);
  std::stable_sort(sorted.begin(), sorted.end(), [](auto* a, auto* b) { return a->klmSeconds > b->klmSeconds; });
  for (std::size_t i = 0; i < std::min(slowest, sorted.size()); ++i) {
    int actions = 0;
    for (const auto& [a, n] : sorted[i]->actions) actions += n;
    std::snprintf(line, sizeof line, "| %s | %d | %d | %.1f | %.1f |\n", sorted[i]->object.c_str(), actions,
                  sorted[i]->edits, sorted[i]->loggedSeconds, sorted[i]->klmSeconds);
    md += line;
  }
  return md;
}

nlohmann::json toJson(const CurationReport& report) {
  nlohmann::json objects = nlohmann::json::array();
  auto counts = [](const std::map<CurationAction, int>& actions) {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [a, n] : actions) j[toString(a)] = n;
    return j;
  };
  for (const auto& o : report.objects) {
    objects.push_back({{"object", o.object}, {"actions", counts(o.actions)}, {"edits", o.edits},
                       {"one_key", o.oneKey}, {"logged_seconds", o.loggedSeconds}, {"klm_seconds", o.klmSeconds}});
    if (!o.carriedFrom.empty()) objects.back()["carried_from"] = o.carriedFrom;
  }
  return {{"objects", objects},
          {"actions", counts(report.actions)},
          {"one_key_share", report.oneKeyShare},
          {"mean_edits", report.meanEdits},
          {"mean_logged_seconds", report.meanLoggedSeconds},
          {"mean_klm_seconds", report.meanKlmSeconds},
          {"objects_per_hour_logged", report.objectsPerHourLogged},
          {"objects_per_hour_klm", report.objectsPerHourKlm},
          {"replayed", report.replayed},
          {"carried_objects", report.carriedObjects},
          {"klm_operators", {{"K", report.operators.keystroke}, {"P", report.operators.point},
                             {"B", report.operators.button}, {"M", report.operators.mental}}}};
}

}  // namespace sagrid
