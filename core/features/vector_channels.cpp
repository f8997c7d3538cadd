#include "core/features/vector_channels.h"

namespace sagrid {

std::vector<std::array<int, 3>> vectorChannelTriples(const std::vector<std::string>& names) {
  std::vector<std::array<int, 3>> triples;
  auto endsWith = [](const std::string& s, const char* suffix) {
    return s.size() > 2 && s.compare(s.size() - 2, 2, suffix) == 0;
  };
  for (std::size_t c = 0; c + 2 < names.size(); ++c) {
    const std::string& x = names[c];
    if (!endsWith(x, "_x")) continue;
    const std::string base = x.substr(0, x.size() - 2);
    if (names[c + 1] == base + "_y" && names[c + 2] == base + "_z") {
      triples.push_back({static_cast<int>(c), static_cast<int>(c + 1), static_cast<int>(c + 2)});
      c += 2;
    }
  }
  return triples;
}

}  // namespace sagrid
