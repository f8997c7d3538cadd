#include "support/output_check.h"

#include <algorithm>
#include <cctype>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/io/json_file.h"
#include "core/io/npz.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh_import.h"

namespace sagrid::test {
namespace fs = std::filesystem;

namespace {

bool isTemporary(const fs::path& p) { return p.filename().string().find(".tmp-") != std::string::npos; }

// The root element's name must come back as the last closing tag.
std::string xmlProblem(const std::string& text) {
  std::size_t at = 0;
  while ((at = text.find('<', at)) != std::string::npos &&
         (text.compare(at, 2, "<?") == 0 || text.compare(at, 2, "<!") == 0))
    ++at;
  if (at == std::string::npos) return "holds no XML element";
  const std::size_t end = text.find_first_of(" \t\r\n/>", at + 1);
  const std::string root = text.substr(at + 1, end - at - 1);
  std::string tail = text;
  while (!tail.empty() && std::isspace(static_cast<unsigned char>(tail.back()))) tail.pop_back();
  const std::string closing = "</" + root + ">";
  if (tail.size() < closing.size() ||
      tail.compare(tail.size() - closing.size(), closing.size(), closing) != 0)
    return "XML root <" + root + "> is not closed at the end (truncated?)";
  return "";
}

std::string pngProblem(const std::string& bytes) {
  static const std::string kSignature("\x89PNG\r\n\x1a\n", 8);
  if (bytes.compare(0, 8, kSignature) != 0) return "is not a PNG";
  if (bytes.size() < 20 || bytes.compare(bytes.size() - 8, 4, "IEND") != 0)
    return "PNG has no IEND chunk at its end (truncated?)";
  return "";
}

std::string problemOf(const fs::path& file) {
  const std::string ext = file.extension().string();
  try {
    if (file.filename() == "labels.json") {
      readLabels(file);
    } else if (ext == ".json") {
      readJsonFile(file, kMaxInputFileBytes);
    } else if (ext == ".jsonl") {
      const std::string text = readFileBytes(file);
      if (!text.empty() && text.back() != '\n') return "last line is not ended (truncated?)";
      for (std::size_t at = 0, next; at < text.size(); at = next + 1) {
        next = text.find('\n', at);
        parseJsonDocument(text.substr(at, next - at), file);
      }
    } else if (ext == ".npz") {
      readNpz(file);
    } else if (ext == ".obj" || ext == ".glb" || ext == ".ply" || ext == ".stl") {
      importMesh(file);
    } else if (ext == ".xml" || ext == ".urdf" || ext == ".mjcf") {
      return xmlProblem(readFileBytes(file));
    } else if (ext == ".png") {
      return pngProblem(readFileBytes(file));
    }
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

std::vector<std::string> invalidOutputs(const fs::path& folder) {
  std::vector<std::string> problems;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (!entry.is_regular_file() || isTemporary(entry.path())) continue;
    if (const std::string problem = problemOf(entry.path()); !problem.empty())
      problems.push_back(entry.path().string() + ": " + problem);
  }
  return problems;
}

std::vector<fs::path> temporaryFiles(const fs::path& folder) {
  std::vector<fs::path> found;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (isTemporary(entry.path())) found.push_back(entry.path());
  return found;
}

std::vector<std::string> relativeFiles(const fs::path& folder) {
  std::vector<std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.is_regular_file()) files.push_back(fs::relative(entry.path(), folder).string());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace sagrid::test
