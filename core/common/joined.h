// A list for a message: the items' text in order, separated by ", " (or `separator`).
#pragma once

#include <string>

namespace sagrid {

template <class Items>
std::string joined(const Items& items, const std::string& separator = ", ") {
  std::string text;
  bool first = true;
  for (const auto& item : items) {
    if (!first) text += separator;
    text += item;
    first = false;
  }
  return text;
}

}  // namespace sagrid
