#include "core/mesh/up_axis_benchmark.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <system_error>

#include "core/common/error.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh_files.h"
#include "core/mesh/mesh_import.h"

namespace sagrid {
namespace fs = std::filesystem;

int UpAxisBenchmark::counted() const {
  int n = 0;
  for (const auto& c : cases) n += c.expected.has_value();
  return n;
}

int UpAxisBenchmark::correct() const {
  int n = 0;
  for (const auto& c : cases) n += c.expected && *c.expected == c.detection.axis;
  return n;
}

namespace {

// object.up of DIR/labels.json beside the mesh, when there is one.
std::optional<UpAxis> labelledUp(const fs::path& mesh) {
  const fs::path labels = mesh.parent_path() / "labels.json";
  std::error_code ec;
  if (!fs::is_regular_file(labels, ec)) return std::nullopt;
  return parseUpAxis(readLabels(labels).object.up);
}

// The z-up mesh with `up` as its file frame's up axis, in file coordinates.
Mesh turnedTo(const Mesh& zUp, UpAxis up) {
  Mesh m = zUp;
  for (auto& p : m.positions) p = zUpToFile(p, up);
  for (auto& n : m.normals) n = zUpToFile(n, up);
  return m;
}

}  // namespace

UpAxisBenchmark benchmarkUpAxis(const std::vector<fs::path>& paths,
                                const UpAxisBenchmarkOptions& options) {
  std::vector<MeshFile> files;
  for (const auto& p : paths) {
    auto found = findMeshFiles(p);
    files.insert(files.end(), found.begin(), found.end());
  }
  UpAxisBenchmark result;
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (options.onProgress) options.onProgress(i, files.size(), files[i].id);
    try {
      std::optional<UpAxis> expected = labelledUp(files[i].path);
      if (!expected) expected = options.expect;
      // Imported with the known axis the mesh is z-up; with none it stays in the file's frame.
      const Mesh zUp = importMesh(files[i].path, ImportOptions(expected ? *expected : UpAxis::Z));
      if (options.allSix && expected) {
        for (UpAxis up : kAllUpAxes) {
          result.cases.push_back({files[i].id + "@" + toString(up), up,
                                  detectUpAxis(turnedTo(zUp, up), UpAxis::Z, options.weights)});
        }
      } else {
        const Mesh file = expected ? turnedTo(zUp, *expected) : zUp;
        result.cases.push_back(
            {files[i].id, expected, detectUpAxis(file, UpAxis::Z, options.weights)});
      }
    } catch (const Error& e) {
      const std::string path = files[i].path.string(), what = e.what();
      result.failures.push_back(what.rfind(path + ": ", 0) == 0 ? what : path + ": " + what);
    }
  }
  if (options.onProgress) options.onProgress(files.size(), files.size(), "");
  return result;
}

UpAxisWeights fitUpAxisOnFiles(const std::vector<fs::path>& paths,
                               const std::vector<fs::path>& yzPaths,
                               const UpAxisBenchmarkOptions& options, float* accuracy) {
  std::vector<std::pair<MeshFile, bool>> files;  // with "all six directions"
  for (const auto& p : paths) {
    for (auto& f : findMeshFiles(p)) files.emplace_back(std::move(f), options.allSix);
  }
  std::size_t yzCount = 0;
  for (const auto& p : yzPaths) {
    for (auto& f : findMeshFiles(p)) files.emplace_back(std::move(f), false), ++yzCount;
  }
  std::vector<UpAxisExample> examples;
  std::vector<bool> fromYz;
  for (std::size_t i = 0; i < files.size(); ++i) {
    const MeshFile& file = files[i].first;
    if (options.onProgress) options.onProgress(i, files.size(), file.id);
    try {
      std::optional<UpAxis> expected = labelledUp(file.path);
      if (!expected) expected = options.expect;
      if (!expected) continue;
      const Mesh zUp = importMesh(file.path, ImportOptions(*expected));
      const std::vector<UpAxis> yz{UpAxis::PosY, UpAxis::PosZ};
      const std::vector<UpAxis> six(std::begin(kAllUpAxes), std::end(kAllUpAxes));
      for (UpAxis up : files[i].second ? six : yz) {
        UpAxisExample e;
        e.candidates = upAxisDescriptors(turnedTo(zUp, up));
        e.up = static_cast<int>(up);
        if (e.candidates.empty()) continue;
        examples.push_back(std::move(e));
        fromYz.push_back(i >= files.size() - yzCount);
      }
    } catch (const Error&) {
      // Files that cannot be read do not teach anything; benchmarkUpAxis reports them.
    }
  }
  // The yz objects (few, real) weigh as much in total as the others (many, generated).
  const auto yzExamples = static_cast<float>(std::count(fromYz.begin(), fromYz.end(), true));
  const float others = static_cast<float>(examples.size()) - yzExamples;
  if (yzExamples > 0 && others > 0) {
    for (std::size_t i = 0; i < examples.size(); ++i) {
      if (fromYz[i]) examples[i].weight = others / yzExamples;
    }
  }
  return fitUpAxisWeights(examples, 4000, 1e-3f, accuracy);
}

std::string formatUpAxisWeights(const UpAxisWeights& w) {
  std::string out;
  char number[32];
  for (std::size_t k = 0; k < w.size(); ++k) {
    std::snprintf(number, sizeof number, "%s%.4ff", k ? ", " : "", w[k]);
    out += number;
  }
  return out;
}

