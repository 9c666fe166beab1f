// The recommended opening shot of each discipline (games/break_shot.hpp;
// the measurements: docs/break.md).
//
// Pool: fixed, measured constants on the rack's own geometry. Snooker and
// three-cushion: a short deterministic scan with the engine (no noise) over
// the contact's fullness on the target ball, at a few speeds and sides,
// keeping the middle of the widest run of neighbouring offsets that all
// succeed (a safe break-off back to baulk; a three-cushion point), so that
// the shot has the most room for error the scan can see.
#include "cueball/games/break_shot.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "cueball/core/errors.hpp"
#include "cueball/table/placement.hpp"
#include "cueball/table/rack.hpp"

namespace cueball {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;
// Snooker ids (game.hpp): reds 1..15, colours 16..21.
constexpr int kLastRed = 15;
// Three-cushion ids: 0 white, 1 yellow, 2 red.
constexpr int kCaromRed = 2;

const SimulationBall* find(const Scenario& table, int id) {
  for (const SimulationBall& b : table.balls)
    if (b.id == id) return &b;
  return nullptr;
}

double angle_deg(Vec2 d) { return std::atan2(d.y, d.x) * kRadToDeg; }

// The aim, degrees, from `from` at a ball at `target` so that the cue ball's
// line passes the target's centre at `offset` diameters to the left (+) or
// right (-) of the line of centres: fullness 1 - |offset|.
double aim_with_offset(Vec2 from, Vec2 target, double offset, double radius) {
  const Vec2 d = target - from;
  const double s = std::clamp(offset * 2.0 * radius / norm(d), -1.0, 1.0);
  return angle_deg(d) + std::asin(s) * kRadToDeg;
}

std::vector<Vec2> positions_but(const Scenario& table, int id) {
  std::vector<Vec2> out;
  for (const SimulationBall& b : table.balls)
    if (b.id != id) out.push_back(b.state.position);
  return out;
}

// `wanted` when it is in the region and free, else the nearest free spot
// of the region on the line through it along `along` (a unit vector), in
// 5 mm steps either way, up to `reach`; none when there is none.
std::optional<Vec2> free_spot_near(const GameState& state, Vec2 wanted, Vec2 along, double reach) {
  const Table& t = state.table.table;
  const std::vector<Vec2> others = positions_but(state.table, state.cue_ball());
  const double step = 0.005;
  for (double s = 0.0; s <= reach; s += step)
    for (const double sign : {1.0, -1.0}) {
      const Vec2 p = wanted + (sign * s) * along;
      if ((!state.ball_in_hand || in_region(t, *state.ball_in_hand, p)) && is_free_spot(t, others, p, t.ball.radius))
        return p;
    }
  return std::nullopt;
}

// Where the cue ball is struck from: placed (in hand) or where it lies.
Vec2 cue_position(const GameState& state, Action& action, Vec2 wanted, Vec2 along) {
  if (state.ball_in_hand) {
    const Table& t = state.table.table;
    const std::optional<Vec2> p = free_spot_near(state, wanted, along, std::max(t.length, t.width));
    if (!p) throw InvalidArgument("place", "no free spot for the cue ball in its region near (" +
                                               std::to_string(wanted.x) + ", " + std::to_string(wanted.y) + ")");
    action.place = *p;
    return *p;
  }
  const SimulationBall* cue = find(state.table, state.cue_ball());
  if (cue == nullptr) throw InvalidArgument("kind", "the cue ball is neither on the table nor in hand");
  return cue->state.position;
}

// ------------------------------------------------------------------ pool

Action pool_break(const GameState& state) {
  const Table& t = state.table.table;
  const double R = t.ball.radius;
  const std::vector<int> balls = object_balls(state);
  if (balls.empty()) throw InvalidArgument("kind", "a pool break needs an object ball on the table");
  // The apex: the ball on (the lowest object ball, WPA 2.3 / 3.3 / 9.3).
  const int apex_id = state.on.empty() ? *std::min_element(balls.begin(), balls.end()) : state.on.front();
  const SimulationBall* apex = find(state.table, apex_id);
  if (apex == nullptr) throw InvalidArgument("kind", "the ball on, " + std::to_string(apex_id) + ", is not on the table");
  const Vec2 a = apex->state.position;

  Action action;
  const double x = head_string_x(t) - kBreakBehindString;
  const double y = R + kBreakFromRail;
  // The spot, or the nearest free one across the table from it.
  const Vec2 cue = cue_position(state, action, {x, y}, {0.0, 1.0});
  // A cut passes the apex on the cue ball's own side of the long string.
  const double side_sign = cue.y < long_string_y(t) ? -1.0 : 1.0;
  action.strike.speed = kBreakSpeed;
  action.strike.aim_deg = aim_with_offset(cue, a, side_sign * kBreakCut, R);
  action.strike.height = kBreakHeight;
  action.strike.elevation_deg = kBreakElevationDeg;
  return action;
}

// ------------------------------------------------------------------ scans with the engine

// One candidate of a scan: a strike and whether the engine says it works.
struct Candidate {
  ShotAction strike;
  bool ok = false;
};

// A scan: rows of candidates (one per speed and side), each ordered by the
// contact's offset; the answer is the middle of the longest run of
// successes in any row (the first such row on a tie).
struct Scan {
  std::vector<std::vector<Candidate>> rows;
};

std::optional<ShotAction> widest_window(const Scan& scan) {
  std::size_t best_len = 0;
  std::optional<ShotAction> best;
  for (const std::vector<Candidate>& row : scan.rows) {
    std::size_t start = 0;
    for (std::size_t i = 0; i <= row.size(); ++i) {
      if (i < row.size() && row[i].ok) continue;
      const std::size_t len = i - start;
      if (len > best_len) {
        best_len = len;
        best = row[start + len / 2].strike;
      }
      start = i + 1;
    }
  }
  return best;
}

// Plays `strike` on the cue ball from `cue` on the state's table, without noise.
ShotFacts try_strike(const GameState& state, Vec2 cue, const ShotAction& strike, SimulationResult& result) {
  Scenario s = state.table;
  const int cue_id = state.cue_ball();
  bool placed = false;
  for (SimulationBall& b : s.balls)
    if (b.id == cue_id) {
      b.state = BallState{};
      b.state.position = cue;
      placed = true;
    }
  if (!placed) {
    SimulationBall b;
    b.id = cue_id;
    b.name = "cue";
    b.state.position = cue;
    s.balls.insert(s.balls.begin(), b);
  }
  ShotStrike st;
  st.ball = cue_id;
  st.strike = to_strike(strike, s.table.ball.radius);
  s.cue = st;
  result = run_scenario(s);
  return shot_facts(s.table, s.settings.parameters, result, cue_id);
}

// ---- snooker: a safe break-off

struct BreakOff {
  const GameState& state;
  Vec2 cue;
  Vec2 end_red;
  double baulk_line_x = 0.0;
  Scan scan;
};

// Step 1: the end red of the back row on the yellow's side (lowest y), and
// the cue ball's spot in the D between the yellow and the brown.
void choose_target(BreakOff& b, Action& action) {
  const Table& t = b.state.table.table;
  const SnookerSpots spots = snooker_spots(t);
  b.baulk_line_x = spots.baulk_line_x;
  double back = -1.0;
  for (const SimulationBall& ball : b.state.table.balls)
    if (ball.id >= 1 && ball.id <= kLastRed) back = std::max(back, ball.state.position.x);
  if (back < 0.0) throw InvalidArgument("kind", "a snooker break-off needs a red on the table");
  bool found = false;
  for (const SimulationBall& ball : b.state.table.balls) {
    if (ball.id < 1 || ball.id > kLastRed || ball.state.position.x < back - t.ball.radius) continue;
    if (!found || ball.state.position.y < b.end_red.y) b.end_red = ball.state.position;
    found = true;
  }
  const Vec2 wanted{spots.baulk_line_x - 0.005, 0.5 * t.width - 0.6 * spots.d_radius};
  b.cue = cue_position(b.state, action, wanted, {0.0, 1.0});
}

// Step 2: contacts from thin to half-ball on the red's outer (yellow) side,
// three speeds, both sides; a success hits a red first, pots nothing and
// leaves the cue ball in baulk. (The pack's reds touch: the end red, backed
// by its row, throws the cue ball off wider than a lone red would,
// contact_cluster.hpp, so the safe contacts are the fuller ones.)
void scan_break_off(BreakOff& b) {
  const double R = b.state.table.table.ball.radius;
  for (const double speed : {kBreakOffSpeed - 1.0, kBreakOffSpeed - 0.5, kBreakOffSpeed})
    for (const double side : {kBreakOffSide, -kBreakOffSide}) {
      std::vector<Candidate> row;
      for (double fullness = 0.02; fullness <= 0.601; fullness += 0.02) {
        Candidate c;
        c.strike.speed = speed;
        c.strike.side = side;
        // The outer side: the cue ball passes the red on the low-y side.
        c.strike.aim_deg = aim_with_offset(b.cue, b.end_red, -(1.0 - fullness), R);
        SimulationResult r;
        const ShotFacts f = try_strike(b.state, b.cue, c.strike, r);
        bool in_baulk = false;
        for (const BallTrajectory& bt : r.balls)
          if (bt.id == b.state.cue_ball()) in_baulk = !bt.pocketed && bt.final_state.position.x < b.baulk_line_x;
        c.ok = f.first_contact >= 1 && f.first_contact <= kLastRed && f.pots.empty() && in_baulk;
        row.push_back(c);
      }
      b.scan.rows.push_back(std::move(row));
    }
}

Action snooker_break_off(const GameState& state) {
  Action action;
  BreakOff b{state, {}, {}, 0.0, {}};
  choose_target(b, action);
  scan_break_off(b);
  const std::optional<ShotAction> best = widest_window(b.scan);
  if (best) {
    action.strike = *best;
  } else {  // no safe one found: the documented nominal break-off
    action.strike.speed = kBreakOffSpeed;
    action.strike.side = kBreakOffSide;
    action.strike.aim_deg = aim_with_offset(b.cue, b.end_red, -(1.0 - kBreakOffFullness), state.table.table.ball.radius);
  }
  return action;
}

// ---- three-cushion: the opening shot

struct Opening {
  const GameState& state;
  int cue_id = 0;
  int other_id = 1;
  Vec2 cue;
  Vec2 red;
  Scan scan;
};

// The point (UMB): the red first, then the other ball after at least three cushions.
bool made_point(const ShotFacts& f, int other) {
  if (f.first_contact != kCaromRed) return false;
  for (const CueCushionsBeforeContact& c : f.cue_cushions_before_contact)
    if (c.ball == other) return c.cushions >= 3;
  return false;
}

// Offsets across the whole red, three speeds, the three sides.
void scan_opening(Opening& o) {
  const double R = o.state.table.table.ball.radius;
  for (const double speed : {kOpeningSpeed - 0.5, kOpeningSpeed, kOpeningSpeed + 0.5})
    for (const double side : {0.0, 0.3, -0.3}) {
      std::vector<Candidate> row;
      for (int k = -30; k <= 30; ++k) {
        Candidate c;
        c.strike.speed = speed;
        c.strike.side = side;
        c.strike.aim_deg = aim_with_offset(o.cue, o.red, 0.03 * k, R);
        SimulationResult r;
        c.ok = made_point(try_strike(o.state, o.cue, c.strike, r), o.other_id);
        row.push_back(c);
      }
      o.scan.rows.push_back(std::move(row));
    }
}

Action three_cushion_opening(const GameState& state) {
  Opening o{state, state.cue_ball(), state.cue_ball() == 0 ? 1 : 0, {}, {}, {}};
  const SimulationBall* red = find(state.table, kCaromRed);
  if (red == nullptr || find(state.table, o.other_id) == nullptr)
    throw InvalidArgument("kind", "a three-cushion opening needs the red and the opponent's ball on the table");
  o.red = red->state.position;
  Action action;
  const SimulationBall* cue = find(state.table, o.cue_id);
  if (cue == nullptr) throw InvalidArgument("kind", "the cue ball is not on the table");
  o.cue = cue->state.position;
  scan_opening(o);
  const std::optional<ShotAction> best = widest_window(o.scan);
  if (best) {
    action.strike = *best;
  } else {  // none found: the textbook half-ball hit on the cue ball's side of the red
    const double side_sign = o.cue.y < o.red.y ? -1.0 : 1.0;
    action.strike.speed = kOpeningSpeed;
    action.strike.aim_deg = aim_with_offset(o.cue, o.red, side_sign * (1.0 - kOpeningFullness), state.table.table.ball.radius);
  }
  return action;
}

}  // namespace

