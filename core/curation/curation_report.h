// What a curation log says about curator throughput (issue 41, `sagrid eval --curation LOG`):
// per object the actions by kind, the edits, whether one key did it, the time as logged, and the
// time a keystroke-level model (KLM) predicts for the logged actions, so the figure means the same
// whoever drove the GUI. Operator times are Card, Moran & Newell's ("The keystroke-level model for
// user performance time with interactive systems", CACM 23(7), 1980): K 0.28 s (an average typist,
// 40 words a minute), P 1.1 s (point with a mouse), B 0.1 s (press or release a button),
// M 1.35 s (mental preparation).
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/curation/curation_log.h"

namespace sagrid {

struct KlmOperators {
  double keystroke = 0.28;
  double point = 1.1;
  double button = 0.1;
  double mental = 1.35;
};

// The operators one logged action stands for, e.g. a drag = M P B P B; a one-key accept = M K.
std::string klmSequence(CurationAction action);
double klmSeconds(CurationAction action, const KlmOperators& ops = {});

// Gaps between two logged actions longer than this are counted as this much (a curator away).
inline constexpr double kMaxLoggedGapSeconds = 120.0;

struct ObjectCuration {
  std::string object;
  std::map<CurationAction, int> actions;
  int edits = 0;        // drag, add, copies, delete, retype, category (switched or confirmed), units, edit
  bool oneKey = false;  // nothing but looking and one accept-all
  double loggedSeconds = 0;
  double klmSeconds = 0;
  std::string carriedFrom;  // opened with the points of this object of the same geometry
};

struct CurationReport {
  KlmOperators operators;
  std::vector<ObjectCuration> objects;  // in the order first opened
  std::map<CurationAction, int> actions;
  double oneKeyShare = 0;
  double meanEdits = 0;
  double meanLoggedSeconds = 0;
  double meanKlmSeconds = 0;
  double objectsPerHourLogged = 0;
  double objectsPerHourKlm = 0;
  bool replayed = false;  // every event replayed: the logged times are the machine's, not a person's
  int carriedObjects = 0;  // objects opened with the points of another of the same geometry
};

// Objects the log shows being finished (accept-all or skip) or edited; objects only opened and
// left are not counted. Actions belong to the object they name.
CurationReport curationReport(const std::vector<CurationEvent>& events, const KlmOperators& ops = {});

std::string curationMarkdown(const CurationReport& report, std::size_t slowest = 10);
nlohmann::json toJson(const CurationReport& report);

}  // namespace sagrid