UpAxisWeights parseUpAxisWeights(const std::string& text) {
  UpAxisWeights w{};
  std::size_t count = 0, at = 0;
  while (true) {
    at = text.find_first_not_of(" \t\r\n,", at);
    if (at == std::string::npos) break;
    const std::size_t end = text.find_first_of(" \t\r\n,", at);
    std::string number = text.substr(at, end == std::string::npos ? std::string::npos : end - at);
    if (!number.empty() && number.back() == 'f') number.pop_back();
    char* stop = nullptr;
    const float value = std::strtof(number.c_str(), &stop);
    if (number.empty() || stop != number.c_str() + number.size() || !std::isfinite(value)) {
      throw InvalidArgument("up-axis weights: '" + number + "' (number " +
                            std::to_string(count + 1) + ") is not a finite number");
    }
    if (count == w.size()) {
      throw InvalidArgument("up-axis weights: more than the " + std::to_string(w.size()) +
                            " numbers of this detector");
    }
    w[count++] = value;
    at = end;
  }
  if (count != w.size()) {
    throw InvalidArgument("up-axis weights: " + std::to_string(count) +
                          " numbers, this detector has " + std::to_string(w.size()));
  }
  return w;
}

std::string formatUpAxisBenchmark(const UpAxisBenchmark& b, bool perCase) {
  std::string out;
  char line[512];
  if (perCase) {
    std::snprintf(line, sizeof line, "%-40s %-8s %-8s %-5s  scores (x -x y -y z -z)\n", "object",
                  "expected", "detected", "conf");
    out += line;
    for (const auto& c : b.cases) {
      std::snprintf(line, sizeof line, "%-40s %-8s %-8s %.2f  %6.2f %6.2f %6.2f %6.2f %6.2f %6.2f%s\n",
                    c.id.c_str(), c.expected ? toString(*c.expected) : "?", toString(c.detection.axis),
                    c.detection.confidence, c.detection.scores[0], c.detection.scores[1],
                    c.detection.scores[2], c.detection.scores[3], c.detection.scores[4],
                    c.detection.scores[5],
                    c.expected && *c.expected != c.detection.axis ? "  WRONG" : "");
      out += line;
    }
  }
  std::array<std::array<int, 6>, 6> confusion{};
  double rightConfidence = 0, wrongConfidence = 0;
  for (const auto& c : b.cases) {
    if (!c.expected) continue;
    ++confusion[static_cast<int>(*c.expected)][static_cast<int>(c.detection.axis)];
    (*c.expected == c.detection.axis ? rightConfidence : wrongConfidence) += c.detection.confidence;
  }
  const int n = b.counted(), right = b.correct();
  // What importMesh does with an OBJ: the detected axis when sure enough, else y.
  const UpAxis unsure = unsureUpAxis(".obj");
  int importRight = 0;
  for (const auto& c : b.cases) {
    if (!c.expected) continue;
    const bool taken =
        c.detection.axis == unsure || c.detection.confidence >= kMinDetectedUpConfidence;
    importRight += (taken ? c.detection.axis : unsure) == *c.expected;
  }
  std::snprintf(line, sizeof line, "accuracy: %d / %d = %.1f%% (%zu cases, %zu import failures)\n",
                right, n, n ? 100.0 * right / n : 0.0, b.cases.size(), b.failures.size());
  out += line;
  std::snprintf(line, sizeof line,
                "import rule (OBJ keeps y below confidence %.2f): %d / %d = %.1f%%\n",
                kMinDetectedUpConfidence, importRight, n, n ? 100.0 * importRight / n : 0.0);
  out += line;
  std::snprintf(line, sizeof line, "mean confidence: right %.2f, wrong %.2f\n",
                right ? rightConfidence / right : 0.0, n - right ? wrongConfidence / (n - right) : 0.0);
  out += line;
  if (n) {
    out += "confusion (rows expected, columns detected):\n          x    -x     y    -y     z    -z\n";
    for (int r = 0; r < 6; ++r) {
      std::snprintf(line, sizeof line, "  %-3s %5d %5d %5d %5d %5d %5d\n", toString(kAllUpAxes[r]),
                    confusion[r][0], confusion[r][1], confusion[r][2], confusion[r][3],
                    confusion[r][4], confusion[r][5]);
      out += line;
    }
  }
  for (const auto& f : b.failures) out += "failed: " + f + "\n";
  return out;
}

namespace {
nlohmann::json evidenceJson(const UpAxisDetection& d) {
  nlohmann::json out = nlohmann::json::object();
  for (std::size_t i = 0; i < 6; ++i) {
    const UpAxisEvidence& e = d.evidence[i];
    out[toString(kAllUpAxes[i])] = {{"support", e.supportArea}, {"flat_bottom", e.flatBottom},
                                    {"tipping", e.tipping}, {"mass_height", e.massHeight},
                                    {"top_support", e.topSupport}};
  }
  return out;
}
}  // namespace

nlohmann::json upAxisBenchmarkJson(const UpAxisBenchmark& b) {
  nlohmann::json cases = nlohmann::json::array();
  for (const auto& c : b.cases) {
    cases.push_back({{"id", c.id},
                     {"expected", c.expected ? nlohmann::json(toString(*c.expected)) : nlohmann::json()},
                     {"detected", toString(c.detection.axis)},
                     {"confidence", c.detection.confidence},
                     {"degenerate", c.detection.degenerate},
                     {"scores", c.detection.scores},
                     {"evidence", evidenceJson(c.detection)}});
  }
  return {{"counted", b.counted()}, {"correct", b.correct()}, {"cases", cases}, {"failures", b.failures}};
}

}  // namespace sagrid
