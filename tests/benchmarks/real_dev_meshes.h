// Meshes the benchmarks share: the real-dev objects and ~100k-triangle versions of them (each
// triangle split into n x n, colours baked into vertex colours, written as OBJ under the temp
// folder once per process).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sagrid::bench {

extern const std::vector<std::string> kRealDev;  // libero__basin_faucet, __faucet_knob, __flat_stove

std::filesystem::path benchDir();  // a scratch folder under the temp folder
std::filesystem::path realDevMesh(int i);
// The dense copy of real-dev object i (>= 100k triangles).
std::filesystem::path denseCopy(int i);

}  // namespace sagrid::bench
