// The break: a recommended opening shot for each discipline (issue 25,
// item 3; the measurements behind the choices: docs/break.md, made with
// bench/break_study.cpp).
//
//   GameState s = new_game(config, seed);        // phase break_shot
//   GameStep step = play(s, recommended_break(s), shot_seed);
//
// Pool (9-ball, 8-ball, 10-ball): the side break pros favour (D. Alciatore,
// "How to Rack and Break 9-Ball Like a Pro", Billiards Digest 2018: from
// near a long rail, square on the 1, the wing ball into the corner): the cue
// ball 10 cm off the y = 0 rail just behind the head string, a square hit on
// the apex ball at 11 m/s (a pro's break speed), centre ball, level cue. The
// engine resolves the rack's contacts at once (contact_cluster.hpp), so the
// wing ball goes as players expect, and this break makes a ball on 0.78 of
// breaks on the default rack, 0.69 with the 9 on the foot spot (the pros':
// 0.71), under tournament noise (docs/break.md). Written on the rack as the
// state holds it: the apex is the ball on (the lowest object ball on the
// table), so the same break serves 8-ball and 10-ball racks.
//
// Snooker: a safe break-off (WPBSA Rules, section 3.2: the cue ball in hand
// in the D, any red first): from the D on the yellow's side, a contact from
// thin to half-ball (a scan with the engine keeps the safest) on the end red
// of the pack's back row on that side, with running side so the cue ball
// comes off the top and side cushions back towards baulk.
//
// Three-cushion: the standard opening (UMB: the red must be struck first):
// the cue ball from its opening spot onto the red about half-ball on the
// side of the cue ball's own half, so that it goes to the foot cushion, a
// long cushion, the other long cushion and back to the opponent's ball on
// the head spot.
#pragma once

#include "cueball/games/game.hpp"

namespace cueball {

// ---- pool: the measured side break (docs/break.md)

/// Distance of the cue ball's centre behind the head string, m.
inline constexpr double kBreakBehindString = 0.01;
/// The cue ball's centre's distance from the y = 0 cushion's nose line,
/// less a radius, m: the side break (docs/break.md, "The recommended break").
inline constexpr double kBreakFromRail = 0.10;
/// Impact offset on the apex ball, a fraction of the ball's diameter, 0 a
/// square hit; positive passes the apex on the cue ball's own side of the
/// long string.
inline constexpr double kBreakCut = 0.0;
/// Cue speed, m/s (a pro's break: the cue ball at 25-30 mph, about
/// 11-13 m/s; Alciatore, "typical speeds").
inline constexpr double kBreakSpeed = 11.0;
/// Tip offset above centre, ball radii (follow of 0.1 cut scratches but
/// made no more balls: docs/break.md).
inline constexpr double kBreakHeight = 0.0;
/// Cue elevation, degrees (level: the engine has no airborne phase).
inline constexpr double kBreakElevationDeg = 0.0;

// ---- snooker break-off

/// Cue speed of the break-off, m/s.
inline constexpr double kBreakOffSpeed = 4.0;
/// Share of the end red hit (fraction of the diameter overlapping at
/// contact) when the scan finds no safe one: about half-ball, the middle of
/// the safe contacts on the default pack (docs/break.md).
inline constexpr double kBreakOffFullness = 0.5;
/// Running side, ball radii.
inline constexpr double kBreakOffSide = 0.3;

// ---- three-cushion opening

/// Cue speed of the opening shot, m/s.
inline constexpr double kOpeningSpeed = 3.5;
/// Fullness of the hit on the red: half-ball.
inline constexpr double kOpeningFullness = 0.5;

/// The recommended opening shot for `state`, which must be in
/// GamePhase::break_shot (InvalidArgument "phase" otherwise, naming the
/// phase; "kind" when the state has no ball the shot needs: no object ball
/// for a pool break, no red for a snooker break-off, no red or opponent's
/// ball for a three-cushion opening). The action places the cue ball
/// (Action::place) when it is in hand, at the spot above or, when that spot
/// is taken, the nearest free spot of the region towards the long string;
/// the strike's aim is absolute (aim_deg), so noise and aim_at play no part.
Action recommended_break(const GameState& state);

/// A 9-ball state at the break with its rack moved along the long string so
/// that the 9, not the 1, sits on the foot spot: every object ball shifted
/// by the same vector (gaps kept). WPA 2.2 racks the 1 on the foot spot
/// (what new_game() does); many professional events rack the 9 there (the
/// 2016 WPA World 9-Ball Championship did, whose breakers made a ball on 71 %
/// of breaks), which puts the rack two rows (2 sqrt(3) R) nearer the head
/// string; at a pro's break speed the break then makes a ball more often
/// (docs/break.md). Throws
/// InvalidArgument "kind" for another discipline or without the 9 on the
/// table, "phase" outside GamePhase::break_shot, "rack" when a moved ball
/// would not fit on the table.
GameState nine_on_foot_spot(GameState state);

}  // namespace cueball
