// The part of the mesh a toggle button point switches with, and how it moves: a rotary knob
// turns about the normal of the panel it stands on, or about its own axis of rotational symmetry
// where it clearly has one (control_symmetry.h), a lever about its pivot at the held end; a long
// grip held alike at both ends (a bar across a knob's face, a cross on a stem) has no held end and
// turns as a knob with what holds it, about that holder's axis of rotational symmetry; a
// push button or touch key slides along its normal. One mechanism for every file: the part is the
// small component of the point's material it lies on (with the small components inside its box:
// a knob's pointer, its cap), else the same over connected triangles whatever their material,
// else the surface grown around the point up to where it stops standing out of the panel; a point
// on nothing that stands out (a key printed on glass) gets a thin disc. A component is small when
// no other point lies on it, it is nearer this point than any other and holds little of the
// object; one the point lies well inside (a large knob labelled at its centre) is taken however
// large, if no other point lies on it and it holds at most kMaxControlAreaShare of the surface.
// Everything in the mesh's z-up frame and units.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace sagrid {

struct Mesh;
class SurfaceScene;

enum class ControlMotion { Knob, Lever, Button };
// Marked: the curator's triangles (the GUI's Grow, Shrink and brush), what `eval --parts` measures
// the found parts against.
enum class PartOrigin { Connected, Material, Grown, Disc, Marked };

const char* toString(ControlMotion motion);
const char* toString(PartOrigin origin);
std::optional<ControlMotion> parseControlMotion(const std::string& text);
std::optional<PartOrigin> parsePartOrigin(const std::string& text);

// A knob or lever is a hinge, a button a slide.
inline bool isHinge(ControlMotion motion) { return motion != ControlMotion::Button; }

struct ControlPart {
  std::vector<int> triangles;  // sorted indices into the mesh's triangles; empty for a disc
  ControlMotion motion = ControlMotion::Knob;
  PartOrigin origin = PartOrigin::Connected;
  // Hinge: the axis (a positive turn lifts a lever's free end away from what holds it; a knob's
  // points out of the panel). Slide: the direction a press moves it (into the panel). Unit length.
  Eigen::Vector3f axis = Eigen::Vector3f::UnitZ();
  Eigen::Vector3f pivot = Eigen::Vector3f::Zero();  // on the hinge axis; a slide's part centre
  float radius = 0;  // half the part's largest extent across the axis (a disc's radius)
};

struct ControlParts {
  std::vector<std::optional<ControlPart>> parts;  // per point; nullopt: a site only
  std::vector<std::string> warnings;  // per point: why it was left a site or got a disc; or empty
};

// A part is refused (site only) when it would take most of the object: more than this share of
// its surface (a faucet's lever handle alone can hold a third of it).
inline constexpr float kMaxControlAreaShare = 0.5f;

// The part of each point of `points` (toggle button points, mesh frame). Points are told apart:
// a part never holds what lies nearer another point.
ControlParts findControlParts(const Mesh& mesh, const std::vector<Eigen::Vector3f>& points);
// The same with `scene` built on `mesh` already (annotate has one): its points' nearest triangles
// come from it instead of a new one.
ControlParts findControlParts(const Mesh& mesh, const SurfaceScene& scene,
                              const std::vector<Eigen::Vector3f>& points);

// Where the part of `triangles` goes when pressed as a button (unit length): into what holds it;
// for a flat key level with what holds it, along its thinnest direction against the way it faces
// (one open sheet) or towards the middle of the object.
Eigen::Vector3f pressDirection(const Mesh& mesh, const std::vector<int>& triangles);

// The motion of a given part (the curator's triangles): its axis and pivot from its shape and
// from where the rest of the mesh holds it.
ControlPart describeControlPart(const Mesh& mesh, std::vector<int> triangles, PartOrigin origin);

// The point a knob or button of `triangles` turns or slides about: the mean of the part's distinct
// vertices (as describeControlPart places it); the origin for no valid triangle.
Eigen::Vector3f partCentre(const Mesh& mesh, const std::vector<int>& triangles);

}  // namespace sagrid
