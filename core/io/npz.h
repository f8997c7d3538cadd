// NumPy .npy / .npz files: the interchange format of feature caches and of TRELLIS's toolkit.
// Arrays are C-order, little-endian, of dtype uint8, int32, int64, float32, float64 or bool.
// .npz is a zip of "<name>.npy" entries; we write stored (uncompressed) entries and read both
// stored and deflate-compressed ones (np.savez_compressed). Writes are atomic.
#pragma once

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/common/error.h"

namespace sagrid {

struct NpyArray {
  std::string dtype;                 // "uint8", "int32", "int64", "float32", "float64", "bool"
  std::vector<std::size_t> shape;    // empty for a scalar
  std::vector<std::uint8_t> data;    // elementCount() * itemSize() bytes, C order, little-endian

  std::size_t elementCount() const;
  std::size_t itemSize() const;

  template <typename T>
  static NpyArray from(const std::vector<T>& values, std::vector<std::size_t> shape);
  template <typename T>
  static NpyArray from(const std::vector<T>& values) { return from(values, {values.size()}); }

  template <typename T>
  bool is() const { return dtype == dtypeName<T>(); }
  // The values as T; throws InvalidArgument when the dtype is not exactly T's.
  template <typename T>
  std::vector<T> as() const;
  // The values converted to double from any numeric dtype (for reading loosely typed files).
  std::vector<double> asDouble() const;

  template <typename T>
  static const char* dtypeName();
};

using NpzArchive = std::map<std::string, NpyArray>;

// In-memory .npy encoding; `source` names the file (or entry) in error messages.
NpyArray parseNpy(std::string_view bytes, const std::filesystem::path& source);
std::string serializeNpy(const NpyArray& array);

NpyArray readNpy(const std::filesystem::path& path);
void writeNpy(const std::filesystem::path& path, const NpyArray& array);
// Keys are the entry names without ".npy", as numpy.load(...)[key] sees them.
NpzArchive readNpz(const std::filesystem::path& path);
void writeNpz(const std::filesystem::path& path, const NpzArchive& archive);

// ---- template definitions

template <typename T>
const char* NpyArray::dtypeName() {
  if constexpr (std::is_same_v<T, std::uint8_t>) return "uint8";
  else if constexpr (std::is_same_v<T, std::int32_t>) return "int32";
  else if constexpr (std::is_same_v<T, std::int64_t>) return "int64";
  else if constexpr (std::is_same_v<T, float>) return "float32";
  else if constexpr (std::is_same_v<T, double>) return "float64";
  else if constexpr (std::is_same_v<T, bool>) return "bool";
  else static_assert(sizeof(T) == 0, "unsupported npy element type");
}

template <typename T>
NpyArray NpyArray::from(const std::vector<T>& values, std::vector<std::size_t> shape) {
  NpyArray array;
  array.dtype = dtypeName<T>();
  array.shape = std::move(shape);
  if (array.elementCount() != values.size()) {
    throw InvalidArgument("npy: shape holds " + std::to_string(array.elementCount()) +
                          " elements but " + std::to_string(values.size()) + " values were given");
  }
  array.data.resize(values.size() * sizeof(T));
  if constexpr (std::is_same_v<T, bool>) {
    for (std::size_t i = 0; i < values.size(); ++i) array.data[i] = values[i] ? 1 : 0;
  } else if (!values.empty()) {
    std::memcpy(array.data.data(), values.data(), array.data.size());
  }
  return array;
}

template <typename T>
std::vector<T> NpyArray::as() const {
  if (!is<T>()) {
    throw InvalidArgument(std::string("npy: array has dtype ") + dtype + ", expected " + dtypeName<T>());
  }
  std::vector<T> values(elementCount());
  if constexpr (std::is_same_v<T, bool>) {
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = data[i] != 0;
  } else if (!values.empty()) {
    std::memcpy(values.data(), data.data(), values.size() * sizeof(T));
  }
  return values;
}

}  // namespace sagrid
