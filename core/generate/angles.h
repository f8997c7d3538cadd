// Angles in the procedural generators are radians; one definition of pi for all of them.
#pragma once

namespace sagrid::gen {

inline constexpr float kPi = 3.14159265358979f;

}  // namespace sagrid::gen
