// What every ball-cushion model returns: the ball's velocity and spin just
// after the impact, in the impact frame of cushion_impact.hpp (X along the
// cushion, Y horizontal into the cushion, Z up). The models themselves live
// one to a file in this folder (and cushion_impact.hpp for Mathavan 2010);
// cushion_model.hpp chooses one by name.
#pragma once

#include "cueball/core/vec.hpp"

namespace cueball {

struct CushionRebound {
  Vec3 velocity;          ///< (xG', yG', zG'), m/s; yG' <= 0 (leaving the cushion), zG' = 0
  Vec3 angular_velocity;  ///< rad/s
};

/// The impact frame of a wall (paper 000, Figs 2-4) from its inward normal n
/// at the contact (n points from the wall into the playing area): Y
/// horizontal into the wall = -n, Z up, X = Y x Z. The simulator passes a
/// ball to a model in it and takes the rebound back out of it.
struct CushionImpactFrame {
  Vec2 x, y;
  explicit CushionImpactFrame(Vec2 inward_normal) : x{-inward_normal.y, inward_normal.x}, y{-inward_normal} {}
  /// A table-frame vector with horizontal part v and vertical part z, in the frame.
  Vec3 to_frame(Vec2 v, double z) const { return {dot(v, x), dot(v, y), z}; }
  /// The horizontal part, in the table frame, of a vector in the frame.
  Vec2 from_frame(Vec3 v) const { return v.x * x + v.y * y; }
};

}  // namespace cueball
