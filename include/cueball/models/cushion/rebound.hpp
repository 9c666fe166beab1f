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

}  // namespace cueball
