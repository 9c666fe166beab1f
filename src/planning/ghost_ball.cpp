// Ghost-ball pots: a table's straight pots from its geometry, and their
// chance under the aim noise; see ghost_ball.hpp.
#include "cueball/planning/ghost_ball.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cueball/planning/pocket_windows.hpp"
#include "cueball/planning/shot_planner.hpp"
#include "cueball/simulation/batch.hpp"

namespace cueball {

namespace {

// Iterations of the point a ball at O is sent to: the direction to the
// point moves the window's middle, which moves the point (a few mm; the
// second pass moves it by microns).
constexpr int kWindowMiddlePasses = 2;

// The point on the line through the middle of the pocket's window for the
// direction from O to it, level with the pocket's centre.
Vec2 window_middle(const PocketWindows& windows, std::size_t pocket, Vec2 O, Vec2 centre) {
  Vec2 P = centre;
  for (int pass = 0; pass < kWindowMiddlePasses; ++pass) {
    const double d = norm(P - O);
    if (d <= 0.0) break;
    const Vec2 u = (P - O) / d;
    P = centre + pocket_window_middle(windows, pocket, u) * perp(u);
  }
  return P;
}

}  // namespace

bool path_clear(const std::vector<SimulationBall>& balls, Vec2 a, Vec2 b, double clearance,
                std::initializer_list<int> except) {
  return std::none_of(balls.begin(), balls.end(), [&](const SimulationBall& x) {
    return std::find(except.begin(), except.end(), x.id) == except.end() &&
           distance_to_segment(x.state.position, a, b) < clearance;
  });
}

std::vector<GhostBallPot> ghost_ball_pots(const Scenario& table, int cue_ball, const std::vector<int>& targets,
                                          GhostBallAim aim) {
  std::vector<GhostBallPot> pots;
  const SimulationBall* cue = find_ball(table.balls, cue_ball);
  if (!cue) return pots;
  const double R = table.settings.parameters.ball.radius;
  const double min_cos_cut = std::cos(kMaxCutDeg * std::numbers::pi / 180.0);
  const Vec2 C = cue->state.position;
  const std::shared_ptr<const PocketWindows> windows = pocket_windows(table);
  for (const int target : targets) {
    const SimulationBall* object = find_ball(table.balls, target);
    if (!object || target == cue_ball) continue;
    const Vec2 O = object->state.position;
    for (std::size_t p = 0; p < table.table.pockets.size(); ++p) {
      const Vec2 centre = table.table.pockets[p].centre;
      const Vec2 P = aim == GhostBallAim::window_middle ? window_middle(*windows, p, O, centre) : centre;
      const double op = norm(P - O);
      if (op <= 0.0) continue;
      const Vec2 u = (P - O) / op;
      const Vec2 G = O - 2.0 * R * u;
      const double cg = norm(G - C);
      if (cg <= 0.0) continue;
      const double cos_cut = dot((G - C) / cg, u);
      if (cos_cut < min_cos_cut) continue;
      if (!path_clear(table.balls, C, G, 2.0 * R, {cue_ball, target}) ||
          !path_clear(table.balls, O, P, 2.0 * R, {cue_ball, target}))
        continue;
      const double score = cos_cut / (cg * op);
      const double window = pocket_window_half_width(*windows, p, u);
      pots.push_back({target, static_cast<int>(p), G, score, window, 2.0 * R * window * score, P});
    }
  }
  std::stable_sort(pots.begin(), pots.end(),
                   [](const GhostBallPot& a, const GhostBallPot& b) { return a.aim_tolerance > b.aim_tolerance; });
  return pots;
}

std::vector<GhostBallPot> ghost_ball_combinations(const Scenario& table, int cue_ball, int ball_on, int target) {
  std::vector<GhostBallPot> pots;
  const SimulationBall* cue = find_ball(table.balls, cue_ball);
  const SimulationBall* on = find_ball(table.balls, ball_on);
  const SimulationBall* object = find_ball(table.balls, target);
  if (!cue || !on || !object || cue_ball == ball_on || cue_ball == target || ball_on == target) return pots;
  const double R = table.settings.parameters.ball.radius;
  const double min_cos_cut = std::cos(kMaxCutDeg * std::numbers::pi / 180.0);
  const Vec2 C = cue->state.position, A = on->state.position, O = object->state.position;
  const std::shared_ptr<const PocketWindows> windows = pocket_windows(table);
  for (std::size_t p = 0; p < table.table.pockets.size(); ++p) {
    const Vec2 P = window_middle(*windows, p, O, table.table.pockets[p].centre);
    const double op = norm(P - O);
    if (op <= 0.0) continue;
    const Vec2 u = (P - O) / op;
    const Vec2 T = O - 2.0 * R * u;  // the ball on's centre where it meets the target
    const double at = norm(T - A);
    if (at <= 0.0) continue;
    const Vec2 v = (T - A) / at;
    const Vec2 G = A - 2.0 * R * v;  // the cue ball's centre where it meets the ball on
    const double cg = norm(G - C);
    if (cg <= 0.0) continue;
    const double cos_on = dot((G - C) / cg, v), cos_target = dot(v, u);
    if (cos_on < min_cos_cut || cos_target < min_cos_cut) continue;
    if (!path_clear(table.balls, C, G, 2.0 * R, {cue_ball, ball_on}) ||
        !path_clear(table.balls, A, T, 2.0 * R, {cue_ball, ball_on, target}) ||
        !path_clear(table.balls, O, P, 2.0 * R, {cue_ball, target}))
      continue;
    const double score = 2.0 * R * cos_on * cos_target / (cg * at * op);
    const double window = pocket_window_half_width(*windows, p, u);
    pots.push_back({target, static_cast<int>(p), G, score, window, 2.0 * R * window * score, P, ball_on});
  }
  std::stable_sort(pots.begin(), pots.end(),
                   [](const GhostBallPot& a, const GhostBallPot& b) { return a.aim_tolerance > b.aim_tolerance; });
  return pots;
}

double ghost_ball_pot_chance(double aim_tolerance, double aim_sigma) {
  if (aim_tolerance <= 0.0) return 0.0;
  if (aim_sigma <= 0.0) return 1.0;
  return std::erf(aim_tolerance / (aim_sigma * std::numbers::sqrt2));
}

double best_ghost_ball_chance(const Scenario& table, int cue_ball, const std::vector<int>& targets, double aim_sigma) {
  const std::vector<GhostBallPot> pots = ghost_ball_pots(table, cue_ball, targets);
  if (pots.empty()) return 0.0;
  return ghost_ball_pot_chance(pots.front().aim_tolerance, aim_sigma);
}

GhostBallStroke ghost_ball_stroke(const Scenario& table, int cue_ball, const GhostBallPot& pot, double speed,
                                  double height) {
  GhostBallStroke out;
  const std::size_t cue = index_of(table.balls, cue_ball);
  if (cue >= table.balls.size()) {
    out.left = table;
    out.scratched = true;
    return out;
  }
  const double R = table.settings.parameters.ball.radius;
  const Vec2 C = table.balls[cue].state.position;
  const double aim_deg = std::atan2(pot.ghost.y - C.y, pot.ghost.x - C.x) * 180.0 / std::numbers::pi;
  std::vector<SimulationBall> balls = table.balls;
  try {
    balls[cue].state = strike_ball(to_strike(ShotAction{speed, aim_deg, 0.0, 0.0, height}, R), C,
                                   table.settings.parameters.ball, table.cue_parameters);
    out.left = table_after(table, simulate_unchecked(table.table, balls, table.settings));
  } catch (const std::exception&) {  // an event limit or a refused strike: no leave to value
    out.left = table;
    out.scratched = true;
    return out;
  }
  out.potted = !find_ball(out.left.balls, pot.target);
  out.scratched = !find_ball(out.left.balls, cue_ball);
  return out;
}

}  // namespace cueball
