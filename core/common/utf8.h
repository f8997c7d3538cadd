// UTF-8 validation for text files users hand us (labels.json, manifests), so a bad byte is
// reported with its offset instead of as an obscure parser error.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace sagrid {

// Byte offset of the first byte that is not part of a well-formed UTF-8 sequence (overlong
// forms, surrogates and code points above U+10FFFF count as ill-formed), or nullopt.
std::optional<std::size_t> firstInvalidUtf8(std::string_view text);

}  // namespace sagrid
