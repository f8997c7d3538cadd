#include "core/features/printed_marks.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

#include "core/mesh/mesh.h"

namespace sagrid {

namespace {

constexpr float kPi = 3.14159265358979f;

float luminance(const Eigen::Vector3f& rgb) {
  return 0.2126f * rgb.x() + 0.7152f * rgb.y() + 0.0722f * rgb.z();
}

// The textured tops seen from above: luminance and height per pixel, and which pixels a top covers.
struct TopRaster {
  int width = 0, height = 0;
  float pixel = 0;  // mesh units
  Eigen::Vector2f origin = Eigen::Vector2f::Zero();
  std::vector<float> lum, z;
  std::vector<char> covered;

  std::size_t at(int x, int y) const { return static_cast<std::size_t>(y) * width + x; }
  Eigen::Vector2f centreOf(float x, float y) const {
    return origin + pixel * Eigen::Vector2f(x + 0.5f, y + 0.5f);
  }
};

bool isTexturedTop(const Mesh& mesh, std::size_t t, float minUpNormal) {
  if (mesh.uvs.empty() || mesh.triangleMaterials.empty()) return false;
  const int m = mesh.triangleMaterials[t];
  if (m < 0 || m >= static_cast<int>(mesh.materials.size()) || mesh.materials[m].texture < 0)
    return false;
  const Eigen::Vector3i& tri = mesh.triangles[t];
  const Eigen::Vector3f n = (mesh.positions[tri[1]] - mesh.positions[tri[0]])
                                .cross(mesh.positions[tri[2]] - mesh.positions[tri[0]]);
  const float length = n.norm();
  return length > 0 && n.z() >= minUpNormal * length;
}

TopRaster rasterizeTops(const Mesh& mesh, const std::vector<std::size_t>& tops, int pixels) {
  Eigen::AlignedBox2f box;
  for (std::size_t t : tops)
    for (int k = 0; k < 3; ++k) box.extend(mesh.positions[mesh.triangles[t][k]].head<2>());
  TopRaster r;
  const float extent = box.sizes().maxCoeff();
  if (!(extent > 0)) return r;
  r.pixel = extent / static_cast<float>(pixels);
  r.origin = box.min();
  r.width = static_cast<int>(std::ceil(box.sizes().x() / r.pixel)) + 1;
  r.height = static_cast<int>(std::ceil(box.sizes().y() / r.pixel)) + 1;
  const std::size_t count = static_cast<std::size_t>(r.width) * r.height;
  r.lum.assign(count, 0.0f);
  r.z.assign(count, -std::numeric_limits<float>::infinity());
  r.covered.assign(count, 0);
  for (std::size_t t : tops) {
    const Eigen::Vector3i& tri = mesh.triangles[t];
    const Eigen::Vector3f& a = mesh.positions[tri[0]];
    const Eigen::Vector3f& b = mesh.positions[tri[1]];
    const Eigen::Vector3f& c = mesh.positions[tri[2]];
    const Eigen::Vector2f e1 = (b - a).head<2>(), e2 = (c - a).head<2>();
    const float det = e1.x() * e2.y() - e1.y() * e2.x();
    if (std::abs(det) < 1e-12f) continue;
    Eigen::AlignedBox2f tb;
    for (const auto* p : {&a, &b, &c}) tb.extend(p->head<2>());
    const int x0 = std::max(0, static_cast<int>((tb.min().x() - r.origin.x()) / r.pixel));
    const int x1 = std::min(r.width - 1, static_cast<int>((tb.max().x() - r.origin.x()) / r.pixel));
    const int y0 = std::max(0, static_cast<int>((tb.min().y() - r.origin.y()) / r.pixel));
    const int y1 =
        std::min(r.height - 1, static_cast<int>((tb.max().y() - r.origin.y()) / r.pixel));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const Eigen::Vector2f d =
            r.centreOf(static_cast<float>(x), static_cast<float>(y)) - a.head<2>();
        const float u = (d.x() * e2.y() - d.y() * e2.x()) / det;
        const float v = (e1.x() * d.y() - e1.y() * d.x()) / det;
        if (u < -1e-4f || v < -1e-4f || u + v > 1.0001f) continue;
        const float z = a.z() + u * (b.z() - a.z()) + v * (c.z() - a.z());
        const std::size_t i = r.at(x, y);
        if (z <= r.z[i]) continue;
        r.z[i] = z;
        r.lum[i] = luminance(mesh.albedo(static_cast<int>(t), u, v));
        r.covered[i] = 1;
      }
    }
  }
  return r;
}

