// Two designs of the learned point decision compared repeat by repeat (`sagrid scorer compare`):
// the repeats of `scorer cv --repeats` leave the same generated objects out for any candidate
// files with the same generated objects, so two runs' repeats pair, and a difference is read
// against the spread of the differences instead of the spread of either run. Reads the two runs'
// scorer_cv.json; refuses runs whose repeats do not pair (other seeds, another left-out share,
// other curated objects). One design's runs with other seeds pool into one (more repeats than
// one run was given).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sagrid {

// One arm's figures as scorer_cv.json records them.
struct RecordedFigures {
  double editsPerHandPoint = 0, oneKeyShare = 0, singleErrorM = 0;
  double handPoints = 0, objects = 0;  // what the arm was measured on (the pairing check)
};

// A run of `scorer cv`: the full run and its repeats, each over every fold and over the folds of
// the sources no pass was made on.
struct RecordedScorerCv {
  std::string file;
  RecordedFigures all, unseen;  // every generated object in training
  double leftOutShare = 0;
  std::vector<unsigned> seeds;  // per repeat
  std::vector<RecordedFigures> repeatsAll, repeatsUnseen;
};

// Throws FileError naming `file` when it is unreadable, not JSON or lacks a field; a run without
// repeats has none (pairScorerCvs then refuses it).
RecordedScorerCv readScorerCv(const std::filesystem::path& file);

// Runs of one design on the same objects with other repeats (`scorer cv --repeats N --seed S` with
// other seeds) as one run: their repeats together, in seed order. Throws InvalidArgument naming
// the files when a seed repeats, the left-out shares differ, or the full runs differ (another
// design or other objects). One run is returned as it is.
RecordedScorerCv pooledScorerCvs(const std::vector<RecordedScorerCv>& runs);

struct PairedFigure {
  double these = 0, those = 0;
  double difference() const { return these - those; }
};

struct PairedScorerCv {
  std::string these, those;        // the files
  PairedFigure all, unseen;        // the full runs (edits per hand point)
  std::vector<unsigned> seeds;     // per repeat
  std::vector<PairedFigure> edits, unseenEdits, oneKey, error;  // per repeat; error in cm
  // Repeats where `these` needs fewer / more / as many edits per hand point as `those` (every
  // fold); and the two-sided sign test's p over the repeats that differ.
  int fewer = 0, more = 0, same = 0;
  double signTestP = 1;
  int unseenFewer = 0, unseenMore = 0, unseenSame = 0;
  double unseenSignTestP = 1;
};

// Throws InvalidArgument, naming both files and what differs, when their repeats do not pair:
// none, another count, other seeds or left-out share, or other hand points or objects per arm.
PairedScorerCv pairScorerCvs(const RecordedScorerCv& these, const RecordedScorerCv& those);

// The two-sided exact sign test: the chance of a split of `fewer` against `more` at least as
// uneven under a fair coin (1 for no differing pair).
double signTestP(int fewer, int more);

// A report section: per repeat both figures and their difference, the mean and sd of the
// differences, the counts and the sign test.
std::string pairedScorerCvMarkdown(const PairedScorerCv& paired);

}  // namespace sagrid
