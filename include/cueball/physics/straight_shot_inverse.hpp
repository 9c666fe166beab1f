// The inverse problem of paper 001 (Jaroukh 2019, eqs 17-28): which initial
// speed v0 and topspin w0 bring a ball, struck straight along a line, to a
// planned point x2 with a planned speed v2 there.
//
// Positions are measured along the line of the shot, increasing in the
// direction of travel. w0 is topspin: positive turns the ball the way it
// rolls (R w0 = v0 is natural roll, w0 < 0 is draw / backspin).
//
// The paper's unknowns Z = v0 - R w0 (eq. 17) and N = 5 v0 + 2 R w0 (eq. 18)
// fix the motion: sliding lasts t1 = 2Z / (7 mu_s g) (19), ends at speed
// v1 = N / 7 (20) after x1 - x0 = 2 Z (N + Z) / (49 mu_s g) (21), and rolling
// covers x2 - x1 = 7 (v1^2 - v2^2) / (10 mu_r g) (24). Without x1 the problem
// has a one-parameter family of answers; each call below picks one member and
// says which. All four are closed forms (a quadratic in Z at most); the
// distance is monotonic in Z on the valid range, so each answer is unique.
//
// Validity (paper 001 after eq. 23): v0 >= R w0 >= -5/2 v0, i.e. Z >= 0 and
// N >= 0: the ball never reverses and is never overspun. A request outside it
// throws InfeasibleShot naming the failed condition:
//   "x1 >= x0"           sliding cannot end behind the start (Z >= 0, v0 >= R w0)
//   "x2 >= x1"           the ball must have stopped sliding by the planned point (N >= 7 v2)
//   "v2 >= 0"            the planned speed is a speed
//   "x2 >= x0"           positions increase in the direction of travel
//   "x2 > x0 or v2 > 0"  the ball has to go somewhere
//   "v0 >= v2"           (given v0) a ball cannot speed up without overspin
#pragma once

#include "cueball/core/parameters.hpp"

namespace cueball {

struct ShotTarget {
  double x0 = 0.0;  ///< start, m
  double x2 = 0.0;  ///< planned point, m
  double v2 = 0.0;  ///< planned speed at x2, m/s (0: the ball stops there)
};

enum class PlanVariant {
  given_slide_end,  ///< the paper's problem: x1 is given (eqs 25-28)
  natural_roll,     ///< x1 = x0: the ball rolls from the start (Z = 0)
  given_spin,       ///< w0 is given; x1 follows
  given_speed,      ///< v0 is given; w0 and x1 follow
};

struct ShotPlan {
  PlanVariant variant;
  double v0;  ///< initial speed, m/s (eq. 27)
  double w0;  ///< initial topspin, rad/s (eq. 28)
  double t1;  ///< end of sliding, s (eq. 19)
  double x1;  ///< position at the end of sliding, m (eq. 21)
  double v1;  ///< speed at the end of sliding, m/s (eq. 20)
  double t2;  ///< time at which the ball passes x2 with speed v2, s (eq. 22)
};

/// The paper's inverse problem: x1 (end of sliding) given, eqs 25-28.
ShotPlan plan_shot_with_slide_end(const ShotTarget& target, double x1, const Parameters& p);

/// Natural roll from the start (x1 = x0, R w0 = v0): the member of the family
/// with the lowest initial speed for a ball that never slides backwards.
ShotPlan plan_natural_roll_shot(const ShotTarget& target, const Parameters& p);

/// Given topspin w0 (e.g. a robot that always strikes at one height): solves
/// the quadratic in Z from eqs 17-24 with N = 7 R w0 + 5 Z; v0 = R w0 + Z.
ShotPlan plan_shot_with_spin(const ShotTarget& target, double w0, const Parameters& p);

/// Given speed v0: solves the quadratic in Z from eqs 17-24 with N = 7 v0 - 2 Z.
ShotPlan plan_shot_with_speed(const ShotTarget& target, double v0, const Parameters& p);

const char* to_string(PlanVariant v);

}  // namespace cueball
