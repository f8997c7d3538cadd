// Touch controls that exist only in a glass hob's texture: symbols painted into the top's image,
// with no geometry of their own (the Sweet Home 3D induction hobs are drawn this way).
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "core/generate/random.h"
#include "core/generate/texture_painter.h"

namespace sagrid::gen {

// Paints `count` touch symbols inside `area` (metres, in the plane of the top) onto `painter`,
// whose image covers `top`, and returns the symbols' centres in metres. The symbols share one
// style per hob (outlined, filled or plus/minus marks, sometimes mixed) and lie in one row along
// the area's long side or in a compact cluster at its centre.
std::vector<Eigen::Vector2f> paintPrintedControls(Rng& rng, TexturePainter& painter,
                                                  const Eigen::AlignedBox2f& top,
                                                  const Eigen::AlignedBox2f& area, int count,
                                                  const Eigen::Vector3f& color);

// Printing on the glass that is not a control (a maker's name, a level scale), so that not every
// mark is a button: a few thin bars inside `area`.
void paintPrintedLettering(Rng& rng, TexturePainter& painter, const Eigen::AlignedBox2f& top,
                           const Eigen::AlignedBox2f& area, const Eigen::Vector3f& color);

}  // namespace sagrid::gen
