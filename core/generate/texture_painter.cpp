#include "core/generate/texture_painter.h"

#include <algorithm>
#include <cmath>

namespace sagrid::gen {

namespace {
std::uint8_t toByte(float v) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}
}  // namespace

TexturePainter::TexturePainter(int width, int height, const Eigen::Vector3f& background) {
  m_texture.width = width;
  m_texture.height = height;
  m_texture.rgba.resize(static_cast<std::size_t>(width) * height * 4);
  for (std::size_t i = 0; i < m_texture.rgba.size(); i += 4) {
    m_texture.rgba[i] = toByte(background.x());
    m_texture.rgba[i + 1] = toByte(background.y());
    m_texture.rgba[i + 2] = toByte(background.z());
    m_texture.rgba[i + 3] = 255;
  }
  m_aspect = static_cast<float>(height) / width;
}

template <typename Inside>
void TexturePainter::fill(const Eigen::Vector2f& minUv, const Eigen::Vector2f& maxUv,
                          const Eigen::Vector3f& color, Inside inside) {
  const int w = m_texture.width, h = m_texture.height;
  const int x0 = std::max(0, static_cast<int>(std::floor(minUv.x() * w)));
  const int x1 = std::min(w - 1, static_cast<int>(std::ceil(maxUv.x() * w)));
  // Row 0 is the top of the image, which is v = 1.
  const int y0 = std::max(0, static_cast<int>(std::floor((1.0f - maxUv.y()) * h)));
  const int y1 = std::min(h - 1, static_cast<int>(std::ceil((1.0f - minUv.y()) * h)));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const Eigen::Vector2f uv((x + 0.5f) / w, 1.0f - (y + 0.5f) / h);
      if (!inside(uv)) continue;
      std::uint8_t* p = &m_texture.rgba[(static_cast<std::size_t>(y) * w + x) * 4];
      p[0] = toByte(color.x());
      p[1] = toByte(color.y());
      p[2] = toByte(color.z());
    }
  }
}

void TexturePainter::disc(const Eigen::Vector2f& c, float r, const Eigen::Vector3f& color) {
  const float rv = r / m_aspect;
  fill(c - Eigen::Vector2f(r, rv), c + Eigen::Vector2f(r, rv), color, [&](const Eigen::Vector2f& uv) {
    const Eigen::Vector2f d(uv.x() - c.x(), (uv.y() - c.y()) * m_aspect);
    return d.squaredNorm() <= r * r;
  });
}

void TexturePainter::ring(const Eigen::Vector2f& c, float r, float width, const Eigen::Vector3f& color) {
  const float outer = r + 0.5f * width, inner = std::max(0.0f, r - 0.5f * width);
  const float rv = outer / m_aspect;
  fill(c - Eigen::Vector2f(outer, rv), c + Eigen::Vector2f(outer, rv), color,
       [&](const Eigen::Vector2f& uv) {
         const Eigen::Vector2f d(uv.x() - c.x(), (uv.y() - c.y()) * m_aspect);
         const float n2 = d.squaredNorm();
         return n2 <= outer * outer && n2 >= inner * inner;
       });
}

void TexturePainter::rect(const Eigen::Vector2f& lo, const Eigen::Vector2f& hi, const Eigen::Vector3f& color) {
  fill(lo, hi, color, [&](const Eigen::Vector2f& uv) {
    return uv.x() >= lo.x() && uv.x() <= hi.x() && uv.y() >= lo.y() && uv.y() <= hi.y();
  });
}

void TexturePainter::speckle(float amount, unsigned seed) {
  unsigned state = seed * 2654435761u + 1u;
  for (std::size_t i = 0; i < m_texture.rgba.size(); i += 4) {
    state = state * 1664525u + 1013904223u;  // fixed LCG: identical bytes everywhere
    const int delta = static_cast<int>((state >> 24) % 256) - 128;
    const int d = static_cast<int>(delta * amount);
    for (int k = 0; k < 3; ++k) {
      m_texture.rgba[i + k] = static_cast<std::uint8_t>(std::clamp(m_texture.rgba[i + k] + d, 0, 255));
    }
  }
}

Texture TexturePainter::take() && { return std::move(m_texture); }

}  // namespace sagrid::gen
