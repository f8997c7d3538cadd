// Where SAGrid finds the resources it ships (default models, sample meshes, bundled datasets):
// the working directory's resources/ (a checkout), then the installed share/sagrid beside the
// binary (<prefix>/bin/../share/sagrid, so /usr/bin/sagrid finds /usr/share/sagrid and a
// relocated root such as a `dpkg -x` folder works too), then the source tree the binary was built
// from (a build-tree binary run from anywhere).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sagrid {

// The folders that may hold the resources, in the order they are tried: ./resources,
// <folder of the running binary>/../share/sagrid, <source dir>/resources.
std::vector<std::filesystem::path> resourceRoots();

// <root>/<relative> for the first root where that is a directory; when no root has it, the path
// under the second root (the installed location: an error then names where an installed binary
// looks, not a source tree that exists only on the build machine).
std::filesystem::path findResourceDir(const std::string& relative,
                                      const std::vector<std::filesystem::path>& roots);
std::filesystem::path resourceDir(const std::string& relative);  // with resourceRoots()

// The default model folder: resourceDir("models").
std::filesystem::path defaultModelsDir();

// The running binary's folder (from /proc/self/exe); empty when it cannot be read.
std::filesystem::path executableDir();

}  // namespace sagrid
