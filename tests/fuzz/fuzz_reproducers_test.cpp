// Regression tests for what the fuzz targets found (tests/fuzz, `make fuzz`): every input saved
// under tests/data/bad/fuzz/<target>/ goes through the same loader as its fuzz target, in a child
// process with a time limit, and must give a result or a sagrid::Error: no crash, no abort, no
// other exception, no hang. Folder names are the targets' seed folders: mesh_obj, mesh_ply,
// mesh_stl, mesh_glb, mesh_fbx, labels, model_card, npz, npy, architecture.
// A reproducer whose fix is still to come is listed in tests/data/bad/fuzz/PENDING (one
// "<folder>/<file>  <who fixes it>" a line) and skipped with that note until it is removed there.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "core/common/error.h"
#include "core/geometry/material_parts.h"
#include "core/io/npz.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh_import.h"
#include "core/model/architecture.h"
#include "core/model/model_card.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

namespace fs = std::filesystem;

const fs::path kReproducers = fs::path(SAGRID_TEST_DATA_DIR) / "bad" / "fuzz";
constexpr unsigned kSecondsPerInput = 20;

std::string readAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

// The fuzz target's loader for `folder`, on a copy of the input named as the target names it.
void load(const std::string& folder, const fs::path& input, const fs::path& work) {
  auto copyAs = [&](const std::string& name) {
    fs::copy_file(input, work / name, fs::copy_options::overwrite_existing);
    return work / name;
  };
  if (folder.rfind("mesh_", 0) == 0) {
    (void)connectedAndMaterialParts(importMesh(copyAs("input." + folder.substr(5))));
  } else if (folder == "labels") {
    (void)metersPerUnit(readLabels(copyAs("labels.json")));
  } else if (folder == "model_card") {
    (void)model::readModelCard(copyAs("stove.heatsource.json"));
  } else if (folder == "npz") {
    for (const auto& [name, array] : readNpz(copyAs("features.npz"))) (void)array.asDouble();
  } else if (folder == "npy") {
    (void)readNpy(copyAs("array.npy")).asDouble();
  } else if (folder == "architecture") {
    (void)model::Architecture::parse(readAll(input));
  } else {
    ADD_FAILURE() << "unknown reproducer folder " << folder;
  }
}

// "ok", "error: ...", or what went wrong in the child (signal, exception, time limit).
std::string outcomeInChild(const std::string& folder, const fs::path& input, const fs::path& work) {
  int pipeFds[2];
  if (pipe(pipeFds) != 0) return "pipe failed";
  const pid_t child = fork();
  if (child == 0) {
    close(pipeFds[0]);
    alarm(kSecondsPerInput);  // a hang ends as SIGALRM
    std::string outcome = "ok";
    int code = 0;
    try {
      load(folder, input, work);
    } catch (const Error& e) {
      outcome = std::string("error: ") + e.what();
    } catch (const std::exception& e) {
      outcome = std::string("non-sagrid exception: ") + e.what();
      code = 3;
    }
    (void)!write(pipeFds[1], outcome.data(), outcome.size());
    _exit(code);
  }
  close(pipeFds[1]);
  std::string outcome;
  char buffer[512];
  for (ssize_t n; (n = read(pipeFds[0], buffer, sizeof buffer)) > 0;) outcome.append(buffer, n);
  close(pipeFds[0]);
  int status = 0;
  waitpid(child, &status, 0);
  if (WIFSIGNALED(status)) {
    return WTERMSIG(status) == SIGALRM
               ? "hang: no answer within " + std::to_string(kSecondsPerInput) + " s"
               : std::string("crash: signal ") + strsignal(WTERMSIG(status));
  }
  return outcome;
}

std::map<std::string, std::string> pendingFixes() {
  std::map<std::string, std::string> pending;
  std::istringstream lines(readAll(kReproducers / "PENDING"));
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string name, note;
    if (!(words >> name) || name[0] == '#') continue;
    std::getline(words, note);
    pending[name] = note;
  }
  return pending;
}

TEST(FuzzReproducers, EveryInputGivesAResultOrOneClearError) {
  ASSERT_TRUE(fs::is_directory(kReproducers)) << kReproducers;
  const auto pending = pendingFixes();
  const fs::path work = test::freshTempDir();
  int checked = 0;
  for (const auto& folder : fs::directory_iterator(kReproducers)) {
    if (!folder.is_directory()) continue;
    for (const auto& input : fs::directory_iterator(folder.path())) {
      const std::string folderName = folder.path().filename().string();
      const std::string name = folderName + "/" + input.path().filename().string();
      SCOPED_TRACE(name);
      if (const auto it = pending.find(name); it != pending.end()) {
        std::printf("[ PENDING  ] %s:%s\n", name.c_str(), it->second.c_str());
        continue;
      }
      const std::string outcome = outcomeInChild(folderName, input.path(), work);
      EXPECT_TRUE(outcome == "ok" || outcome.rfind("error: ", 0) == 0) << outcome;
      // An error names the file it was given.
      if (outcome.rfind("error: ", 0) == 0 && folderName != "architecture")
        EXPECT_NE(outcome.find(work.string()), std::string::npos) << outcome;
      ++checked;
    }
  }
  std::printf("%d reproducers checked, %zu pending a fix\n", checked, pending.size());
}

}  // namespace
}  // namespace sagrid
