// Ball in hand: the cue ball's spot chosen for the pot and the leave; see
// ball_in_hand.hpp.
#include "cueball/planning/ball_in_hand.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "cueball/core/errors.hpp"
#include "cueball/planning/ghost_ball.hpp"
#include "core/angles.hpp"
#include "planning/shot_search.hpp"

namespace cueball {

namespace {

// A spot behind a ghost ball, and what step 2 makes of it.
struct Spot {
  Vec2 cue_ball;
  int target = 0;       // id of the ball it pots (a grid spot: the first target)
  int pocket = 0;
  double paths = 0.0;   // cue ball to ghost ball plus object ball to pocket, m
  double window = 0.0;  // the best window probability of a direct shot into the pocket
  Scenario table;
};

Vec2 rotated(Vec2 v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

// InvalidArgument("region") unless lo < hi, both finite.
void check_bounds(const char* lo_name, double lo, const char* hi_name, double hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
    throw InvalidArgument("region", std::string("region ") + lo_name + " = " + format_number(lo) + ", " + hi_name +
                                        " = " + format_number(hi) + "; allowed: finite, " + lo_name + " < " + hi_name +
                                        " (m)");
}

// InvalidArgument("region") for a region wholly off the playing surface: bad
// input, not a shot without an answer.
void check_on_table(const PlacementRegion& r, const Table& t) {
  if (r.x_max <= 0.0 || r.x_min >= t.length || r.y_max <= 0.0 || r.y_min >= t.width)
    throw InvalidArgument("region", "region [" + format_number(r.x_min) + ", " + format_number(r.x_max) + "] x [" +
                                        format_number(r.y_min) + ", " + format_number(r.y_max) +
                                        "] m lies wholly off the playing surface; allowed: a region overlapping [0, " +
                                        format_number(t.length) + "] x [0, " + format_number(t.width) + "] m");
}

// A target of the request and where it is.
struct Target {
  int id = 0;
  Vec2 O;
};

// The table without the cue ball, the targets on it, and where the cue ball may go.
struct Hand {
  const Scenario& s;
  const BallInHandRequest& q;
  int cue_id = 0;
  std::vector<Target> targets;  // PlanRequest::targets (or its target)
  Scenario without;    // the table without the cue ball, its "cue" cleared
  SimulationBall cue;  // the cue ball's own parameters when it is there
  double R = 0.0;

  // No object ball but `target`'s centre within 2R of the path a -> b.
  bool clear(Vec2 a, Vec2 b, int target) const { return path_clear(without.balls, a, b, 2.0 * R, {target}); }
  // A place for the cue ball: inside the region, on the bed, kInHandGap clear of every ball.
  bool placeable(Vec2 p) const {
    if (q.region && !in_region(s.table, *q.region, p)) return false;
    if (!ball_on_table(s.table, p, R)) return false;
    return std::all_of(without.balls.begin(), without.balls.end(), [&](const SimulationBall& o) {
      return norm(o.state.position - p) >= 2.0 * R + kInHandGap;
    });
  }
  // The spot with the cue ball placed at C.
  Spot spot_at(Vec2 C, int target, int pocket, double paths) const {
    Spot spot;
    spot.cue_ball = C;
    spot.target = target;
    spot.pocket = pocket;
    spot.paths = paths;
    spot.table = without;
    SimulationBall placed = cue;
    placed.state = BallState{};
    placed.state.position = C;
    spot.table.balls.insert(spot.table.balls.begin(), placed);
    return spot;
  }
};

Hand hand_of(const Scenario& s, const BallInHandRequest& q) {
  Hand h{s, q, cue_ball_id(s, q.position.shot), {}, s, {}, s.settings.parameters.ball.radius};
  h.without.cue.reset();
  h.cue.id = h.cue_id;
  h.cue.name = "cue";
  h.without.balls.clear();
  for (const SimulationBall& b : s.balls) {
    if (b.id == h.cue_id) h.cue = b;
    else h.without.balls.push_back(b);
  }
  const std::vector<int> ids = target_ids(q.position.shot);
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const std::size_t i = index_of(h.without.balls, ids[k]);
    if (i == h.without.balls.size())
      throw InvalidArgument(q.position.shot.targets.empty() ? "target" : "targets",
                            (q.position.shot.targets.empty() ? "target" : "targets[" + std::to_string(k) + "]") +
                                " = " + std::to_string(ids[k]) + " is not the id of an object ball on the table");
    h.targets.push_back({ids[k], h.without.balls[i].state.position});
  }
  return h;
}

// The distances behind G along -w that a region adds: where the line first
// lies inside it (a kInHandGap in), and the middle of its stretch inside,
// up to kInHandFarthest.
void add_region_distances(const PlacementRegion& region, Vec2 G, Vec2 w, std::vector<double>& distances) {
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
  slab(G.x, w.x, region.x_min, region.x_max);
  slab(G.y, w.y, region.y_min, region.y_max);
  if (lo < hi) distances.insert(distances.end(), {lo + kInHandGap, 0.5 * (lo + hi)});
}

// The spots behind the ghost ball of `target` for pocket k, when its path
// to the pocket is clear: at each distance behind G along each cut.
void add_ghost_ball_spots(const Hand& h, const Target& target, std::size_t k, std::vector<Spot>& spots) {
  const Vec2 O = target.O, P = h.s.table.pockets[k].centre;
  const double op = norm(P - O);
  if (op <= 2.0 * h.R || !h.clear(O, P, target.id)) return;
  const Vec2 u = (P - O) / op;
  const Vec2 G = O - 2.0 * h.R * u;
  for (const double cut : kInHandCutsDeg) {
    const Vec2 w = rotated(u, cut * kDegree);  // the cue ball's direction to G
    std::vector<double> distances(kInHandDistances.begin(), kInHandDistances.end());
    if (h.q.region) add_region_distances(bounding_rectangle(h.s.table, *h.q.region), G, w, distances);
    for (const double d : distances) {
      const Vec2 C = G - d * w;
      if (h.placeable(C) && h.clear(C, G, target.id)) spots.push_back(h.spot_at(C, target.id, static_cast<int>(k), d + op));
    }
  }
}

// Step 1: the spots behind the ghost ball of each pocket a target has a
// clear path to (and the request allows).
std::vector<Spot> ghost_ball_spots(const Hand& h) {
  std::vector<Spot> spots;
  const Scenario& s = h.s;
  for (const Target& target : h.targets)
    for (std::size_t k = 0; k < s.table.pockets.size(); ++k)
      if (!h.q.position.shot.pocket || static_cast<std::size_t>(*h.q.position.shot.pocket) == k)
        add_ghost_ball_spots(h, target, k, spots);
  return spots;
}


// No straight pot from behind a ghost ball: the centres of a grid over the
// bed (or the region), each free place a spot for any shot asked for.
std::vector<Spot> grid_spots(const Hand& h) {
  std::vector<Spot> spots;
  const PlacementRegion box = bounding_rectangle(h.s.table, h.q.region ? *h.q.region : PlacementRegion{});
  const double x0 = box.x_min, x1 = box.x_max, y0 = box.y_min, y1 = box.y_max;
  for (int i = 0; i < kInHandGrid[0]; ++i)
    for (int j = 0; j < kInHandGrid[1]; ++j) {
      const Vec2 C{x0 + (x1 - x0) * (i + 0.5) / kInHandGrid[0], y0 + (y1 - y0) * (j + 0.5) / kInHandGrid[1]};
      double paths = norm(C - h.targets.front().O);  // to the nearest target
      for (const Target& target : h.targets) paths = std::min(paths, norm(C - target.O));
      if (h.placeable(C)) spots.push_back(h.spot_at(C, h.targets.front().id, -1, paths));
    }
  return spots;
}

// A spot's chance by LeaveValuation::ghost_ball: the best ghost-ball pot of
// its target into its pocket (a grid spot's: of any target into any pocket
// the request allows).
double ghost_ball_spot_chance(const Hand& h, const Spot& spot, bool grid) {
  const std::optional<int>& allowed = h.q.position.shot.pocket;
  const std::vector<int> ids = grid ? target_ids(h.q.position.shot) : std::vector<int>{spot.target};
  for (const GhostBallPot& pot : ghost_ball_pots(spot.table, h.cue_id, ids))  // best first
    if (grid ? !allowed || pot.pocket == *allowed : pot.pocket == spot.pocket)
      return ghost_ball_pot_chance(pot.aim_tolerance, h.q.position.shot.noise.aim);
  return 0.0;
}

// Step 2: each spot's direct shot into its pocket (a grid spot's: every
// shot asked for) scored by its window probability, noise-free (by
// LeaveValuation::ghost_ball: its ghost-ball chance); the kInHandSpots best
// kept, at most two a pocket (grid spots: no such limit).
std::vector<const Spot*> kept_spots(const Hand& h, std::vector<Spot>& spots, bool grid, LeaveValuation valuation,
                                   int& simulations) {
  for (Spot& spot : spots) {
    if (valuation == LeaveValuation::ghost_ball) {
      spot.window = ghost_ball_spot_chance(h, spot, grid);
      continue;
    }
    PlanRequest direct = h.q.position.shot;
    direct.cue_ball = h.cue_id;
    if (!grid) {
      direct.target = spot.target;
      direct.targets.clear();
      direct.pocket = spot.pocket;
      direct.kinds = {ShotKind::direct};
    }
    direct.simulations = kMinPlanSimulations;
    spot.window = best_window_probability(spot.table, direct, simulations);
  }
  std::stable_sort(spots.begin(), spots.end(), [](const Spot& a, const Spot& b) {
    const double wa = std::floor(a.window / 0.02), wb = std::floor(b.window / 0.02);
    if (wa != wb) return wa > wb;
    return a.paths < b.paths;
  });
  std::vector<const Spot*> kept;
  for (const Spot& spot : spots) {
    if (kept.size() == kInHandSpots || spot.window <= 0.0) break;
    const auto same_pocket = std::count_if(kept.begin(), kept.end(), [&](const Spot* k) {
      return k->target == spot.target && k->pocket == spot.pocket;
    });
    if (grid || same_pocket < 2) kept.push_back(&spot);
  }
  return kept;
}

// Step 3: each kept spot played for position; the best leave chosen.
void play_kept_spots(const Hand& h, const std::vector<const Spot*>& kept, BallInHandResult& result, int& simulations) {
  PositionRequest p = h.q.position;
  p.shot.cue_ball = h.cue_id;
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
}

}  // namespace

BallInHandResult plan_ball_in_hand(const Scenario& table_state, const BallInHandRequest& q) {
  const auto start = std::chrono::steady_clock::now();
  if (q.region && q.region->kind == PlacementRegion::Kind::rectangle) {
    check_bounds("x_min", q.region->x_min, "x_max", q.region->x_max);
    check_bounds("y_min", q.region->y_min, "y_max", q.region->y_max);
    check_on_table(*q.region, table_state.table);
  }
  const Hand h = hand_of(table_state, q);
  // 1. Spots behind the ghost ball of each clear pocket, else on a grid.
  std::vector<Spot> spots = ghost_ball_spots(h);
  bool grid = spots.empty();
  if (grid) spots = grid_spots(h);
  if (spots.empty())
    throw NoFeasibleShot(std::string("no spot for the cue ball: no free place") + (q.region ? " inside the region" : "") +
                         " on a grid of " + std::to_string(kInHandGrid[0] * kInHandGrid[1]) + " places");
  // 2. Each spot scored noise-free; the best kept.
  int simulations = 0;
  std::vector<const Spot*> kept = kept_spots(h, spots, grid, q.position.valuation, simulations);
  // 2b. None scored above 0, where the score saw only straight pots (a
  // ghost-ball chance, or a direct shot into the spot's pocket): the grid's
  // places scored by the engine's window search of every shot asked for (a
  // bank, a kick), which they may still allow.
  if (kept.empty() && (!grid || q.position.valuation == LeaveValuation::ghost_ball)) {
    if (!grid) spots = grid_spots(h);  // the grid already: its places rescored
    grid = true;
    kept = kept_spots(h, spots, grid, LeaveValuation::windows, simulations);
  }
  BallInHandResult result;
  result.spots = static_cast<int>(spots.size());
  if (kept.empty())
    throw NoFeasibleShot("no spot for the cue ball pots " + targets_text(target_ids(q.position.shot)) + " (" +
                         std::to_string(spots.size()) + (grid ? " places on a grid" : " spots behind ghost balls") +
                         " tried)");
  // 3. Each kept spot played for position; the best leave chosen.
  play_kept_spots(h, kept, result, simulations);
  result.plan.plan.simulations = simulations;
  result.plan.plan.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace cueball
