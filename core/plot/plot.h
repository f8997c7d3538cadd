// Small PNG charts for reports (training loss curves, evaluation bar charts): an RGB canvas with
// lines, rectangles and stb_easy_font text, written atomically with stb_image_write. Good enough
// to look at a result; not a plotting library.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace sagrid::plot {

using Color = std::array<unsigned char, 3>;

struct Series {
  std::string name;
  std::vector<double> x, y;
  Color color{31, 119, 180};
};

struct LinePlot {
  std::string title, xLabel, yLabel;
  std::vector<Series> series;
  bool logY = false;
};

struct BarGroup {
  std::string label;           // e.g. an affordance type
  std::vector<double> values;  // one per method; NaN = missing
};

struct BarChart {
  std::string title, yLabel;
  std::vector<std::string> methods;  // legend, one colour each
  std::vector<BarGroup> groups;
};

// Both throw FileError when the file cannot be written and InvalidArgument for empty data.
void writeLinePlotPng(const std::filesystem::path& file, const LinePlot& plot, int width = 800,
                      int height = 500);
void writeBarChartPng(const std::filesystem::path& file, const BarChart& chart, int width = 900,
                      int height = 500);

// The canvas behind the charts (exposed for tests).
class Canvas {
 public:
  Canvas(int width, int height, Color background = {255, 255, 255});
  void set(int x, int y, Color c);
  Color at(int x, int y) const;
  void line(double x0, double y0, double x1, double y1, Color c, int thickness = 1);
  void fillRect(int x0, int y0, int x1, int y1, Color c);
  void text(int x, int y, const std::string& text, Color c, int scale = 1);
  static int textWidth(const std::string& text, int scale = 1);
  std::string encodePng() const;
  int width() const { return m_width; }
  int height() const { return m_height; }

 private:
  int m_width, m_height;
  std::vector<unsigned char> m_rgb;
};

}  // namespace sagrid::plot
