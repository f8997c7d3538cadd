#include "core/io/npz.h"

#include <algorithm>
#include <cctype>

#include "core/common/atomic_file.h"
#include "core/io/little_endian.h"
#include "core/io/zip_archive.h"

namespace sagrid {
namespace fs = std::filesystem;

namespace {

using io::u16;
using io::u32;
using io::put16;

struct DtypeInfo {
  const char* name;
  const char* descr;  // numpy array-protocol type string, little-endian
  std::size_t size;
};
constexpr DtypeInfo kDtypes[] = {{"uint8", "|u1", 1},   {"int32", "<i4", 4},   {"int64", "<i8", 8},
                                 {"float32", "<f4", 4}, {"float64", "<f8", 8}, {"bool", "|b1", 1}};

const DtypeInfo* findByName(const std::string& name) {
  for (const auto& d : kDtypes) {
    if (name == d.name) return &d;
  }
  return nullptr;
}

const DtypeInfo* findByDescr(std::string descr) {
  // '<' little-endian, '|' not applicable, '=' native (little-endian on every platform we run).
  if (!descr.empty() && (descr[0] == '=' || descr[0] == '<' || descr[0] == '|'))
    descr = descr.substr(1);
  for (const auto& d : kDtypes) {
    if (descr == std::string(d.descr).substr(1)) return &d;
  }
  return nullptr;
}


// Value of `key` in the header dict, e.g. "'<f4'" or "(3, 4)" or "False".
std::string headerValue(const std::string& header, const std::string& key, const fs::path& source) {
  const auto at = header.find("'" + key + "'");
  if (at == std::string::npos) throw FileError(source, "npy header has no '" + key + "'");
  std::size_t start = header.find(':', at);
  if (start == std::string::npos) throw FileError(source, "npy header is malformed");
  ++start;
  while (start < header.size() && header[start] == ' ') ++start;
  std::size_t end = start;
  if (start < header.size() && header[start] == '(') {
    end = header.find(')', start);
    if (end == std::string::npos) throw FileError(source, "npy header has an unterminated shape");
    return header.substr(start, end - start + 1);
  }
  while (end < header.size() && header[end] != ',' && header[end] != '}') ++end;
  std::string value = header.substr(start, end - start);
  while (!value.empty() && value.back() == ' ') value.pop_back();
  return value;
}

std::vector<std::size_t> parseShape(const std::string& text, const fs::path& source) {
  std::vector<std::size_t> shape;
  std::size_t i = 1;  // after '('
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ' ' || text[i] == ',')) ++i;
    if (i >= text.size() || text[i] == ')') break;
    if (!std::isdigit(static_cast<unsigned char>(text[i]))) {
      throw FileError(source, "npy header has a malformed shape " + text);
    }
    std::size_t value = 0;
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) {
      value = value * 10 + static_cast<std::size_t>(text[i] - '0');
      if (value > (std::size_t{1} << 48)) throw FileError(source, "npy shape is implausibly large");
      ++i;
    }
    shape.push_back(value);
  }
  return shape;
}

}  // namespace

std::size_t NpyArray::elementCount() const {
  std::size_t n = 1;
  for (std::size_t s : shape) n *= s;
  return n;
}

std::size_t NpyArray::itemSize() const {
  const DtypeInfo* info = findByName(dtype);
  if (!info) throw InvalidArgument("npy: unsupported dtype '" + dtype + "'");
  return info->size;
}

std::vector<double> NpyArray::asDouble() const {
  const std::size_t n = elementCount();
  std::vector<double> values(n);
  auto convert = [&](auto tag) {
    using T = decltype(tag);
    for (std::size_t i = 0; i < n; ++i) {
      T v;
      std::memcpy(&v, data.data() + i * sizeof(T), sizeof(T));
      values[i] = static_cast<double>(v);
    }
  };
  if (dtype == "uint8" || dtype == "bool")
    convert(std::uint8_t{});
  else if (dtype == "int32")
    convert(std::int32_t{});
  else if (dtype == "int64")
    convert(std::int64_t{});
  else if (dtype == "float32")
    convert(float{});
  else if (dtype == "float64")
    convert(double{});
  else
    throw InvalidArgument("npy: unsupported dtype '" + dtype + "'");
  return values;
}

