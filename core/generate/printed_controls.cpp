#include "core/generate/printed_controls.h"

#include <algorithm>
#include <cmath>

namespace sagrid::gen {

namespace {

using Vec2 = Eigen::Vector2f;
using Box2 = Eigen::AlignedBox2f;

enum class Symbol { Ring, RingWithDot, Disc, PlusMinus };

// Metres on the top to the painter's UV, and lengths to u units.
struct TopMapping {
  Box2 top;
  Vec2 uv(const Vec2& p) const { return (p - top.min()).cwiseQuotient(top.sizes()); }
  float u(float metres) const { return metres / top.sizes().x(); }
};

void paintSymbol(TexturePainter& painter, const TopMapping& map, Symbol symbol, const Vec2& c,
                 float radius, float line, const Eigen::Vector3f& color) {
  const Vec2 uv = map.uv(c);
  switch (symbol) {
    case Symbol::Ring:
      painter.ring(uv, map.u(radius), map.u(line), color);
      break;
    case Symbol::RingWithDot:
      painter.ring(uv, map.u(radius), map.u(line), color);
      painter.disc(uv, map.u(0.3f * radius), color);
      break;
    case Symbol::Disc:
      painter.disc(uv, map.u(radius), color);
      break;
    case Symbol::PlusMinus: {
      const Vec2 h(radius, 0.5f * line), v(0.5f * line, radius);
      painter.rect(map.uv(c - h), map.uv(c + h), color);
      painter.rect(map.uv(c - v), map.uv(c + v), color);
      break;
    }
  }
}

std::vector<Vec2> rowLayout(const Box2& area, int count) {
  const bool alongX = area.sizes().x() >= area.sizes().y();
  std::vector<Vec2> centres;
  for (int i = 0; i < count; ++i) {
    const float t = (i + 0.5f) / count;
    centres.push_back(alongX ? Vec2(area.min().x() + t * area.sizes().x(), area.center().y())
                             : Vec2(area.center().x(), area.min().y() + t * area.sizes().y()));
  }
  return centres;
}

// Rows of a few symbols each, every other row shifted by half a pitch as on many touch panels.
std::vector<Vec2> clusterLayout(Rng& rng, const Box2& area, int count, float pitch) {
  const int columns = std::max(2, static_cast<int>(std::ceil(std::sqrt(1.5 * count))));
  const int rows = (count + columns - 1) / columns;
  const bool staggered = rng.chance(0.5);
  const Vec2 centre = area.center();
  std::vector<Vec2> centres;
  for (int i = 0; i < count; ++i) {
    const int row = i / columns, column = i % columns;
    const int inRow = std::min(columns, count - row * columns);
    const float shift = staggered && row % 2 ? 0.5f * pitch : 0.0f;
    const float x = centre.x() + (column - 0.5f * (inRow - 1)) * pitch + shift;
    const float y = centre.y() + (0.5f * (rows - 1) - row) * pitch * 0.8f;
    centres.push_back(Vec2(x, y).cwiseMax(area.min()).cwiseMin(area.max()));
  }
  return centres;
}

}  // namespace

std::vector<Vec2> paintPrintedControls(Rng& rng, TexturePainter& painter, const Box2& top,
                                       const Box2& area, int count, const Eigen::Vector3f& color) {
  const TopMapping map{top};
  const bool cluster = count >= 4 && rng.chance(0.5);
  const float across = std::min(area.sizes().x(), area.sizes().y());
  const float along = std::max(area.sizes().x(), area.sizes().y());
  const float pitch = cluster ? rng.uniformf(0.02, 0.035) : along / count;
  std::vector<Vec2> centres =
      cluster ? clusterLayout(rng, area, count, pitch) : rowLayout(area, count);
  const float radius = std::min({rng.uniformf(0.004, 0.009), 0.4f * pitch, 0.4f * across});
  const float line = std::max(0.001f, radius * rng.uniformf(0.12, 0.25));
  const auto style = static_cast<Symbol>(rng.uniformInt(0, 3));
  const bool mixed = rng.chance(0.3);
  for (const Vec2& c : centres) {
    const Symbol symbol = mixed ? static_cast<Symbol>(rng.uniformInt(0, 3)) : style;
    paintSymbol(painter, map, symbol, c, radius, line, color);
  }
  return centres;
}

void paintPrintedLettering(Rng& rng, TexturePainter& painter, const Box2& top, const Box2& area,
                           const Eigen::Vector3f& color) {
  const TopMapping map{top};
  const int letters = rng.uniformInt(3, 8);
  const float height = rng.uniformf(0.006, 0.012);
  const float width = 0.6f * height;
  const Vec2 start(area.center().x() - 0.5f * letters * 1.3f * width, area.center().y());
  for (int i = 0; i < letters; ++i) {
    const Vec2 c = start + Vec2((i + 0.5f) * 1.3f * width, 0);
    const Vec2 half(0.5f * width * rng.uniformf(0.2, 1.0), 0.5f * height);
    painter.rect(map.uv(c - half), map.uv(c + half), color);
  }
}

}  // namespace sagrid::gen
