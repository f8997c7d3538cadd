// Variety table of a generated dataset: counts of each recorded generator parameter (stove kind,
// burner layout and look, control placement; sink kind, faucet and handle type, ...), affordance
// counts, units, file formats and triangle counts, read back from the labels.json files.
#pragma once

#include <filesystem>
#include <string>

namespace sagrid::gen {

// Markdown tables, one per category and parameter. Throws FileError for an unreadable dataset.
std::string datasetStatsTable(const std::filesystem::path& datasetDir);

}  // namespace sagrid::gen
