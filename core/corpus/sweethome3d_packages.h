// Where the Sweet Home 3D corpus's archives come from: Debian's sweethome3d-furniture libraries
// (.sh3f), the default catalog in sweethome3d.jar and, when asked, sweethome3d-furniture-nonfree;
// installed files, else .debs downloaded with apt-get and unpacked with dpkg -x.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace sagrid {

// One archive to read: a furniture library (.sh3f, catalog PluginFurnitureCatalog.properties) or
// the application jar (catalog com/eteks/sweethome3d/io/DefaultFurnitureCatalog.properties).
struct SweetHome3dSource {
  std::filesystem::path archive;
  bool isJar = false;
  std::string library;         // the .sh3f file's stem, or "default" for the jar
  std::string package;         // Debian package, e.g. "sweethome3d-furniture"
  std::string packageVersion;  // empty when unknown
};

struct SweetHome3dPackageOptions {
  std::filesystem::path debCache;             // where .debs are downloaded and unpacked
  std::filesystem::path installedRoot = "/";  // where an installed package's files are looked for
  std::vector<std::filesystem::path> sh3f;    // explicit archives: skip the package lookup
  std::optional<std::filesystem::path> jar;
  // Also the libraries of sweethome3d-furniture-nonfree (Debian's non-free component: models
  // under their authors' licences, e.g. the Free Art License): installed, else downloaded through
  // a private apt configuration that reads that component alone.
  bool nonFree = false;
};

// The archives to read: the explicit ones when given; else the installed files under
// /usr/share/sweethome3d; else `apt-get download` of both packages (and with nonFree the third)
// into debCache and `dpkg -x`.
// Throws Error saying what to install when neither works. `log` receives one line per action.
std::vector<SweetHome3dSource> locateSweetHome3dSources(
    const SweetHome3dPackageOptions& options,
    const std::function<void(const std::string&)>& log = {});

}  // namespace sagrid
