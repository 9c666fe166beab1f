// The ghost-ball agent (agent.hpp): ghost-ball aiming at the easiest clear
// pot of a ball on, no simulation; the planner benchmark's baseline, moved
// here from bench/planner_benchmark.cpp.
//
//   break       break_action();
//   decision    decision_by_policy(), the table good when ghost_ball_shot()
//               finds a clear pot on it (with the cue ball in hand: when
//               ghost_ball_in_hand_spot() finds a spot);
//   in hand     the cue ball on ghost_ball_in_hand_spot() in the legal
//               region; with no spot, a seeded random free spot there
//               (RandomStream(splitmix64(seed))), or where it lies when it
//               is on the table and in the region;
//   the shot    ghost_ball_shot() over shot_targets(): centre ball,
//               kGhostBallSpeed, the lowest clear elevation; the call (when
//               required) its ball and pocket, the nomination its ball;
//   no pot      safe_hit() of a target (a plain hit of a ball on), announced
//               as a push-out when one may be (nothing to lose); the call,
//               that ball and its nearest pocket.
// It never pushes out when it has a pot. Three-cushion: carom_search_action().
#include <algorithm>
#include <cmath>
#include <numbers>

#include "cueball/agents/agent.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/core/random.hpp"
#include "cueball/planning/ghost_ball.hpp"

namespace cueball {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr int kPlacementAttempts = 10000;

double angle_deg(Vec2 v) { return std::atan2(v.y, v.x) / kDeg; }

std::vector<Vec2> positions_but(const Scenario& table, int cue_ball) {
  std::vector<Vec2> out;
  for (const SimulationBall& b : table.balls)
    if (b.id != cue_ball) out.push_back(b.state.position);
  return out;
}

// The ghost-ball agent's shot from a table with the cue ball where it will be struck.
Action ghost_shot(const LegalActions& legal, const Scenario& table, const std::vector<int>& targets) {
  Action a;
  int ball = -1, pocket = -1;
  if (const std::optional<GhostBallShot> g = ghost_ball_shot(table, legal.cue_ball, targets)) {
    a.strike = g->strike;
    ball = g->target;
    pocket = g->pocket;
  } else {
    const std::optional<ShotAction> hit = safe_hit(table, legal.cue_ball, targets, ball);
    if (!hit) throw InvalidArgument("state", "no ball on to play at");
    a.strike = *hit;
    pocket = nearest_pocket(table, ball);
    a.push_out = legal.push_out;
  }
  if (legal.call_required) {
    a.called_ball = std::find(legal.callable.begin(), legal.callable.end(), ball) != legal.callable.end() ||
                            legal.callable.empty()
                        ? ball
                        : legal.callable.front();
    a.called_pocket = pocket;
  }
  if (legal.nominate_required && !legal.nominable.empty())
    a.nominate = std::find(legal.nominable.begin(), legal.nominable.end(), ball) != legal.nominable.end()
                     ? ball
                     : legal.nominable.front();
  return a;
}

// The first of `pots` whose cue clears at one of lowest_clear_elevation_deg()'s elevations.
std::optional<GhostBallShot> first_clear(const Scenario& table, int cue_ball, const std::vector<GhostBallPot>& pots,
                                         double speed) {
  if (pots.empty()) return std::nullopt;
  const Vec2 C = find_ball(table.balls, cue_ball)->state.position;
  for (const GhostBallPot& pot : pots) {
    ShotAction a;
    a.speed = speed;
    a.aim_deg = angle_deg(pot.ghost - C);
    const std::optional<double> elevation = lowest_clear_elevation_deg(table, cue_ball, a);
    if (!elevation) continue;
    a.elevation_deg = *elevation;
    return GhostBallShot{pot.target, pot.pocket, a, pot.score, pot.aim_tolerance};
  }
  return std::nullopt;
}

}  // namespace

