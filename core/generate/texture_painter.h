// Paints procedural textures (flat glass cooking zones, printed markings) into an RGBA image.
// Coordinates are texture UVs in [0,1] with v = 0 at the bottom row, as Mesh and OBJ use them.
#pragma once

#include <Eigen/Core>

#include "core/mesh/mesh.h"

namespace sagrid::gen {

class TexturePainter {
 public:
  TexturePainter(int width, int height, const Eigen::Vector3f& background);

  // A filled disc and a ring (annulus) in UV units; radii are in u units (aspect corrected).
  void disc(const Eigen::Vector2f& centerUv, float radiusU, const Eigen::Vector3f& color);
  void ring(const Eigen::Vector2f& centerUv, float radiusU, float widthU, const Eigen::Vector3f& color);
  void rect(const Eigen::Vector2f& minUv, const Eigen::Vector2f& maxUv, const Eigen::Vector3f& color);
  // Faint speckle so large flat areas are not one exact colour.
  void speckle(float amount, unsigned seed);

  Texture take() &&;

 private:
  template <typename Inside>
  void fill(const Eigen::Vector2f& minUv, const Eigen::Vector2f& maxUv, const Eigen::Vector3f& color,
            Inside inside);
  Texture m_texture;
  float m_aspect;  // height / width: v distances scale by this to be in u units
};

}  // namespace sagrid::gen
