// Line of sight from the cue ball to an object ball: which straight strokes
// reach it without first meeting another ball. What snooker's "snookered"
// asks (WPBSA Rules, section 2, Definitions: the cue ball is snookered when
// a direct stroke in a straight line to every ball on is wholly or partly
// obstructed by a ball not on; it is not snookered when one ball on can be
// struck at both extreme edges free of obstruction), and its "full-ball
// view" of the foul-and-a-miss rule (WPBSA 3.14: a clear path to the whole
// ball on).
//
// Geometry in the bed's plane, balls as discs of one radius R. A straight
// stroke of the cue ball from C in direction w reaches the target O when the
// line's distance to O is at most 2R; it meets the target first when no
// other ball's centre comes within 2R of the cue ball's centre on the way,
// i.e. of the segment from C to the cue ball's centre at contact (the ghost
// ball). The two "extreme edge" strokes are the lines from C tangent to the
// circle of radius 2R about O (a grazing contact on either side). Cushions
// never obstruct (the rule books count balls only).
#pragma once

#include <vector>

#include "cueball/core/vec.hpp"

namespace cueball {

/// What the cue ball at `cue` sees of the ball at `target`.
struct BallView {
  bool left_edge = false;   ///< the grazing stroke passing the target on its left (seen from the cue ball) is clear
  bool right_edge = false;  ///< the grazing stroke on its right is clear
  bool full = false;        ///< every stroke that reaches the target is clear (a full-ball view)
  bool both_edges() const { return left_edge && right_edge; }
  bool any() const { return left_edge || right_edge; }
};

/// The view from the cue ball at `cue` of the ball at `target`, past
/// `obstacles` (the centres of the balls that may obstruct: the target and
/// the cue ball themselves must not be among them), balls of radius
/// `radius`. An obstacle obstructs a stroke when its centre comes strictly
/// closer than 2R - kSightTolerance to the cue ball's path before (or at)
/// the contact. A target touching or overlapping the cue ball (centres at
/// most 2R apart) is seen fully.
BallView view_of_ball(Vec2 cue, Vec2 target, const std::vector<Vec2>& obstacles, double radius);

/// Slack on "obstructs", m: a ball that only just touches the path (to
/// rounding) does not obstruct it.
inline constexpr double kSightTolerance = 1e-9;

}  // namespace cueball