// The raster averaged over factor x factor blocks; a block is covered when all its pixels are.
TopRaster downsampled(const TopRaster& r, int factor) {
  if (factor == 1) return r;
  TopRaster d;
  d.width = r.width / factor;
  d.height = r.height / factor;
  d.pixel = r.pixel * factor;
  d.origin = r.origin;
  const std::size_t count = static_cast<std::size_t>(d.width) * d.height;
  d.lum.assign(count, 0.0f);
  d.z.assign(count, 0.0f);
  d.covered.assign(count, 0);
  for (int y = 0; y < d.height; ++y) {
    for (int x = 0; x < d.width; ++x) {
      float sum = 0, zMax = -std::numeric_limits<float>::infinity();
      bool all = true;
      for (int dy = 0; dy < factor; ++dy)
        for (int dx = 0; dx < factor; ++dx) {
          const std::size_t i = r.at(x * factor + dx, y * factor + dy);
          all = all && r.covered[i];
          sum += r.lum[i];
          zMax = std::max(zMax, r.z[i]);
        }
      const std::size_t o = d.at(x, y);
      d.lum[o] = sum / static_cast<float>(factor * factor);
      d.z[o] = zMax;
      d.covered[o] = all;
    }
  }
  return d;
}

struct Circle {
  float x = 0, y = 0, radius = 0, support = 0;  // pixels of the raster searched
};

// Luminance edges of a raster: the gradient's unit direction where its step is large enough
// (Sobel, all eight neighbours on a top), else zero.
struct EdgeMap {
  int width = 0, height = 0;
  std::vector<Eigen::Vector2f> direction;
  bool at(int x, int y, const Eigen::Vector2f& radial, float minAlignment) const {
    if (x < 0 || y < 0 || x >= width || y >= height) return false;
    const Eigen::Vector2f& d = direction[static_cast<std::size_t>(y) * width + x];
    return d.squaredNorm() > 0 && std::abs(d.dot(radial)) >= minAlignment;
  }
};

EdgeMap edgesOf(const TopRaster& r, float edgeStep) {
  EdgeMap e;
  e.width = r.width;
  e.height = r.height;
  e.direction.assign(static_cast<std::size_t>(r.width) * r.height, Eigen::Vector2f::Zero());
  for (int y = 1; y + 1 < r.height; ++y) {
    for (int x = 1; x + 1 < r.width; ++x) {
      bool inside = true;
      for (int dy = -1; dy <= 1 && inside; ++dy)
        for (int dx = -1; dx <= 1; ++dx) inside = inside && r.covered[r.at(x + dx, y + dy)];
      if (!inside) continue;
      auto l = [&](int dx, int dy) { return r.lum[r.at(x + dx, y + dy)]; };
      const float gx = (l(1, -1) + 2 * l(1, 0) + l(1, 1) - l(-1, -1) - 2 * l(-1, 0) - l(-1, 1)) / 8;
      const float gy = (l(-1, 1) + 2 * l(0, 1) + l(1, 1) - l(-1, -1) - 2 * l(0, -1) - l(1, -1)) / 8;
      const float g = std::hypot(gx, gy);
      if (g >= edgeStep) e.direction[r.at(x, y)] = Eigen::Vector2f(gx / g, gy / g);
    }
  }
  return e;
}

// Whether an edge crosses the outline at `origin` + `distance` x `normal` at right angles (within
// a pixel of it along `normal`, its gradient along `normal`).
bool edgeAcross(const EdgeMap& edges, const Eigen::Vector2f& origin, const Eigen::Vector2f& normal,
                float distance) {
  for (float t : {0.0f, -1.0f, 1.0f}) {
    const Eigen::Vector2f q = origin + (distance + t) * normal;
    if (edges.at(static_cast<int>(std::lround(q.x())), static_cast<int>(std::lround(q.y())), normal,
                 0.8f))
      return true;
  }
  return false;
}

// The share of the circle's circumference where an edge crosses it at right angles: how much of
// it is really drawn.
float circumferenceSupport(const EdgeMap& edges, float cx, float cy, float radius) {
  const int samples = std::max(24, static_cast<int>(2 * kPi * radius));
  int hits = 0;
  for (int s = 0; s < samples; ++s) {
    const float a = 2 * kPi * static_cast<float>(s) / static_cast<float>(samples);
    const Eigen::Vector2f radial(std::cos(a), std::sin(a));
    hits += edgeAcross(edges, Eigen::Vector2f(cx, cy), radial, radius);
  }
  return static_cast<float>(hits) / static_cast<float>(samples);
}

