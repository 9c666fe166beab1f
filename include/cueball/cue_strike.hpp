// The cue strike, for a robot: where and how hard to hit.
//
// Standard instantaneous-impact model of a cue striking a ball (D. G.
// Alciatore, "Technical Proofs" TP A.30 "Effects of cue tip offset on cue
// ball speed and spin", and W. C. Marlow, "The Physics of Pocket Billiards",
// 1995, ch. 6): the impulse J is along a level cue, through the contact point
// at height b above the ball's centre. Then
//     v0 = J / m,   w0 = J b / I = 5 J b / (2 m R^2)   =>   b = 2 R^2 w0 / (5 v0),
// so natural roll (R w0 = v0) needs b = 2R/5 (the ball's 70 % height), a stun
// shot b = 0, and draw b < 0. With a cue of mass M_c and tip restitution e,
//     v0 = (1 + e) V / (1 + m / M_c + 5 b^2 / (2 R^2))     (TP A.30, e = 1 there).
// Tips slip ("miscue") beyond about half the ball's radius from the centre
// (Alciatore TP A.30/A.31): cue_tip_offset_ok() tells.
#pragma once

#include "cueball/parameters.hpp"

namespace cueball {

struct CueParameters {
  double mass = 0.54;              ///< M_c, kg (19 oz, Alciatore's typical cue)
  double tip_restitution = 0.75;   ///< e, cue tip-ball (Alciatore: 0.71-0.87)
};

/// Largest tip offset from the ball's centre before the tip slips, as a
/// fraction of R (Alciatore: about 0.5).
inline constexpr double kMiscueOffsetFraction = 0.5;

/// Height b of the tip above the ball's centre, m, for a level cue that gives
/// speed v0 > 0 and topspin w0 (positive = forward roll).
double level_cue_tip_height(double v0, double w0, const BallParameters& ball);

/// Cue speed V, m/s, that gives ball speed v0 when striking at height b.
double level_cue_speed(double v0, double tip_height, const BallParameters& ball, const CueParameters& cue);

/// True when |b| is within the miscue limit kMiscueOffsetFraction * R.
bool cue_tip_offset_ok(double tip_height, const BallParameters& ball);

}  // namespace cueball