Action recommended_break(const GameState& state) {
  if (state.phase != GamePhase::break_shot)
    throw InvalidArgument("phase", std::string(to_string(state.phase)) +
                                       ": a recommended break needs a state in phase break_shot");
  switch (state.config.kind) {
    case GameKind::nine_ball:
    case GameKind::eight_ball:
    case GameKind::ten_ball: return pool_break(state);
    case GameKind::snooker: return snooker_break_off(state);
    case GameKind::three_cushion: return three_cushion_opening(state);
  }
  throw InvalidArgument("kind", "unknown game");
}

GameState nine_on_foot_spot(GameState state) {
  if (state.config.kind != GameKind::nine_ball)
    throw InvalidArgument("kind", std::string(to_string(state.config.kind)) + ": only a 9-ball rack has the 9 to spot");
  if (state.phase != GamePhase::break_shot)
    throw InvalidArgument("phase", std::string(to_string(state.phase)) + ": the rack can only be moved before the break");
  const SimulationBall* nine = find(state.table, 9);
  if (nine == nullptr) throw InvalidArgument("kind", "the 9 is not on the table");
  const Table& t = state.table.table;
  const Vec2 shift = foot_spot(t) - nine->state.position;
  const int cue = state.cue_ball();
  for (SimulationBall& b : state.table.balls) {
    if (b.id == cue) continue;
    b.state.position = b.state.position + shift;
    if (!ball_on_table(t, b.state.position))
      throw InvalidArgument("rack", "ball " + std::to_string(b.id) + " would be off the table with the 9 on the foot spot");
  }
  return state;
}

}  // namespace cueball
