#include "core/corpus/sweethome3d_packages.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <set>
#include <sstream>

#include "core/common/atomic_file.h"
#include "core/common/error.h"

namespace sagrid {
namespace fs = std::filesystem;

namespace {

constexpr const char* kFurniturePackage = "sweethome3d-furniture";
constexpr const char* kNonFreeFurniturePackage = "sweethome3d-furniture-nonfree";
constexpr const char* kAppPackage = "sweethome3d";

std::string shellQuote(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// Runs a shell command; returns its exit status and combined output.
std::pair<int, std::string> runCommand(const std::string& command) {
  std::string output;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return {-1, "cannot start a shell"};
  std::array<char, 4096> buffer{};
  while (const std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe))
    output.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  return {status, output};
}

std::string lastLine(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  const auto at = text.find_last_of('\n');
  return at == std::string::npos ? text : text.substr(at + 1);
}

std::string trimmed(std::string text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  std::size_t start = 0;
  while (start < text.size() && std::isspace(static_cast<unsigned char>(text[start]))) ++start;
  return text.substr(start);
}

std::string installedVersion(const std::string& package) {
  const auto [status, output] = runCommand("dpkg-query -W -f='${Version}' " + shellQuote(package));
  return status == 0 ? trimmed(output) : std::string();
}

// The .sh3f files an installed package holds (dpkg-query -L); empty when it is not installed.
std::set<fs::path> installedLibraries(const std::string& package) {
  std::set<fs::path> files;
  const auto [status, output] = runCommand("dpkg-query -L " + shellQuote(package));
  if (status != 0) return files;
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    const fs::path file = trimmed(line);
    if (file.extension() == ".sh3f" && fs::is_regular_file(file)) files.insert(file);
  }
  return files;
}

// Options making apt-get read Debian's non-free component alone, from a private state folder
// under `cache` (the system's sources and lists are left as they are).
std::string nonFreeAptOptions(const fs::path& cache) {
  const fs::path apt = cache / "apt-non-free";
  std::error_code ec;
  fs::create_directories(apt / "sources", ec);
  fs::create_directories(apt / "lists" / "partial", ec);
  fs::create_directories(apt / "archives" / "partial", ec);
  if (ec) throw FileError(apt, "cannot create the apt state folder: " + ec.message());
  std::string codename = "bookworm";
  const auto [status, output] = runCommand(". /etc/os-release && echo \"$VERSION_CODENAME\"");
  if (status == 0 && !trimmed(output).empty()) codename = trimmed(output);
  writeFileAtomic(apt / "sources" / "debian-non-free.sources",
                  "Types: deb\nURIs: http://deb.debian.org/debian\nSuites: " + codename +
                      "\nComponents: non-free\n"
                      "Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg\n");
  writeFileAtomic(apt / "none.list", "");
  auto option = [](const std::string& name, const fs::path& value) {
    return " -o " + shellQuote(name + "=" + value.string());
  };
  return option("Dir::Etc::sourcelist", apt / "none.list") +
         option("Dir::Etc::sourceparts", apt / "sources") +
         option("Dir::State::Lists", apt / "lists") +
         option("Dir::Cache::Archives", apt / "archives");
}

std::vector<fs::path> sh3fFiles(const fs::path& furnitureDir) {
  std::vector<fs::path> files;
  if (!fs::is_directory(furnitureDir)) return files;
  for (const auto& e : fs::directory_iterator(furnitureDir)) {
    if (e.is_regular_file() && e.path().extension() == ".sh3f") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The unpacked root of `package` from the .deb cache, downloading it when no .deb is cached
// (`aptOptions`: extra apt-get options, whose package lists are updated first). Returns the root
// and the package version.
std::pair<fs::path, std::string> unpackedPackage(const std::string& package, const fs::path& cache,
                                                 const std::function<void(const std::string&)>& log,
                                                 const std::string& aptOptions = {}) {
  auto cachedDeb = [&]() -> fs::path {
    std::vector<fs::path> debs;
    if (fs::is_directory(cache)) {
      for (const auto& e : fs::directory_iterator(cache)) {
        const std::string name = e.path().filename().string();
        if (e.is_regular_file() && name.rfind(package + "_", 0) == 0 &&
            e.path().extension() == ".deb") {
          debs.push_back(e.path());
        }
      }
    }
    std::sort(debs.begin(), debs.end());
    return debs.empty() ? fs::path() : debs.back();
  };
  fs::path deb = cachedDeb();
  if (deb.empty()) {
    std::error_code ec;
    fs::create_directories(cache, ec);
    if (ec) throw FileError(cache, "cannot create the .deb cache folder: " + ec.message());
    if (log) log("downloading " + package + " with apt-get download into " + cache.string());
    const std::string update =
        aptOptions.empty() ? std::string() : "apt-get" + aptOptions + " update && ";
    const auto [status, output] =
        runCommand("cd " + shellQuote(cache.string()) + " && " + update + "apt-get" + aptOptions +
                   " download " + shellQuote(package));
    deb = cachedDeb();
    if (status != 0 || deb.empty()) {
      throw Error("Sweet Home 3D package '" + package +
                  "' is not installed and `apt-get download " + package + "` failed (" +
                  lastLine(output) + "). Install it (sudo apt-get install " + package +
                  (aptOptions.empty() ? "" : ", from Debian's non-free component") +
                  "), check that Debian's apt sources are reachable, or pass the archives with "
                  "--sh3f FILE / "
                  "--jar FILE.");
    }
  }
  const auto [vStatus, vOutput] =
      runCommand("dpkg-deb -f " + shellQuote(deb.string()) + " Version");
  if (vStatus != 0) throw FileError(deb, "is not a readable .deb (" + lastLine(vOutput) + ")");
  const std::string version = trimmed(vOutput);
  const fs::path root = cache / (deb.stem().string() + ".unpacked");
  if (!fs::is_directory(root)) {
    const fs::path temp =
        cache / (deb.stem().string() + ".unpacking-" + std::to_string(::getpid()));
    fs::remove_all(temp);
    if (log) log("unpacking " + deb.filename().string());
    const auto [xStatus, xOutput] =
        runCommand("dpkg -x " + shellQuote(deb.string()) + " " + shellQuote(temp.string()));
    if (xStatus != 0) {
      fs::remove_all(temp);
      throw FileError(deb, "dpkg -x failed (" + lastLine(xOutput) + ")");
    }
    fs::rename(temp, root);
  }
  return {root, version};
}

}  // namespace

std::vector<SweetHome3dSource> locateSweetHome3dSources(
    const SweetHome3dPackageOptions& options, const std::function<void(const std::string&)>& log) {
  std::vector<SweetHome3dSource> sources;
  const fs::path installedShare = options.installedRoot / "usr/share/sweethome3d";
  auto versionOf = [&](const fs::path& file, const std::string& package) {
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(file, ec);
    return canonical.string().rfind("/usr/share/sweethome3d/", 0) == 0 ? installedVersion(package)
                                                                       : std::string();
  };
  if (!options.sh3f.empty() || options.jar) {
    for (const auto& file : options.sh3f) {
      if (!fs::is_regular_file(file)) throw FileError(file, "furniture library (.sh3f) not found");
      sources.push_back({file, false, file.stem().string(), kFurniturePackage,
                         versionOf(file, kFurniturePackage)});
    }
    if (options.jar) {
      if (!fs::is_regular_file(*options.jar))
        throw FileError(*options.jar, "Sweet Home 3D jar not found");
      sources.push_back(
          {*options.jar, true, "default", kAppPackage, versionOf(*options.jar, kAppPackage)});
    }
    return sources;
  }

  std::vector<fs::path> libraries = sh3fFiles(installedShare / "furniture");
  // An installed non-free package puts its libraries in the same folder: they are its own.
  const std::set<fs::path> nonFreeInstalled = options.installedRoot == "/"
                                                  ? installedLibraries(kNonFreeFurniturePackage)
                                                  : std::set<fs::path>();
  libraries.erase(std::remove_if(libraries.begin(), libraries.end(),
                                 [&](const fs::path& f) { return nonFreeInstalled.count(f) > 0; }),
                  libraries.end());
  std::string furnitureVersion;
  if (!libraries.empty()) {
    furnitureVersion = installedVersion(kFurniturePackage);
  } else {
    const auto [root, version] = unpackedPackage(kFurniturePackage, options.debCache, log);
    libraries = sh3fFiles(root / "usr/share/sweethome3d/furniture");
    furnitureVersion = version;
    if (libraries.empty())
      throw FileError(root, "the unpacked sweethome3d-furniture package holds no .sh3f files");
  }
  for (const auto& file : libraries) {
    sources.push_back({file, false, file.stem().string(), kFurniturePackage, furnitureVersion});
  }
  if (options.nonFree) {
    std::vector<fs::path> nonFree(nonFreeInstalled.begin(), nonFreeInstalled.end());
    std::string version =
        nonFree.empty() ? std::string() : installedVersion(kNonFreeFurniturePackage);
    if (nonFree.empty()) {
      const auto [root, unpackedVersion] = unpackedPackage(
          kNonFreeFurniturePackage, options.debCache, log, nonFreeAptOptions(options.debCache));
      nonFree = sh3fFiles(root / "usr/share/sweethome3d/furniture");
      version = unpackedVersion;
      if (nonFree.empty())
        throw FileError(root,
                        "the unpacked sweethome3d-furniture-nonfree package holds no .sh3f files");
    }
    for (const auto& file : nonFree)
      sources.push_back({file, false, file.stem().string(), kNonFreeFurniturePackage, version});
  }

  fs::path jar = installedShare / "sweethome3d.jar";
  std::string appVersion;
  if (fs::is_regular_file(jar)) {
    appVersion = installedVersion(kAppPackage);
  } else {
    const auto [root, version] = unpackedPackage(kAppPackage, options.debCache, log);
    jar = root / "usr/share/sweethome3d/sweethome3d.jar";
    appVersion = version;
    if (!fs::is_regular_file(jar))
      throw FileError(jar, "not found in the unpacked sweethome3d package");
  }
  sources.push_back({jar, true, "default", kAppPackage, appVersion});
  return sources;
}

}  // namespace sagrid
