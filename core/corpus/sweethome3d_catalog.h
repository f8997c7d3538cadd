// Sweet Home 3D furniture catalogs: parsing the Java .properties files that list a library's
// models (PluginFurnitureCatalog.properties in a .sh3f, DefaultFurnitureCatalog.properties in the
// application jar), and the one place that decides which catalog entries enter the SAGrid real
// corpus and in which role (stove, sink, or a "none" appliance distractor), and under which id.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sagrid {

// A Java .properties file: bytes are ISO-8859-1, \uXXXX escapes (with UTF-16 surrogate pairs),
// backslash line continuations, '#'/'!' comments, '=', ':' or whitespace separators. Keys and
// values come back as UTF-8. Throws FileError naming `source` and the line for a bad \u escape.
std::map<std::string, std::string> parseJavaProperties(std::string_view bytes,
                                                       const std::filesystem::path& source);

struct FurnitureCatalogEntry {
  int index = 0;         // N of the "key#N" properties
  std::string id;        // e.g. "eTeks#cooker", "Blend Swap CC-0#stove"
  std::string name;      // English name
  std::string category;  // e.g. "Kitchen", "Bathroom"
  std::string creator;
  std::string model;  // path inside the archive, e.g. "/scopia/cooker/cooker.obj"
  std::optional<double> width, depth, height;        // cm
  std::optional<std::vector<double>> modelRotation;  // 3x3, row-major, when given
};

struct FurnitureCatalog {
  std::string id, name, license, version;  // library-level lines (empty for the default catalog)
  std::vector<FurnitureCatalogEntry> entries;  // ordered by index
};

// Entries without an id or a model are skipped (they are not furniture). Throws FileError for
// unparsable numbers, naming the key.
FurnitureCatalog parseFurnitureCatalog(std::string_view bytes, const std::filesystem::path& source);

enum class CorpusRole { Stove, Sink, None };
const char* toString(CorpusRole role);  // "stove", "sink", "none"

// The selection rules, in one place. Only entries of category Kitchen or Bathroom are considered;
// the English name decides, first match wins:
//   stove: cooker, cooktop, stove, hob
//   sink:  sink, washbasin, lavatory, basin, vanity — unless the name, with "basin" removed,
//          still mentions "bath" (bathtubs and bath-shower combinations are not sinks)
//   none (appliance distractor): oven, microwave, coffee machine/maker/brewer, dishwasher, hood,
//          fridge, refrigerator, washing machine, clothes washer, toaster, deep fryer, sandwich
//          (maker), grill, kettle, blender, mixer, dryer
// Matching is case-insensitive on substrings, as the labeller's listing script does, so ids and
// roles agree with the labels shipped in resources/datasets/sweethome3d.
std::optional<CorpusRole> selectCorpusRole(const FurnitureCatalogEntry& entry);

inline constexpr std::size_t kMaxCorpusIdLength = 64;

// The catalog id lowercased, each run of characters outside [a-z0-9] replaced by one '_', trimmed
// of '_': "Scopia#bathroom3" -> "scopia_bathroom3", "eTeks#cooker" -> "eteks_cooker". Ids longer
// than kMaxCorpusIdLength keep their start and end in an 8-hex-digit hash of the full id.
std::string corpusObjectId(const std::string& catalogId);

}  // namespace sagrid