std::optional<GhostBallShot> ghost_ball_shot(const Scenario& table, int cue_ball, const std::vector<int>& targets,
                                             double speed) {
  // By score (the geometry alone), ties in the targets' order, then the
  // pockets': the ghost-ball agent's choice before the pocket windows, its
  // aim the textbook one at the pocket's centre (the benchmarks' baseline
  // kept as it was: sent to the middle of the windows, it potted 0.483 of
  // the planner benchmark's single pots on seeds 1..100 against 0.347).
  std::vector<GhostBallPot> pots = ghost_ball_pots(table, cue_ball, targets, GhostBallAim::pocket_centre);
  const auto order = [&](int id) { return std::find(targets.begin(), targets.end(), id) - targets.begin(); };
  std::sort(pots.begin(), pots.end(), [&](const GhostBallPot& a, const GhostBallPot& b) {
    if (a.score != b.score) return a.score > b.score;
    if (a.target != b.target) return order(a.target) < order(b.target);
    return a.pocket < b.pocket;
  });
  return first_clear(table, cue_ball, pots, speed);
}

std::optional<GhostBallShot> likeliest_ghost_ball_shot(const Scenario& table, int cue_ball,
                                                       const std::vector<int>& targets, double speed) {
  return first_clear(table, cue_ball, ghost_ball_pots(table, cue_ball, targets), speed);
}

std::optional<Vec2> ghost_ball_in_hand_spot(const Scenario& table, int cue_ball, const std::vector<int>& targets,
                                            const PlacementRegion& region, double back) {
  const double R = table.settings.parameters.ball.radius;
  const std::vector<Vec2> others = positions_but(table, cue_ball);
  std::optional<Vec2> best;
  double best_score = 0.0;
  for (const int target : targets) {
    const SimulationBall* object = find_ball(table.balls, target);
    if (!object || target == cue_ball) continue;
    const Vec2 O = object->state.position;
    for (const Pocket& q : table.table.pockets) {
      const double op = norm(q.centre - O);
      if (op <= 0.0) continue;
      const Vec2 u = (q.centre - O) / op;
      const Vec2 C = O - (2.0 * R + back) * u;
      if (!in_region(table.table, region, C) || !is_free_spot(table.table, others, C, R)) continue;
      if (!path_clear(table.balls, C, O, 2.0 * R, {cue_ball, target}) ||
          !path_clear(table.balls, O, q.centre, 2.0 * R, {cue_ball, target}))
        continue;
      const double score = 1.0 / op;
      if (!best || score > best_score) {
        best_score = score;
        best = C;
      }
    }
  }
  return best;
}

Action ghost_ball_action(const GameState& state, std::uint64_t seed) {
  if (state.config.kind == GameKind::three_cushion) {
    AgentOptions carom;
    carom.kind = AgentKind::carom_search;
    return carom_search_action(carom, state, seed);
  }
  return ghost_ball_action(state, legal_actions(state), seed);
}

Action ghost_ball_action(const GameState& state, const LegalActions& legal, std::uint64_t seed) {
  if (!legal.shoot) {
    if (legal.decisions.empty()) throw InvalidArgument("state", "no action is open (the game is over)");
    // The table as the decider would shoot it.
    GameState as_is = state;
    as_is.phase = GamePhase::play;
    as_is.decisions.clear();
    const LegalActions then = legal_actions(as_is);
    const std::vector<int> targets = shot_targets(as_is, then);
    const bool good = then.ball_in_hand
                          ? ghost_ball_in_hand_spot(as_is.table, then.cue_ball, targets, *then.ball_in_hand).has_value()
                          : ghost_ball_shot(as_is.table, then.cue_ball, targets).has_value();
    Action a;
    a.decision = decision_by_policy(legal.decisions, good);
    return a;
  }
  if (state.phase == GamePhase::break_shot && !legal.call_required && !legal.nominate_required)
    return break_action(state);
  const std::vector<int> targets = shot_targets(state, legal);
  Scenario table = state.table;
  std::optional<Vec2> place;
  if (legal.ball_in_hand) {
    place = ghost_ball_in_hand_spot(table, legal.cue_ball, targets, *legal.ball_in_hand);
    const SimulationBall* cue = find_ball(table.balls, legal.cue_ball);
    if (!place && !(cue && in_region(table.table, *legal.ball_in_hand, cue->state.position))) {
      RandomStream rng(splitmix64(seed));
      place = random_free_spot(table.table, positions_but(table, legal.cue_ball), table.table.ball.radius, rng,
                               kPlacementAttempts, *legal.ball_in_hand);
      if (!place && !cue) throw InvalidArgument("state", "no free spot for the cue ball in its region");
    }
    if (place) table = with_cue_ball_at(table, legal.cue_ball, *place);
  }
  Action a = ghost_shot(legal, table, targets);
  a.place = place;
  return a;
}

}  // namespace cueball
