// What a model update must not learn from or be judged on (issue 40, bad input), checked before
// anything trains so that the current model stays:
//  - labels whose points lie far outside their mesh (wrong units or frame: a point 1.3 m beside
//    a 60 cm hob teaches the model nothing but the mistake);
//  - one mesh (by sha256) labelled twice with labels that disagree (other category, another
//    number of points of a type, or a point with no counterpart near it);
//  - a held-out object that is also training data (its figure would not be held out).
// Each problem names the labels file(s) and what is wrong.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sagrid {

// A point lies far from its mesh beyond this share of the mesh's largest extent outside its box.
inline constexpr double kFarFromMeshShare = 0.25;
// Two labellings of one mesh agree when each point has one of its type within this share of the
// mesh's largest extent in the other.
inline constexpr double kLabelAgreementShare = 0.05;

struct CuratedData {
  std::vector<std::filesystem::path> training;  // dataset folders the update learns from
  std::filesystem::path heldOut;                // the guard's folder (may be empty)
  std::filesystem::path referenceRoot;          // where the folders' manifests may point
};

// Every problem, one line each; empty when the data is sound. Throws what reading a dataset or
// importing a mesh throws (FileError naming the file).
std::vector<std::string> curatedDataProblems(const CuratedData& data);

// Throws InvalidArgument listing the problems (the first ten) when there are any.
void requireSoundCuratedData(const CuratedData& data);

}  // namespace sagrid
