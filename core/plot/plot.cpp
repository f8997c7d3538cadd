#include "core/plot/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/common/third_party_warnings.h"
SAGRID_THIRD_PARTY_BEGIN
#include <stb_easy_font.h>
SAGRID_THIRD_PARTY_END
#include <stb_image_write.h>

#include "core/common/atomic_file.h"
#include "core/common/error.h"

namespace sagrid::plot {
namespace {

const Color kAxis{40, 40, 40};
const Color kGrid{225, 225, 225};
const Color kPalette[] = {{31, 119, 180},  {255, 127, 14}, {44, 160, 44},   {214, 39, 40},
                          {148, 103, 189}, {140, 86, 75},  {227, 119, 194}, {127, 127, 127}};

std::string formatTick(double v) {
  char buffer[32];
  const double a = std::abs(v);
  if (a != 0 && (a < 1e-3 || a >= 1e5))
    std::snprintf(buffer, sizeof buffer, "%.1e", v);
  else
    std::snprintf(buffer, sizeof buffer, "%.4g", v);
  return buffer;
}

// "Nice" tick step for a range (1, 2, 5 x 10^n).
double niceStep(double range, int ticks) {
  const double raw = range / std::max(1, ticks);
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}

void writePng(const std::filesystem::path& file, const Canvas& canvas) {
  writeFileAtomic(file, canvas.encodePng());
}

}  // namespace

Canvas::Canvas(int width, int height, Color background)
    : m_width(width), m_height(height), m_rgb(static_cast<std::size_t>(width) * height * 3) {
  for (std::size_t i = 0; i < m_rgb.size(); i += 3)
    std::copy(background.begin(), background.end(), &m_rgb[i]);
}

void Canvas::set(int x, int y, Color c) {
  if (x < 0 || y < 0 || x >= m_width || y >= m_height) return;
  std::copy(c.begin(), c.end(), &m_rgb[(static_cast<std::size_t>(y) * m_width + x) * 3]);
}

Color Canvas::at(int x, int y) const {
  const auto* p = &m_rgb[(static_cast<std::size_t>(y) * m_width + x) * 3];
  return {p[0], p[1], p[2]};
}

void Canvas::line(double x0, double y0, double x1, double y1, Color c, int thickness) {
  const int steps = static_cast<int>(std::max(std::abs(x1 - x0), std::abs(y1 - y0))) + 1;
  for (int s = 0; s <= steps; ++s) {
    const double t = static_cast<double>(s) / steps;
    const int x = static_cast<int>(std::lround(x0 + t * (x1 - x0)));
    const int y = static_cast<int>(std::lround(y0 + t * (y1 - y0)));
    for (int dx = -(thickness - 1) / 2; dx <= thickness / 2; ++dx)
      for (int dy = -(thickness - 1) / 2; dy <= thickness / 2; ++dy) set(x + dx, y + dy, c);
  }
}

void Canvas::fillRect(int x0, int y0, int x1, int y1, Color c) {
  for (int y = std::min(y0, y1); y <= std::max(y0, y1); ++y)
    for (int x = std::min(x0, x1); x <= std::max(x0, x1); ++x) set(x, y, c);
}

void Canvas::text(int x, int y, const std::string& text, Color c, int scale) {
  // stb_easy_font emits quads (4 vertices of x, y, z, colour = 16 bytes each).
  static char buffer[99999];
  std::string copy = text;
  const int quads = stb_easy_font_print(0, 0, copy.data(), nullptr, buffer, sizeof buffer);
  for (int q = 0; q < quads; ++q) {
    const float* v = reinterpret_cast<const float*>(buffer + q * 64);
    const float qx0 = v[0], qy0 = v[1], qx1 = v[8], qy1 = v[9];
    fillRect(x + static_cast<int>(qx0 * scale), y + static_cast<int>(qy0 * scale),
             x + static_cast<int>(qx1 * scale) - 1, y + static_cast<int>(qy1 * scale) - 1, c);
  }
}

int Canvas::textWidth(const std::string& text, int scale) {
  std::string copy = text;
  return stb_easy_font_width(copy.data()) * scale;
}

std::string Canvas::encodePng() const {
  std::string out;
  stbi_write_png_to_func(
      [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), size);
      },
      &out, m_width, m_height, 3, m_rgb.data(), m_width * 3);
  if (out.empty()) throw Error("PNG encoding failed");
  return out;
}