// An oval key's outline (a stadium): the points `radius` from the segment between the centres
// `a` and `b` of its round ends, in raster pixels.
struct Oval {
  Eigen::Vector2f a = Eigen::Vector2f::Zero(), b = Eigen::Vector2f::Zero();
  float radius = 0;
  float length() const { return (b - a).norm(); }
};

// The share of the oval's outline, `grow` pixels outside it, that edges cross at right angles:
// its two half circles sampled by angle, its straight sides by length, about one sample a pixel.
float outlineSupport(const EdgeMap& edges, const Oval& oval, float grow) {
  const float radius = oval.radius + grow, length = oval.length();
  const Eigen::Vector2f along = (oval.b - oval.a) / length, across(-along.y(), along.x());
  const int arcSamples = std::max(12, static_cast<int>(kPi * radius));
  const int sideSamples = std::max(1, static_cast<int>(length));
  int hits = 0;
  for (int s = 0; s < arcSamples; ++s) {
    const float angle = kPi * (static_cast<float>(s) + 0.5f) / static_cast<float>(arcSamples);
    const Eigen::Vector2f out = std::sin(angle) * along + std::cos(angle) * across;
    hits += edgeAcross(edges, oval.b, out, radius);
    const Eigen::Vector2f back = -std::sin(angle) * along + std::cos(angle) * across;
    hits += edgeAcross(edges, oval.a, back, radius);
  }
  for (int s = 0; s < sideSamples; ++s) {
    const Eigen::Vector2f onAxis =
        oval.a + (static_cast<float>(s) + 0.5f) / static_cast<float>(sideSamples) * length * along;
    hits += edgeAcross(edges, onAxis, across, radius);
    hits += edgeAcross(edges, onAxis, -across, radius);
  }
  return static_cast<float>(hits) / static_cast<float>(2 * (arcSamples + sideSamples));
}

// A local maximum of the Hough votes for circles: a circle centre candidate, with the share of
// its circumference that edges really cross (`drawn`).
struct HoughPeak {
  float x = 0, y = 0, radius = 0, drawn = 0;
};

// Hough transform for circles of radius [rMin, rMax] pixels: every edge pixel votes at each
// radius along and against its gradient; local maxima of the votes (3x3 pixels, radius +- 1) that
// reach a third of the circumference are the peaks. The round end of an oval outline is one too,
// with about half its circle drawn.
std::vector<HoughPeak> houghPeaks(const EdgeMap& edges, int rMin, int rMax) {
  std::vector<HoughPeak> peaks;
  const int width = edges.width, height = edges.height;
  if (width < 3 || height < 3 || rMax < rMin || rMin < 1) return peaks;
  const int radii = rMax - rMin + 1;
  const std::size_t plane = static_cast<std::size_t>(width) * height;
  const auto at = [width](int x, int y) { return static_cast<std::size_t>(y) * width + x; };
  std::vector<float> votes(plane * radii, 0.0f);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const Eigen::Vector2f& d = edges.direction[at(x, y)];
      if (d.squaredNorm() == 0) continue;
      for (int k = 0; k < radii; ++k) {
        const float rad = static_cast<float>(rMin + k);
        for (float sign : {-1.0f, 1.0f}) {
          const int cx = static_cast<int>(std::lround(x + sign * rad * d.x()));
          const int cy = static_cast<int>(std::lround(y + sign * rad * d.y()));
          if (cx < 0 || cy < 0 || cx >= width || cy >= height) continue;
          votes[k * plane + at(cx, cy)] += 1.0f;
        }
      }
    }
  }
  for (int k = 0; k < radii; ++k) {
    const float rad = static_cast<float>(rMin + k);
    const float needed = 2 * kPi * rad / 3;
    for (int y = 1; y + 1 < height; ++y) {
      for (int x = 1; x + 1 < width; ++x) {
        const float v = votes[k * plane + at(x, y)];
        if (v < 0.25f * needed) continue;
        float sum = 0;
        bool isMax = true;
        for (int kk = std::max(0, k - 1); kk <= std::min(radii - 1, k + 1); ++kk)
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              const float w = votes[kk * plane + at(x + dx, y + dy)];
              sum += w;
              if (w > v) isMax = false;
            }
        if (!isMax || sum < needed) continue;
        const float fx = static_cast<float>(x), fy = static_cast<float>(y);
        peaks.push_back({fx, fy, rad, circumferenceSupport(edges, fx, fy, rad)});
      }
    }
  }
  return peaks;
}

