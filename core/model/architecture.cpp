#include "core/model/architecture.h"

#include <cctype>
#include <sstream>

#include "core/common/error.h"

namespace sagrid::model {
namespace {

[[noreturn]] void fail(const std::string& text, const std::string& problem) {
  throw InvalidArgument("architecture \"" + text + "\": " + problem +
                        " (expected Table I form, e.g. \"[3,1,32],[3,2,32,2],[3,1,16]\": "
                        "[kernel,padding,out_channels] or [kernel,padding,out_channels,dilation])");
}

}  // namespace

const char* toString(ExecutionMode mode) {
  return mode == ExecutionMode::Sparse ? "sparse" : "dense";
}

ExecutionMode parseExecutionMode(const std::string& text) {
  if (text == "sparse") return ExecutionMode::Sparse;
  if (text == "dense") return ExecutionMode::Dense;
  throw InvalidArgument("execution mode \"" + text + "\": expected \"sparse\" or \"dense\"");
}

Architecture Architecture::parse(const std::string& text) {
  Architecture arch;
  std::size_t pos = 0;
  auto skipSpace = [&] {
    while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
  };
  skipSpace();
  if (pos == text.size()) fail(text, "it is empty");
  while (true) {
    skipSpace();
    const int layerNumber = static_cast<int>(arch.layers.size()) + 1;
    const std::string where = "layer " + std::to_string(layerNumber);
    if (pos >= text.size() || text[pos] != '[') fail(text, where + ": expected '['");
    ++pos;
    std::vector<long> values;
    while (true) {
      skipSpace();
      std::size_t start = pos;
      if (pos < text.size() && (text[pos] == '-' || text[pos] == '+')) ++pos;
      while (pos < text.size() && std::isdigit(static_cast<unsigned char>(text[pos]))) ++pos;
      if (start == pos ||
          (pos - start == 1 && !std::isdigit(static_cast<unsigned char>(text[start]))))
        fail(text, where + ": expected an integer at position " + std::to_string(start + 1));
      if (pos - start > 7) fail(text, where + ": number too large");
      values.push_back(std::stol(text.substr(start, pos - start)));
      skipSpace();
      if (pos < text.size() && text[pos] == ',') {
        ++pos;
        continue;
      }
      if (pos < text.size() && text[pos] == ']') {
        ++pos;
        break;
      }
      fail(text, where + ": expected ',' or ']' at position " + std::to_string(pos + 1));
    }
    if (values.size() < 3 || values.size() > 4)
      fail(text, where + " has " + std::to_string(values.size()) + " numbers, needs 3 or 4");
    ConvLayerSpec layer;
    layer.kernel = static_cast<int>(values[0]);
    layer.padding = static_cast<int>(values[1]);
    layer.outChannels = static_cast<int>(values[2]);
    layer.dilation = values.size() == 4 ? static_cast<int>(values[3]) : 1;
    if (layer.kernel < 1 || layer.kernel % 2 == 0)
      fail(text, where + ": kernel must be odd and positive, got " + std::to_string(layer.kernel));
    if (layer.outChannels < 1 || layer.outChannels > 4096)
      fail(text,
           where + ": out_channels must be in 1..4096, got " + std::to_string(layer.outChannels));
    if (layer.dilation < 1 || layer.dilation > 16)
      fail(text, where + ": dilation must be in 1..16, got " + std::to_string(layer.dilation));
    const int same = layer.dilation * (layer.kernel - 1) / 2;
    if (layer.padding != same)
      fail(text, where + ": padding " + std::to_string(layer.padding) +
                     " would change the grid size; with kernel " + std::to_string(layer.kernel) +
                     " and dilation " + std::to_string(layer.dilation) + " it must be " +
                     std::to_string(same));
    arch.layers.push_back(layer);
    skipSpace();
    if (pos == text.size()) break;
    if (text[pos] != ',')
      fail(text, "expected ',' between layers at position " + std::to_string(pos + 1));
    ++pos;
  }
  if (arch.layers.size() > 32) fail(text, "more than 32 layers");
  return arch;
}

std::string Architecture::toString() const {
  std::ostringstream out;
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const auto& l = layers[i];
    if (i) out << ',';
    out << '[' << l.kernel << ',' << l.padding << ',' << l.outChannels;
    if (l.dilation != 1) out << ',' << l.dilation;
    out << ']';
  }
  return out.str();
}

int Architecture::receptiveRadius() const {
  int r = 0;
  for (const auto& l : layers) r += l.dilation * (l.kernel - 1) / 2;
  return r;
}

}  // namespace sagrid::model
