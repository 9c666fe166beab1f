// Crafting game states and actions for the rules' and agents' tests: the
// balls of a state set by hand, and the actions those tests play.
#pragma once

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "cueball/games/game.hpp"

namespace cueball::test {

/// Replaces the state's balls with these, at rest ("cue" for id 0, else the id as the name).
inline void place_balls(GameState& s, const std::vector<std::pair<int, Vec2>>& balls) {
  s.table.balls.clear();
  for (const auto& [id, p] : balls) {
    SimulationBall b;
    b.id = id;
    b.name = id == 0 ? "cue" : std::to_string(id);
    b.state.position = p;
    s.table.balls.push_back(b);
  }
}

/// A rotation game (9-ball, 10-ball) in play after the break with exactly
/// these balls: no ball in hand, the lowest ball on.
inline GameState rotation_in_play(GameKind kind, const std::vector<std::pair<int, Vec2>>& balls) {
  GameState s = new_game(default_config(kind));
  s.phase = GamePhase::play;
  s.ball_in_hand.reset();
  place_balls(s, balls);
  int lowest = 99;
  for (const auto& [id, p] : balls)
    if (id != 0 && id < lowest) lowest = id;
  s.on = {lowest};
  return s;
}

/// The direction from `from` to `to`, degrees anticlockwise from +x.
inline double aim_deg(Vec2 from, Vec2 to) {
  return std::atan2(to.y - from.y, to.x - from.x) * 180.0 / std::numbers::pi;
}

/// A centre-ball strike at `speed` m/s towards `aim` degrees.
inline Action strike(double speed, double aim) {
  Action a;
  a.strike.speed = speed;
  a.strike.aim_deg = aim;
  return a;
}

/// `a` with a called ball and pocket.
inline Action called(Action a, int ball, int pocket) {
  a.called_ball = ball;
  a.called_pocket = pocket;
  return a;
}

/// A draw shot (2 m/s, 0.3 R below centre) from `from` towards `to`: on the
/// pool table's bottom-left diagonal the first ball on it drops and the cue
/// ball stays out.
inline Action diagonal_draw(Vec2 from, Vec2 to) {
  Action a = strike(2.0, aim_deg(from, to));
  a.strike.height = -0.3;
  return a;
}

/// A decision.
inline Action decide(Decision d) {
  Action a;
  a.decision = d;
  return a;
}

}  // namespace cueball::test
