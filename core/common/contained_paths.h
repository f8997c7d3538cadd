// Containment for paths built from data (issue 14): an id or name read from a labels file or a
// mesh never chooses where SAGrid reads or writes. Two tools:
//  - safeFileName / UniqueFileNames turn any text into one plain file-name component (no
//    separators, no "..", no NUL, bounded length), deterministically and collision-free in a run;
//  - resolveContained resolves a reference a file makes (labels' object.mesh, an OBJ's mtllib,
//    an MTL's texture) inside the referencing object's own folder and refuses anything else.
#pragma once

#include <cstddef>
#include <filesystem>
#include <set>
#include <string>
#include <string_view>

namespace sagrid {

inline constexpr std::size_t kMaxSafeFileNameLength = 64;

// One path component made from `text`: ASCII letters, digits, '-', '_' and '.' are kept, every
// other byte (separators, NUL, markup, spaces, non-ASCII) becomes '_'; leading dots are dropped
// (no hidden files, no "." or ".."); empty text becomes `fallback`. Text longer than `maxLength`
// keeps a prefix plus '-' and 8 hex digits of its sha256, so long inputs that share a prefix stay
// distinct. Same input, same output; inputs that differ only in replaced bytes may meet, which
// UniqueFileNames resolves within a run.
std::string safeFileName(std::string_view text, std::size_t maxLength = kMaxSafeFileNameLength,
                         std::string_view fallback = "object");

// Hands out safe file names that are unique within one run (one export): a name already given
// (compared case-insensitively, for case-insensitive file systems) gets "-2", "-3", ... appended.
class UniqueFileNames {
 public:
  explicit UniqueFileNames(std::size_t maxLength = kMaxSafeFileNameLength)
      : m_maxLength(maxLength) {}
  std::string claim(std::string_view text, std::string_view fallback = "object");

 private:
  std::size_t m_maxLength;
  std::set<std::string> m_taken;  // lower-cased
};

// The file `reference` names, as written inside `referencingFile`, resolved against `folder`
// (the object's own folder). Backslashes count as separators (Windows-made OBJ/MTL files).
// Throws FileError naming `referencingFile` when the reference is empty, holds a NUL byte, is
// absolute (/x, \x, C:x), climbs out with "..", has a name longer than 255 bytes, or leads
// outside `folder` through a symbolic link. The file itself need not exist; callers check that.
std::filesystem::path resolveContained(const std::filesystem::path& folder,
                                       std::string_view reference,
                                       const std::filesystem::path& referencingFile);

// True when `path` (existing or not) lies inside `folder` after resolving symbolic links.
bool isInsideFolder(const std::filesystem::path& path, const std::filesystem::path& folder);

}  // namespace sagrid