NpyArray parseNpy(std::string_view bytes, const fs::path& source) {
  if (bytes.size() < 10 || bytes.substr(0, 6) != std::string_view("\x93NUMPY", 6)) {
    throw FileError(source, "is not a NumPy .npy array (bad magic)");
  }
  const int major = static_cast<unsigned char>(bytes[6]);
  std::size_t headerLength, headerStart;
  if (major == 1) {
    headerLength = u16(bytes, 8);
    headerStart = 10;
  } else if (major == 2 || major == 3) {
    if (bytes.size() < 12) throw FileError(source, "npy file is truncated");
    headerLength = u32(bytes, 8);
    headerStart = 12;
  } else {
    throw FileError(source, "npy format version " + std::to_string(major) + " is not supported");
  }
  if (headerStart + headerLength > bytes.size()) throw FileError(source, "npy header is truncated");
  const std::string header(bytes.substr(headerStart, headerLength));

  std::string descr = headerValue(header, "descr", source);
  if (descr.size() < 2 || (descr.front() != '\'' && descr.front() != '"')) {
    throw FileError(source, "npy dtype " + descr + " is not supported (structured arrays?)");
  }
  descr = descr.substr(1, descr.size() - 2);
  const DtypeInfo* info = findByDescr(descr);
  if (!info) {
    throw FileError(source, "npy dtype '" + descr +
                                "' is not supported (expected little-endian uint8, int32, int64, "
                                "float32, float64 or bool)");
  }
  if (headerValue(header, "fortran_order", source) != "False") {
    throw FileError(source, "npy array is in Fortran order; save it C-contiguous");
  }
  NpyArray array;
  array.dtype = info->name;
  array.shape = parseShape(headerValue(header, "shape", source), source);
  const std::size_t available = bytes.size() - headerStart - headerLength;
  // The product of the dimensions, checked against the bytes there before it can wrap around
  // (a shape of (2^40, 2^40) would otherwise claim a few bytes and allocate everything later).
  std::size_t elements = 1;
  for (std::size_t dim : array.shape) {
    if (dim != 0 && elements > available / dim) {
      bool empty = false;
      for (std::size_t d : array.shape) empty |= d == 0;
      if (empty) break;
      throw FileError(source, "npy shape claims more elements than the file holds (truncated?)");
    }
    elements *= dim;
  }
  const std::size_t expected = array.elementCount() * info->size;
  if (available < expected) {
    throw FileError(source, "npy data is truncated (" + std::to_string(available) + " of " +
                                std::to_string(expected) + " bytes)");
  }
  const auto* begin =
      reinterpret_cast<const std::uint8_t*>(bytes.data() + headerStart + headerLength);
  array.data.assign(begin, begin + expected);
  return array;
}

std::string serializeNpy(const NpyArray& array) {
  const DtypeInfo* info = findByName(array.dtype);
  if (!info) throw InvalidArgument("npy: unsupported dtype '" + array.dtype + "'");
  if (array.data.size() != array.elementCount() * info->size) {
    throw InvalidArgument("npy: " + std::to_string(array.data.size()) +
                          " data bytes do not fit shape and dtype " + array.dtype);
  }
  std::string shape = "(";
  for (std::size_t i = 0; i < array.shape.size(); ++i) {
    shape += std::to_string(array.shape[i]) +
             (array.shape.size() == 1 ? "," : (i + 1 < array.shape.size() ? ", " : ""));
  }
  shape += ")";
  std::string header = std::string("{'descr': '") + info->descr +
                       "', 'fortran_order': False, 'shape': " + shape + ", }";
  // numpy pads the header with spaces and a newline so the data starts 64-byte aligned.
  const std::size_t total = 10 + header.size() + 1;
  header.append((64 - total % 64) % 64, ' ');
  header += '\n';
  std::string out("\x93NUMPY\x01\x00", 8);
  put16(out, static_cast<std::uint32_t>(header.size()));
  out += header;
  out.append(reinterpret_cast<const char*>(array.data.data()), array.data.size());
  return out;
}

NpyArray readNpy(const fs::path& path) { return parseNpy(readFileBytes(path), path); }

void writeNpy(const fs::path& path, const NpyArray& array) {
  writeFileAtomic(path, serializeNpy(array));
}

NpzArchive readNpz(const fs::path& path) {
  const ZipArchive zip = ZipArchive::open(path);
  NpzArchive archive;
  for (const ZipEntry& entry : zip.entries()) {
    if (entry.isDirectory()) continue;
    const std::string content = zip.read(entry);
    std::string key = entry.name;
    if (key.size() > 4 && key.compare(key.size() - 4, 4, ".npy") == 0) key.resize(key.size() - 4);
    try {
      archive[key] = parseNpy(content, path.string() + ":" + entry.name);
    } catch (const FileError&) {
      throw;
    } catch (const Error& e) {
      throw FileError(path, "entry '" + entry.name + "': " + e.what());
    }
  }
  return archive;
}

void writeNpz(const fs::path& path, const NpzArchive& archive) {
  std::vector<std::pair<std::string, std::string>> entries;
  for (const auto& [key, array] : archive) entries.emplace_back(key + ".npy", serializeNpy(array));
  writeStoredZip(path, entries);
}

}  // namespace sagrid
