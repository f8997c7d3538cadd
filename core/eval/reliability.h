// How well the object-level confidence (core/annotate/object_confidence.h) predicts "right with
// one key": a reliability diagram (objects binned by confidence; mean confidence against the share
// actually right), the expected calibration error, and for "accept automatically above X" the
// share of objects accepted and the precision among them.
#pragma once

#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/annotate/object_confidence.h"

namespace sagrid {

struct ReliabilityBin {
  double low = 0, high = 0;
  std::size_t objects = 0;
  double meanConfidence = 0;  // NaN when empty
  double observed = 0;        // share right with one key; NaN when empty
};


struct ReliabilityReport {
  std::vector<ReliabilityBin> bins;
  double expectedCalibrationError = 0;  // object-weighted |mean confidence - observed|
  std::vector<AutoAcceptRow> autoAccept;
};

// Throws InvalidArgument for mismatched sizes or no objects.
ReliabilityReport reliabilityReport(const std::vector<double>& confidence,
                                    const std::vector<bool>& right, int bins = 5,
                                    const std::vector<double>& thresholds = {0.5, 0.7, 0.8, 0.9,
                                                                             0.95});

nlohmann::json toJson(const ReliabilityReport& r);
std::string reliabilityMarkdown(const ReliabilityReport& r);
void writeReliabilityPng(const std::filesystem::path& file, const ReliabilityReport& r);

}  // namespace sagrid
