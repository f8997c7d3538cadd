#include "core/annotate/shard.h"

#include <charconv>
#include <cstdint>

#include "core/common/error.h"
#include "core/common/sha256.h"

namespace sagrid {

namespace {
std::uint64_t idHash(const std::string& id) {
  const std::string hex = sha256Hex(id).substr(0, 16);
  std::uint64_t value = 0;
  std::from_chars(hex.data(), hex.data() + hex.size(), value, 16);
  return value;
}

bool parseInt(const std::string& text, int& value) {
  if (text.empty()) return false;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size();
}
}  // namespace

bool Shard::contains(const std::string& objectId) const {
  return count <= 1 ||
         idHash(objectId) % static_cast<std::uint64_t>(count) == static_cast<std::uint64_t>(index);
}

std::string Shard::toString() const { return std::to_string(index) + "/" + std::to_string(count); }

Shard parseShard(const std::string& spec) {
  const auto slash = spec.find('/');
  Shard shard;
  const bool parsed = slash != std::string::npos && parseInt(spec.substr(0, slash), shard.index) &&
                      parseInt(spec.substr(slash + 1), shard.count);
  if (!parsed || shard.count < 1 || shard.index < 0 || shard.index >= shard.count) {
    throw InvalidArgument("--shard " + spec +
                          ": expected I/N with N >= 1 and 0 <= I < N (task I of N, counted from "
                          "0, e.g. 0/4 ... 3/4)");
  }
  return shard;
}

std::vector<MeshFile> filesInShard(const std::vector<MeshFile>& files, const Shard& shard) {
  std::vector<MeshFile> out;
  for (const auto& f : files)
    if (shard.contains(f.id)) out.push_back(f);
  return out;
}

}  // namespace sagrid
