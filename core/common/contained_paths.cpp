#include "core/common/contained_paths.h"

#include <algorithm>
#include <cctype>
#include <system_error>

#include "core/common/ascii_case.h"
#include "core/common/error.h"
#include "core/common/sha256.h"

namespace sagrid {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxFileNameBytes = 255;  // NAME_MAX of Linux file systems

bool isKeptByte(unsigned char c) {
  return (c < 0x80 && std::isalnum(c)) || c == '-' || c == '_' || c == '.';
}

// Resolves symbolic links of the longest existing prefix (weakly_canonical), without throwing.
fs::path resolvedForComparison(const fs::path& path) {
  std::error_code ec;
  fs::path resolved = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec) return fs::absolute(path).lexically_normal();
  return resolved;
}

}  // namespace

std::string safeFileName(std::string_view text, std::size_t maxLength, std::string_view fallback) {
  std::string name;
  name.reserve(text.size());
  for (unsigned char c : text) name.push_back(isKeptByte(c) ? static_cast<char>(c) : '_');
  name.erase(0, name.find_first_not_of('.'));  // npos erases everything: text of only dots
  if (name.empty()) name = std::string(fallback);
  constexpr std::size_t kHashLength = 8;
  maxLength = std::max<std::size_t>(maxLength, kHashLength + 2);
  if (name.size() > maxLength) {
    name =
        name.substr(0, maxLength - kHashLength - 1) + "-" + sha256Hex(text).substr(0, kHashLength);
  }
  return name;
}

std::string UniqueFileNames::claim(std::string_view text, std::string_view fallback) {
  const std::string base = safeFileName(text, m_maxLength, fallback);
  std::string name = base;
  for (int n = 2; m_taken.count(asciiLower(name)); ++n) {
    const std::string suffix = "-" + std::to_string(n);
    name = base.substr(0, std::min(base.size(), m_maxLength - suffix.size())) + suffix;
  }
  m_taken.insert(asciiLower(name));
  return name;
}

bool isInsideFolder(const fs::path& path, const fs::path& folder) {
  const fs::path root = resolvedForComparison(folder);
  const fs::path target = resolvedForComparison(path);
  const auto mismatch = std::mismatch(root.begin(), root.end(), target.begin(), target.end());
  // Every component of the folder matched; an empty trailing component ("dir/") counts as none.
  return mismatch.first == root.end() ||
         (std::next(mismatch.first) == root.end() && mismatch.first->empty());
}

fs::path resolveContained(const fs::path& folder, std::string_view reference,
                          const fs::path& referencingFile) {
  const std::string shown(reference.substr(0, std::min<std::size_t>(reference.size(), 120)));
  auto refuse = [&](const std::string& why) {
    throw FileError(referencingFile, "refusing the referenced file '" + shown + "': " + why +
                                         " (referenced files must lie inside " + folder.string() +
                                         ")");
  };
  if (reference.empty()) refuse("the name is empty");
  if (reference.find('\0') != std::string_view::npos) refuse("the name holds a NUL byte");
  std::string text(reference);
  std::replace(text.begin(), text.end(), '\\', '/');
  if (text.front() == '/') refuse("it is an absolute path");
  if (text.size() >= 2 && std::isalpha(static_cast<unsigned char>(text[0])) && text[1] == ':')
    refuse("it is an absolute path");
  const fs::path relative = fs::path(text).lexically_normal();
  if (relative.empty() || *relative.begin() == ".." || relative == ".")
    refuse("it climbs out of the object's folder");
  for (const auto& part : relative) {
    if (part.native().size() > kMaxFileNameBytes) refuse("a name in it is longer than 255 bytes");
  }
  const fs::path resolved = folder / relative;
  if (!isInsideFolder(resolved, folder)) refuse("it leads outside the folder through a link");
  return resolved;
}

}  // namespace sagrid