void writeLinePlotPng(const std::filesystem::path& file, const LinePlot& plot, int width,
                      int height) {
  double xMin = std::numeric_limits<double>::max(), xMax = -xMin, yMin = xMin, yMax = -xMin;
  auto ty = [&](double y) { return plot.logY ? std::log10(std::max(y, 1e-12)) : y; };
  for (const auto& s : plot.series)
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      if (!std::isfinite(s.y[i])) continue;
      xMin = std::min(xMin, s.x[i]), xMax = std::max(xMax, s.x[i]);
      yMin = std::min(yMin, ty(s.y[i])), yMax = std::max(yMax, ty(s.y[i]));
    }
  if (xMin > xMax) throw InvalidArgument("line plot \"" + plot.title + "\": no data");
  if (xMax == xMin) xMax = xMin + 1;
  if (yMax == yMin) yMax = yMin + 1;
  const double pad = 0.05 * (yMax - yMin);
  yMin -= pad, yMax += pad;
  Canvas c(width, height);
  const int left = 80, right = width - 20, top = 40, bottom = height - 50;
  auto px = [&](double x) { return left + (x - xMin) / (xMax - xMin) * (right - left); };
  auto py = [&](double y) { return bottom - (y - yMin) / (yMax - yMin) * (bottom - top); };
  const double step = niceStep(yMax - yMin, 6);
  for (double v = std::ceil(yMin / step) * step; v <= yMax; v += step) {
    c.line(left, py(v), right, py(v), kGrid);
    const std::string label = formatTick(plot.logY ? std::pow(10.0, v) : v);
    c.text(left - 8 - Canvas::textWidth(label), static_cast<int>(py(v)) - 3, label, kAxis);
  }
  const double xStep = niceStep(xMax - xMin, 8);
  for (double v = std::ceil(xMin / xStep) * xStep; v <= xMax; v += xStep) {
    c.line(px(v), bottom, px(v), bottom + 4, kAxis);
    const std::string label = formatTick(v);
    c.text(static_cast<int>(px(v)) - Canvas::textWidth(label) / 2, bottom + 8, label, kAxis);
  }
  c.line(left, top, left, bottom, kAxis);
  c.line(left, bottom, right, bottom, kAxis);
  for (std::size_t k = 0; k < plot.series.size(); ++k) {
    const auto& s = plot.series[k];
    for (std::size_t i = 1; i < std::min(s.x.size(), s.y.size()); ++i)
      if (std::isfinite(s.y[i - 1]) && std::isfinite(s.y[i]))
        c.line(px(s.x[i - 1]), py(ty(s.y[i - 1])), px(s.x[i]), py(ty(s.y[i])), s.color, 2);
    c.fillRect(right - 150, top + 5 + 14 * static_cast<int>(k), right - 140,
               top + 12 + 14 * static_cast<int>(k), s.color);
    c.text(right - 135, top + 4 + 14 * static_cast<int>(k), s.name, kAxis);
  }
  c.text(left, 12, plot.title, kAxis, 2);
  c.text((left + right) / 2 - Canvas::textWidth(plot.xLabel) / 2, height - 20, plot.xLabel, kAxis);
  c.text(8, top - 16, plot.yLabel, kAxis);
  writePng(file, c);
}

void writeBarChartPng(const std::filesystem::path& file, const BarChart& chart, int width,
                      int height) {
  if (chart.groups.empty() || chart.methods.empty())
    throw InvalidArgument("bar chart \"" + chart.title + "\": no data");
  double yMax = 0;
  for (const auto& g : chart.groups)
    for (double v : g.values)
      if (std::isfinite(v)) yMax = std::max(yMax, v);
  if (yMax <= 0) yMax = 1;
  yMax *= 1.1;
  Canvas c(width, height);
  const int left = 80, right = width - 180, top = 40, bottom = height - 50;
  auto py = [&](double y) { return bottom - y / yMax * (bottom - top); };
  const double step = niceStep(yMax, 6);
  for (double v = 0; v <= yMax; v += step) {
    c.line(left, py(v), right, py(v), kGrid);
    const std::string label = formatTick(v);
    c.text(left - 8 - Canvas::textWidth(label), static_cast<int>(py(v)) - 3, label, kAxis);
  }
  const double groupWidth = static_cast<double>(right - left) / chart.groups.size();
  const double barWidth = groupWidth * 0.8 / chart.methods.size();
  for (std::size_t g = 0; g < chart.groups.size(); ++g) {
    const double x0 = left + g * groupWidth + groupWidth * 0.1;
    for (std::size_t m = 0; m < chart.methods.size() && m < chart.groups[g].values.size(); ++m) {
      const double v = chart.groups[g].values[m];
      if (!std::isfinite(v)) continue;
      c.fillRect(static_cast<int>(x0 + m * barWidth), static_cast<int>(py(v)),
                 static_cast<int>(x0 + (m + 1) * barWidth) - 2, bottom, kPalette[m % 8]);
    }
    const std::string& label = chart.groups[g].label;
    c.text(static_cast<int>(x0 + groupWidth * 0.4) - Canvas::textWidth(label) / 2, bottom + 8,
           label, kAxis);
  }
  c.line(left, top, left, bottom, kAxis);
  c.line(left, bottom, right, bottom, kAxis);
  for (std::size_t m = 0; m < chart.methods.size(); ++m) {
    const int y = top + 14 * static_cast<int>(m);
    c.fillRect(right + 15, y + 1, right + 25, y + 8, kPalette[m % 8]);
    c.text(right + 30, y, chart.methods[m], kAxis);
  }
  c.text(left, 12, chart.title, kAxis, 2);
  c.text(8, top - 16, chart.yLabel, kAxis);
  writePng(file, c);
}

}  // namespace sagrid::plot
