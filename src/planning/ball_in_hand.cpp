// Ball in hand: the cue ball's spot chosen for the pot and the leave; see
// ball_in_hand.hpp.
#include "cueball/planning/ball_in_hand.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "cueball/core/errors.hpp"
#include "planning/shot_search.hpp"

namespace cueball {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// A spot behind a ghost ball, and what step 2 makes of it.
struct Spot {
  Vec2 cue_ball;
  int pocket = 0;
  double paths = 0.0;   // cue ball to ghost ball plus object ball to pocket, m
  double window = 0.0;  // the best window probability of a direct shot into the pocket
  Scenario table;
};

Vec2 rotated(Vec2 v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

}  // namespace

BallInHandResult plan_ball_in_hand(const Scenario& table_state, const BallInHandRequest& q) {
  const auto start = std::chrono::steady_clock::now();
  if (q.region) {
    const InHandRegion& r = *q.region;
    const auto bounds = [](const char* lo_name, double lo, const char* hi_name, double hi) {
      if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
        throw InvalidArgument("region", std::string("region ") + lo_name + " = " + format_number(lo) + ", " + hi_name +
                                            " = " + format_number(hi) + "; allowed: finite, " + lo_name + " < " +
                                            hi_name + " (m)");
    };
    bounds("x_min", r.x_min, "x_max", r.x_max);
    bounds("y_min", r.y_min, "y_max", r.y_max);
    // A region wholly off the playing surface is bad input, not a shot without an answer.
    const Table& t = table_state.table;
    if (r.x_max <= 0.0 || r.x_min >= t.length || r.y_max <= 0.0 || r.y_min >= t.width)
      throw InvalidArgument("region", "region [" + format_number(r.x_min) + ", " + format_number(r.x_max) + "] x [" +
                                          format_number(r.y_min) + ", " + format_number(r.y_max) +
                                          "] m lies wholly off the playing surface; allowed: a region overlapping [0, " +
                                          format_number(t.length) + "] x [0, " + format_number(t.width) + "] m");
  }
  const Scenario& s = table_state;
  const int cue_id = q.position.shot.cue_ball ? *q.position.shot.cue_ball : s.cue ? s.cue->ball : 0;
  const int target_id = q.position.shot.target;
  // The table without the cue ball; the cue ball's own parameters kept when it is there.
  Scenario without = s;
  without.cue.reset();
  SimulationBall cue;
  cue.id = cue_id;
  cue.name = "cue";
  without.balls.clear();
  for (const SimulationBall& b : s.balls) {
    if (b.id == cue_id) cue = b;
    else without.balls.push_back(b);
  }
  const auto target = std::find_if(without.balls.begin(), without.balls.end(),
                                   [&](const SimulationBall& b) { return b.id == target_id; });
  if (target == without.balls.end())
    throw InvalidArgument("target", "target = " + std::to_string(target_id) + " is not the id of an object ball on the table");
  const double R = s.settings.parameters.ball.radius;
  const Vec2 O = target->state.position;
  const auto clear = [&](Vec2 a, Vec2 b) {
    return std::none_of(without.balls.begin(), without.balls.end(), [&](const SimulationBall& o) {
      return o.id != target_id && distance_to_path(o.state.position, a, b) < 2.0 * R;
    });
  };
  const auto placeable = [&](Vec2 p) {
    if (q.region && (p.x < q.region->x_min || p.x > q.region->x_max || p.y < q.region->y_min || p.y > q.region->y_max))
      return false;
    if (!ball_on_table(s.table, p, R)) return false;
    return std::all_of(without.balls.begin(), without.balls.end(), [&](const SimulationBall& o) {
      return norm(o.state.position - p) >= 2.0 * R + kInHandGap;
    });
  };

  // 1. Spots behind the ghost ball of each clear pocket.
  std::vector<Spot> spots;
  const auto add_spot = [&](Vec2 C, int pocket, double paths) {
    Spot spot;
    spot.cue_ball = C;
    spot.pocket = pocket;
    spot.paths = paths;
    spot.table = without;
    SimulationBall placed = cue;
    placed.state = BallState{};
    placed.state.position = C;
    spot.table.balls.insert(spot.table.balls.begin(), placed);
    spots.push_back(std::move(spot));
  };
  for (std::size_t k = 0; k < s.table.pockets.size(); ++k) {
    if (q.position.shot.pocket && static_cast<std::size_t>(*q.position.shot.pocket) != k) continue;
    const Vec2 P = s.table.pockets[k].centre;
    const double op = norm(P - O);
    if (op <= 2.0 * R || !clear(O, P)) continue;
    const Vec2 u = (P - O) / op;
    const Vec2 G = O - 2.0 * R * u;
    for (const double cut : kInHandCutsDeg) {
      const Vec2 w = rotated(u, cut * kDegree);  // the cue ball's direction to G
      std::vector<double> distances(kInHandDistances.begin(), kInHandDistances.end());
      // A region: also where the line behind G first lies inside it (a
      // kInHandGap in), and the middle of its stretch inside, up to 3 m.
      if (q.region) {
        double lo = 0.0, hi = kInHandFarthest;
        const auto slab = [&](double g, double dir, double min, double max) {
          if (dir == 0.0) {
            if (g < min || g > max) hi = -1.0;
            return;
          }
          double t0 = (g - max) / dir, t1 = (g - min) / dir;  // C = G - t w inside [min, max]
          if (t0 > t1) std::swap(t0, t1);
          lo = std::max(lo, t0), hi = std::min(hi, t1);
        };
        slab(G.x, w.x, q.region->x_min, q.region->x_max);
        slab(G.y, w.y, q.region->y_min, q.region->y_max);
        if (lo < hi) distances.insert(distances.end(), {lo + kInHandGap, 0.5 * (lo + hi)});
      }
      for (const double d : distances) {
        const Vec2 C = G - d * w;
        if (placeable(C) && clear(C, G)) add_spot(C, static_cast<int>(k), d + op);
      }
    }
  }
  // No straight pot from behind a ghost ball: the centres of a grid over
  // the bed (or the region), each free place a spot for any shot asked for.
  const bool grid = spots.empty();
  if (grid) {
    const double x0 = q.region ? q.region->x_min : 0.0, x1 = q.region ? q.region->x_max : s.table.length;
    const double y0 = q.region ? q.region->y_min : 0.0, y1 = q.region ? q.region->y_max : s.table.width;
    for (int i = 0; i < kInHandGrid[0]; ++i)
      for (int j = 0; j < kInHandGrid[1]; ++j) {
        const Vec2 C{x0 + (x1 - x0) * (i + 0.5) / kInHandGrid[0], y0 + (y1 - y0) * (j + 0.5) / kInHandGrid[1]};
        if (placeable(C)) add_spot(C, -1, norm(C - O));
      }
  }
  BallInHandResult result;
  result.spots = static_cast<int>(spots.size());
  if (spots.empty())
    throw NoFeasibleShot(std::string("no spot for the cue ball: no free place") + (q.region ? " inside the region" : "") +
                         " on a grid of " + std::to_string(kInHandGrid[0] * kInHandGrid[1]) + " places");

  // 2. Each spot's direct shot into its pocket (a grid spot's: every shot
  // asked for), noise-free.
  int simulations = 0;
  ShotSearch windows_only;
  windows_only.noisy = false;
  for (Spot& spot : spots) {
    PlanRequest direct = q.position.shot;
    direct.cue_ball = cue_id;
    if (!grid) {
      direct.pocket = spot.pocket;
      direct.kinds = {ShotKind::direct};
    }
    direct.simulations = kMinPlanSimulations;
    try {
      const SearchedShots w = search_shots(spot.table, direct, windows_only);
      simulations += w.plan.simulations;
      spot.window = w.plan.shot.window_probability;
    } catch (const NoFeasibleShot&) {
      simulations += kMinPlanSimulations;  // at its budget (the error does not say what it spent)
    }
  }
  std::stable_sort(spots.begin(), spots.end(), [](const Spot& a, const Spot& b) {
    const double wa = std::floor(a.window / 0.02), wb = std::floor(b.window / 0.02);
    if (wa != wb) return wa > wb;
    return a.paths < b.paths;
  });
  std::vector<const Spot*> kept;
  for (const Spot& spot : spots) {
    if (kept.size() == kInHandSpots || spot.window <= 0.0) break;
    const auto same_pocket = std::count_if(kept.begin(), kept.end(), [&](const Spot* k) { return k->pocket == spot.pocket; });
    if (grid || same_pocket < 2) kept.push_back(&spot);
  }
  if (kept.empty())
    throw NoFeasibleShot("no spot for the cue ball pots ball " + std::to_string(target_id) + " (" +
                         std::to_string(spots.size()) + (grid ? " places on a grid" : " spots behind ghost balls") +
                         " tried)");

  // 3. Each kept spot played for position; the best leave chosen.
  PositionRequest p = q.position;
  p.shot.cue_ball = cue_id;
  std::optional<NoFeasibleShot> infeasible;
  bool found = false;
  for (const Spot* spot : kept) {
    try {
      PositionPlanResult r = plan_shot_for_position(spot->table, p);
      simulations += r.plan.simulations;
      ++result.spots_played;
      if (!found || r.leave.score > result.plan.leave.score) {
        result.plan = std::move(r);
        result.cue_ball = spot->cue_ball;
        result.table = spot->table;
        found = true;
      }
    } catch (const NoFeasibleShot& e) {
      ++result.spots_played;
      if (!infeasible) infeasible.emplace(e);
    }
  }
  if (!found) throw *infeasible;
  result.plan.plan.simulations = simulations;
  result.plan.plan.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace cueball
