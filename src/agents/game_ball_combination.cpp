// The game ball by a combination through the ball on (agent.hpp): in
// 9-ball and 10-ball the cue ball must meet the lowest ball first (WPA
// Rules of Play 6.2, 2 and 9 opening paragraphs), but any ball may then be
// pocketed, and the player who legally pockets the game ball wins the rack
// at once (WPA section 2's opening paragraph for the 9; section 9's for the
// called 10, a combination included). So the 1 sent into the 9 near a
// pocket is a shot that wins the rack in one stroke, which a player who
// runs out ball by ball passes by.
//
// The plan is plan_shot() of the game ball with PlanRequest::ball_on the
// ball on and the combination kind alone, from where the cue ball lies, or
// with the cue ball in hand from the spots straight behind the ball on
// (combination_in_hand_spots()), the kCombinationInHandSpots easiest each
// planned in full, the likeliest kept. Its success probability is measured
// on fresh draws (shot_planner.hpp), so it can be set against the run-out's
// chance (run_out_chance()) without a selection bias.
#include <algorithm>
#include <cmath>

#include "core/angles.hpp"
#include "cueball/agents/agent.hpp"
#include "cueball/planning/ghost_ball.hpp"

namespace cueball {

namespace {

constexpr int kNine = 9, kTen = 10;

bool contains(const std::vector<int>& v, int id) { return std::find(v.begin(), v.end(), id) != v.end(); }

// A spot for the cue ball in hand and how easy its combination looks.
struct CombinationSpot {
  Vec2 cue_ball;
  double ease = 0.0;  // cos(the ball on's cut on the game ball) / (its path + the game ball's), 1/m
};

}  // namespace

std::optional<int> game_ball(const GameState& state) {
  switch (state.config.kind) {
    case GameKind::nine_ball: return kNine;
    case GameKind::ten_ball: return kTen;
    default: return std::nullopt;
  }
}

double run_out_chance(double shot, double next, int shots_after) {
  return shot * next * std::pow(kRunOutShotChance, std::max(0, shots_after));
}

std::vector<Vec2> combination_in_hand_spots(const Scenario& table, int cue_ball, int ball_on, int target,
                                            const PlacementRegion& region, double back) {
  const double R = table.settings.parameters.ball.radius;
  const SimulationBall* on = find_ball(table.balls, ball_on);
  const SimulationBall* object = find_ball(table.balls, target);
  if (!on || !object || ball_on == target || ball_on == cue_ball || target == cue_ball) return {};
  const Vec2 A = on->state.position, O = object->state.position;
  std::vector<Vec2> others;
  for (const SimulationBall& b : table.balls)
    if (b.id != cue_ball) others.push_back(b.state.position);
  std::vector<CombinationSpot> spots;
  for (const Pocket& p : table.table.pockets) {
    const double op = norm(p.centre - O);
    if (op <= 2.0 * R) continue;
    const Vec2 u = (p.centre - O) / op;
    const Vec2 GT = O - 2.0 * R * u;  // where the ball on must be when it meets the game ball
    const double ag = norm(GT - A);
    if (ag <= 1e-9) continue;
    const Vec2 v = (GT - A) / ag;
    const double cut = std::acos(std::clamp(dot(v, u), -1.0, 1.0)) / kDegree;
    if (cut > kMaxInHandCombinationCutDeg) continue;
    const Vec2 C = A - (2.0 * R + back) * v;  // straight behind the ball on: no cut on it
    if (!in_region(table.table, region, C) || !is_free_spot(table.table, others, C, R)) continue;
    if (!path_clear(table.balls, C, A, 2.0 * R, {cue_ball, ball_on}) ||
        !path_clear(table.balls, A, GT, 2.0 * R, {cue_ball, ball_on, target}) ||
        !path_clear(table.balls, O, p.centre, 2.0 * R, {cue_ball, target}))
      continue;
    spots.push_back({C, std::cos(cut * kDegree) / (ag + op)});
  }
  std::stable_sort(spots.begin(), spots.end(),
                   [](const CombinationSpot& a, const CombinationSpot& b) { return a.ease > b.ease; });
  std::vector<Vec2> out;
  for (const CombinationSpot& s : spots) out.push_back(s.cue_ball);
  return out;
}

std::optional<GameBallCombination> plan_game_ball_combination(const GameState& state, const LegalActions& legal,
                                                              PlanRequest q, long long& simulations) {
  const std::optional<int> game = game_ball(state);
  if (!game || legal.on.size() != 1 || !legal.shoot) return std::nullopt;
  const int ball_on = legal.on.front();
  const Scenario& table = state.table;
  if (ball_on == *game || !find_ball(table.balls, *game) || !find_ball(table.balls, ball_on)) return std::nullopt;
  if (legal.call_required && !legal.callable.empty() && !contains(legal.callable, *game)) return std::nullopt;
  q.cue_ball = legal.cue_ball;
  q.target = *game;
  q.targets.clear();
  q.ball_on = ball_on;
  q.kinds = {ShotKind::combination};
  q.call_shot = legal.call_required;  // 10-ball: the 10 called in its pocket (WPA 9.5)
  // Where the cue ball is struck from: where it lies, or the spots in hand.
  std::vector<std::optional<Vec2>> places;
  if (legal.ball_in_hand) {
    const std::vector<Vec2> spots =
        combination_in_hand_spots(table, legal.cue_ball, ball_on, *game, *legal.ball_in_hand);
    for (std::size_t k = 0; k < spots.size() && k < kCombinationInHandSpots; ++k) places.emplace_back(spots[k]);
  } else if (find_ball(table.balls, legal.cue_ball)) {
    places.emplace_back(std::nullopt);
  }
  std::optional<GameBallCombination> best;
  for (const std::optional<Vec2>& place : places) {
    const Scenario from = place ? with_cue_ball_at(table, legal.cue_ball, *place) : table;
    try {
      ShotPlanResult r = plan_shot(from, q);
      simulations += r.simulations;
      if (!best || r.shot.success_probability > best->shot.success_probability)
        best = GameBallCombination{std::move(r.shot), place};
    } catch (const NoFeasibleShot& e) {
      simulations += e.simulations() >= 0 ? e.simulations() : q.simulations;
    }
  }
  return best;
}

}  // namespace cueball
