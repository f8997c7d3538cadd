// Comparing two labels.json files the way batch tests need: same category, same points of the same
// types in the same order, positions within a tolerance (mesh units).
#pragma once

#include <filesystem>

namespace sagrid::test {

// GoogleTest expectations (non-fatal), naming `a` on a difference.
void expectSameLabels(const std::filesystem::path& a, const std::filesystem::path& b,
                      float tolerance = 1e-5f);

}  // namespace sagrid::test