// Keeps the candidates that do not overlap a better supported one (or one already in `kept`),
// best supported first; of equal support the larger (a zone's outer ring). Centres closer than
// 0.6 of the larger radius overlap.
void keepApart(std::vector<Circle> candidates, std::vector<Circle>& kept) {
  std::stable_sort(candidates.begin(), candidates.end(), [](const Circle& a, const Circle& b) {
    return a.support != b.support ? a.support > b.support : a.radius > b.radius;
  });
  for (const Circle& c : candidates) {
    const bool merged = std::any_of(kept.begin(), kept.end(), [&](const Circle& o) {
      return std::hypot(c.x - o.x, c.y - o.y) < 0.6f * std::max(c.radius, o.radius);
    });
    if (!merged) kept.push_back(c);
  }
}

// `drawn` less the clutter: the least of `supportAt(grow)` on the outlines 5, 9 and 13 pixels
// outside the mark. Where edges run everywhere (a noisy texture) they also cross those (inside, a
// symbol has its icon): only the share beyond that clutter counts. The least of the three: a
// straight line drawn beside a key (an underline) runs along an outline only where it is nearly
// tangent to it, a band a few pixels wide, and crosses the others at a slant; noise is on all of
// them.
template <typename SupportAt>
float beyondClutter(float drawn, SupportAt supportAt) {
  return drawn - std::min({supportAt(5.0f), supportAt(9.0f), supportAt(13.0f)});
}

// The circles among the peaks whose edges really run around a share `minSupport` of them, more
// than around the circles 5, 9 and 13 pixels outside them (past a drawn line's other edge, and
// not thrown off by a line drawn beside it), concentric and overlapping ones merged.
std::vector<Circle> drawnCircles(const EdgeMap& edges, const std::vector<HoughPeak>& peaks,
                                 float minSupport) {
  std::vector<Circle> candidates;
  for (const HoughPeak& p : peaks) {
    // The rings are read only where the circle itself is covered enough: clutter can only
    // lower its support.
    if (p.drawn < minSupport) continue;
    const float support = beyondClutter(p.drawn, [&](float grow) {
      return circumferenceSupport(edges, p.x, p.y, p.radius + grow);
    });
    if (support >= minSupport) candidates.push_back({p.x, p.y, p.radius, support});
  }
  std::vector<Circle> out;
  keepApart(std::move(candidates), out);
  return out;
}

// Oval outlines (stadiums) among the peaks: two peaks of about the same radius (within a pixel),
// each with at least `minEndDrawn` of its circle drawn, `minLength` to `maxLength` radii apart,
// are the round ends of an oval when edges run around `minSupport` of its outline, beyond the
// clutter on the outlines 5, 9 and 13 pixels outside it (as for circles). Returned unmerged, as
// circles at the ovals' centres whose radius is half their length.
std::vector<Circle> drawnOvals(const EdgeMap& edges, const std::vector<HoughPeak>& peaks,
                               const OvalShape& shape, float minSupport) {
  std::vector<HoughPeak> ends;
  std::copy_if(peaks.begin(), peaks.end(), std::back_inserter(ends),
               [&](const HoughPeak& p) { return p.drawn >= shape.minEndDrawn; });
  std::vector<Circle> candidates;
  for (std::size_t i = 0; i < ends.size(); ++i) {
    for (std::size_t j = i + 1; j < ends.size(); ++j) {
      const HoughPeak &p = ends[i], &q = ends[j];
      if (std::abs(p.radius - q.radius) > 1) continue;
      const Oval oval{{p.x, p.y}, {q.x, q.y}, 0.5f * (p.radius + q.radius)};
      const float length = oval.length();
      if (length < shape.minLength * oval.radius || length > shape.maxLength * oval.radius)
        continue;
      const float drawn = outlineSupport(edges, oval, 0);
      if (drawn < minSupport) continue;
      const float support =
          beyondClutter(drawn, [&](float grow) { return outlineSupport(edges, oval, grow); });
      if (support < minSupport) continue;
      const Eigen::Vector2f centre = 0.5f * (oval.a + oval.b);
      candidates.push_back({centre.x(), centre.y(), 0.5f * length + oval.radius, support});
    }
  }
  return candidates;
}

