// OmniGibson model names: exactly 6 letters. The importer asserts it (BEHAVIOR-1K,
// OmniGibson/examples/objects/import_custom_object.py, import_custom_object():
// `len(model) == 6 and model.isalpha()`), and the model names the object's folder, URDF and
// USD. Names are derived from the object id, deterministically, and unique within one export.
#pragma once

#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace sagrid::exportdetail {

inline constexpr std::size_t kOmniGibsonModelNameLength = 6;

// True for exactly 6 lower-case ASCII letters.
bool isOmniGibsonModelName(std::string_view name);

class OmniGibsonModelNames {
 public:
  // The first 6 ASCII letters of `id`, lower-cased ("flat_stove" -> "flatst"). An id with fewer
  // letters is completed with letters drawn from its sha256, and a name already given in this
  // export keeps the id's first 3 letters and takes 3 more from the sha256 of the id and an
  // attempt number; both say so in `warnings`.
  std::string claim(std::string_view id, std::vector<std::string>& warnings);

 private:
  std::set<std::string> m_taken;
};

}  // namespace sagrid::exportdetail
