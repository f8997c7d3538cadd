// Circles printed on upward-facing textured surfaces: the cooking zones and touch symbols of glass
// hobs, which exist only in the texture and give the network no geometry to find. The textured
// tops are rasterized top-down (the highest surface wins), the luminance edges vote for circle
// centres along their gradient (a Hough transform), and circles whose circumference the edges
// support are kept, concentric ones merged. Sizes are shares of the printed area's largest extent,
// so no units are needed: zones 5-30 % of it, symbols 0.6-3 %. Touch symbols may also be oval
// outlines (a stadium: two round ends joined by straight sides), as the power or slider key of
// real induction hobs is.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace sagrid {

struct Mesh;

struct PrintedCircle {
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();  // mesh frame (z-up), on the printed surface
  float radius = 0;   // mesh units; an oval symbol's is half its length
  float support = 0;  // share of the circumference its edges cover, in [0, 1]
};

struct PrintedMarks {
  std::vector<PrintedCircle> zones;    // cooking-zone sized, best supported first
  std::vector<PrintedCircle> symbols;  // touch-symbol sized, outside every zone
  bool empty() const { return zones.empty() && symbols.empty(); }
};

// What makes two round ends (Hough peaks of the symbol radii) an oval symbol's.
struct OvalShape {
  float minEndDrawn = 0.4f;  // share of each end's circle drawn (a half circle's is about 0.5)
  // Distance between the ends' centres in their radii: from a clear stretch to a long key (1 to
  // 6 radii); maxLength 0 = no oval symbols.
  float minLength = 1.0f, maxLength = 6.0f;
};

struct PrintedMarkSettings {
  int pixels = 768;          // raster size along the printed area's largest extent
  float minUpNormal = 0.9f;  // triangles whose normal's z is at least this are tops
  float edgeStep = 0.06f;    // luminance step (Sobel, per pixel) that makes an edge
  // Circumference share a circle's edges must cover: lettering has letters nearly as round as
  // touch symbols, so those must be drawn closed.
  float zoneSupport = 0.7f, symbolSupport = 0.9f;
  float zoneMin = 0.05f, zoneMax = 0.3f;        // zone radius / largest extent
  float symbolMin = 0.006f, symbolMax = 0.03f;  // symbol radius / largest extent
  // A touch panel's symbols stand together: of three or more, a symbol whose nearest other lies
  // farther than this many times the median distance from a symbol to its nearest other is a
  // mark of another kind (a logo or a hot-surface sign at the back of a real induction hob) and is
  // left out; 0 = keep every symbol.
  float isolatedSymbolSpacings = 2.5f;
  // Oval symbols; their outline must be drawn as a round symbol's is (symbolSupport).
  OvalShape ovals;
};

// The symbols of `symbols` that stand with the others (PrintedMarkSettings::isolatedSymbolSpacings
// = `spacings`); all of them when fewer than three or `spacings` <= 0. Their order is kept.
std::vector<PrintedCircle> symbolsStandingTogether(const std::vector<PrintedCircle>& symbols,
                                                   float spacings);

// Empty for meshes without textured upward-facing triangles (the common case, and cheap).
PrintedMarks findPrintedMarks(const Mesh& mesh, const PrintedMarkSettings& settings = {});

}  // namespace sagrid