PrintedCircle toMesh(const TopRaster& full, const TopRaster& searched, const Circle& c) {
  PrintedCircle p;
  const Eigen::Vector2f xy = searched.centreOf(c.x, c.y);
  const int fx =
      std::clamp(static_cast<int>((xy.x() - full.origin.x()) / full.pixel), 0, full.width - 1);
  const int fy =
      std::clamp(static_cast<int>((xy.y() - full.origin.y()) / full.pixel), 0, full.height - 1);
  p.centre = Eigen::Vector3f(xy.x(), xy.y(), full.z[full.at(fx, fy)]);
  p.radius = c.radius * searched.pixel;
  p.support = c.support;
  return p;
}

}  // namespace

PrintedMarks findPrintedMarks(const Mesh& mesh, const PrintedMarkSettings& settings) {
  PrintedMarks marks;
  std::vector<std::size_t> tops;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (isTexturedTop(mesh, t, settings.minUpNormal)) tops.push_back(t);
  if (tops.empty()) return marks;
  const TopRaster full = rasterizeTops(mesh, tops, settings.pixels);
  if (full.width == 0) return marks;
  // Zones on a raster of a third of the resolution: their outlines are wide enough there.
  const int zoneFactor = 3;
  const TopRaster coarse = downsampled(full, zoneFactor);
  const float coarsePixels = static_cast<float>(settings.pixels) / zoneFactor;
  const EdgeMap coarseEdges = edgesOf(coarse, settings.edgeStep);
  const std::vector<HoughPeak> zonePeaks =
      houghPeaks(coarseEdges, static_cast<int>(settings.zoneMin * coarsePixels),
                 static_cast<int>(settings.zoneMax * coarsePixels));
  for (const Circle& c : drawnCircles(coarseEdges, zonePeaks, settings.zoneSupport)) {
    const PrintedCircle zone = toMesh(full, coarse, c);
    if (std::isfinite(zone.centre.z())) marks.zones.push_back(zone);
  }
  const float pixels = static_cast<float>(settings.pixels);
  const EdgeMap edges = edgesOf(full, settings.edgeStep);
  const std::vector<HoughPeak> symbolPeaks =
      houghPeaks(edges, std::max(2, static_cast<int>(settings.symbolMin * pixels)),
                 static_cast<int>(settings.symbolMax * pixels));
  std::vector<Circle> symbols = drawnCircles(edges, symbolPeaks, settings.symbolSupport);
  if (settings.ovals.maxLength > 0)
    keepApart(drawnOvals(edges, symbolPeaks, settings.ovals, settings.symbolSupport), symbols);
  for (const Circle& c : symbols) {
    const PrintedCircle symbol = toMesh(full, full, c);
    if (!std::isfinite(symbol.centre.z())) continue;
    // A dot or a ring inside a zone marks the zone, not a control.
    const bool inZone =
        std::any_of(marks.zones.begin(), marks.zones.end(), [&](const PrintedCircle& z) {
          return (symbol.centre - z.centre).head<2>().norm() < 1.05f * z.radius;
        });
    if (!inZone) marks.symbols.push_back(symbol);
  }
  marks.symbols = symbolsStandingTogether(marks.symbols, settings.isolatedSymbolSpacings);
  return marks;
}

std::vector<PrintedCircle> symbolsStandingTogether(const std::vector<PrintedCircle>& symbols,
                                                   float spacings) {
  if (symbols.size() < 3 || spacings <= 0) return symbols;
  std::vector<float> nearest;
  for (std::size_t i = 0; i < symbols.size(); ++i) {
    float d = std::numeric_limits<float>::infinity();
    for (std::size_t j = 0; j < symbols.size(); ++j)
      if (j != i) d = std::min(d, (symbols[i].centre - symbols[j].centre).norm());
    nearest.push_back(d);
  }
  std::vector<float> sorted = nearest;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const float reach = spacings * sorted[sorted.size() / 2];
  std::vector<PrintedCircle> kept;
  for (std::size_t i = 0; i < symbols.size(); ++i)
    if (nearest[i] <= reach) kept.push_back(symbols[i]);
  return kept;
}

}  // namespace sagrid
