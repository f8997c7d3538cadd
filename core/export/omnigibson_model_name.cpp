#include "core/export/omnigibson_model_name.h"

#include <algorithm>
#include <cctype>

#include "core/common/sha256.h"

namespace sagrid::exportdetail {

namespace {

// `count` letters a-z drawn from the sha256 of `text`.
std::string hashLetters(const std::string& text, std::size_t count) {
  const std::string hex = sha256Hex(text);
  std::string letters;
  for (std::size_t i = 0; letters.size() < count && i + 1 < hex.size(); i += 2) {
    letters.push_back(static_cast<char>('a' + std::stoi(hex.substr(i, 2), nullptr, 16) % 26));
  }
  return letters;
}

}  // namespace

bool isOmniGibsonModelName(std::string_view name) {
  return name.size() == kOmniGibsonModelNameLength &&
         std::all_of(name.begin(), name.end(), [](char c) { return c >= 'a' && c <= 'z'; });
}

std::string OmniGibsonModelNames::claim(std::string_view id, std::vector<std::string>& warnings) {
  std::string letters;
  for (unsigned char c : id) {
    if (c < 0x80 && std::isalpha(c)) letters.push_back(static_cast<char>(std::tolower(c)));
  }
  const std::string shown(id.substr(0, std::min<std::size_t>(id.size(), 60)));
  std::string name = letters.substr(0, kOmniGibsonModelNameLength);
  if (name.size() < kOmniGibsonModelNameLength) {
    name += hashLetters(std::string(id), kOmniGibsonModelNameLength - name.size());
    warnings.push_back("id '" + shown + "' has fewer than 6 letters; OmniGibson model name '" +
                       name + "' (OmniGibson needs exactly 6 letters)");
  }
  if (m_taken.count(name)) {
    const std::string stem = letters.substr(0, 3);
    for (int attempt = 1; m_taken.count(name); ++attempt) {
      name = stem + hashLetters(std::string(id) + "#" + std::to_string(attempt),
                                kOmniGibsonModelNameLength - stem.size());
    }
    warnings.push_back("id '" + shown + "' shares its first 6 letters with another object of " +
                       "this export; OmniGibson model name '" + name + "'");
  }
  m_taken.insert(name);
  return name;
}

}  // namespace sagrid::exportdetail
