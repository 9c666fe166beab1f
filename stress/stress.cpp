// cueball-stress: seeded random shots of nine classes, each simulated and
// checked for the simulator's physical invariants at every event and at
// points between events (issue 11, item 9).
//
// Only the public API (include/cueball/) is used: the tool sees the simulator
// as a user does. Every shot is generated from its own seed (shot k of a run
// with --seed S uses seed S + k, through splitmix64 into std::mt19937_64), so
// the results do not depend on --threads and any shot is reproduced alone by
//     cueball-stress --class NAME --seed S+k --shots 1
// or, written out with --dump-worst, by `cueball simulate FILE`.
//
// The invariants (each a "kind" in the report; a shot counts once per kind,
// with the worst value it reached):
//   overlap      two unpocketed balls' centres closer than 2R - 1e-9 m (value: depth, m)
//   cushion      a centre closer to a cushion's finite nose segment than the
//                contact distance sqrt(h (2R - h)) - 1e-9 m (value: depth, m;
//                a centre behind the nose line counts the contact distance plus
//                its distance behind it)
//   jaw          a centre closer to a jaw's centre than jaw_contact_distance - 1e-9 m
//   off_table    an unpocketed centre outside the playing area: outside the
//                nose-to-nose rectangle [0, L] x [0, W] (1e-9 m slack) and not in
//                a pocket's mouth (the circle about the pocket's centre that
//                holds its jaws' contact circles), or anywhere outside
//                [-0.1, L + 0.1] x [-0.1, W + 0.1] (value: distance outside the rectangle, m)
//   rest_placement  a ball at rest (zero velocity) where ball_on_table() refuses
//                it: inside a cushion's or jaw's contact distance (by more than
//                the 1e-9 m ball_on_table allows), over a pocket's hole but not
//                pocketed, or off the table; a position the next shot could not
//                start from (value: its depth, m)
//   nan          a non-finite number in an event time or a state
//   energy       total kinetic energy (translation + rotation, I = 2/5 m R^2)
//                rising from one checked time to the next by more than
//                1e-9 E + 1e-12 J (value: the gain, J). Between events energy
//                only falls (cloth friction), at events it never rises
//                (restitution <= 1), so every checked time is compared.
//   events       a shot that takes 10,000 events or more (value: the count;
//                the run's limit is 200,000 so the count is known)
//   error        SimulationError (the 200,000-event limit, or a ball leaving a
//                physical state)
//   determinism  the same shot simulated twice differs in any bit of its
//                events, trajectories or final states (every 10th shot)
//   crash        any other exception, from the simulator or from the checks
// The checked times: every distinct event time (the state just after the
// event), 1 ns after and before it (a thousandth of the interval when that is
// shorter), 7 evenly spaced points inside every interval, and the final states.
//
// Set-ups that the library rejects with InvalidArgument (validate_simulation_input
// or the cue strike) are counted as "rejected" and not simulated; the
// generators place balls with the same rules (ball_on_table, centres >= 2R
// apart) so that the count stays near zero.
#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <mutex>
#include <numbers>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "game_stress.hpp"
#include "tool_support.hpp"
#include "cueball/io/scenario_json.hpp"
#include "cueball/physics/cloth_motion.hpp"
#include "cueball/physics/cue_strike.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/core/random.hpp"
#include "cueball/core/parameters.hpp"
#include "cueball/table/placement.hpp"
#include "cueball/table/rack.hpp"
#include "cueball/simulation/scenario.hpp"
#include "cueball/simulation/simulator.hpp"
#include "cueball/io/table_json.hpp"
#include "cueball/table/table.hpp"
#include "cueball/core/vec.hpp"

namespace {

using namespace cueball;
using cueball::tools::fmt;
using cueball::tools::num;
using cueball::tools::quoted;
constexpr tools::Flags kFlags{"cueball-stress"};

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;
constexpr double kTolerance = 1e-9;       // m: overlap, cushion and jaw penetration, off-table slack
constexpr double kEnergyRelative = 1e-9;  // energy may rise by this fraction ...
constexpr double kEnergyAbsolute = 1e-12; // ... plus this, J
constexpr int kEventViolation = 10000;    // a shot this long is a violation
constexpr int kMaxEvents = 200000;        // the simulator's limit in this tool
constexpr int kInteriorPoints = 7;        // checked points inside each interval between events
constexpr double kNearEvent = 1e-9;       // s: "just after" and "just before" an event
constexpr double kOffTableBox = 0.1;      // m: outside [-0.1, L + 0.1] x [-0.1, W + 0.1] is always off

// ------------------------------------------------------------------ geometry

Vec2 direction(double angle) { return {std::cos(angle), std::sin(angle)}; }
double angle_of(Vec2 v) { return std::atan2(v.y, v.x); }

// ------------------------------------------------------------------ a shot

// The input of one simulation: the balls' states at t = 0, after the strike.
struct Shot {
  Table table;
  SimulationSettings settings;
  std::vector<SimulationBall> balls;
  std::string what;  // what the generator built, for the report

  double radius() const { return settings.parameters.ball.radius; }
};

const Table& preset(int kind) {  // 0 pool, 1 snooker, 2 carom
  static const Table pool = pool_table_9ft();
  static const Table snooker = snooker_table_12ft();
  static const Table carom = carom_table_10ft();
  return kind == 0 ? pool : kind == 1 ? snooker : carom;
}

// The models every generated shot uses (--cushion-model; each model's own
// constants). Set once by parse(), before any worker starts.
CushionSettings g_cushion;
BallCollisionModel g_ball_collision_model = BallCollisionModel::coulomb_impulse;

Shot new_shot(int table_kind) {
  Shot s;
  s.settings.cushion = g_cushion;
  s.settings.ball_collision_model = g_ball_collision_model;
  s.settings.ball_collision = default_ball_collision(g_ball_collision_model);
  s.table = preset(table_kind);
  // As the scenario reader does: the cloth preset that goes with the table, the table's ball.
  s.settings.parameters = table_kind == 1 ? snooker_parameters() : pool_parameters();
  s.settings.parameters.ball = s.table.ball;
  s.settings.max_events = kMaxEvents;
  return s;
}

const char* table_label(const Table& t) {
  if (t == preset(0)) return "pool_9ft";
  if (t == preset(1)) return "snooker_12ft";
  if (t == preset(2)) return "carom_10ft";
  return "custom table";
}

// A generator could not place its balls (never seen; retried by the caller).
struct Unplaceable {};

// Smallest centre distance minus 2R to the balls already placed (skipping index `except`).
double ball_gap(const Shot& s, Vec2 p, std::size_t except = SIZE_MAX) {
  double g = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < s.balls.size(); ++i)
    if (i != except) g = std::min(g, norm(p - s.balls[i].state.position) - 2.0 * s.radius());
  return g;
}

std::vector<Vec2> positions(const Shot& s) {
  std::vector<Vec2> out;
  for (const SimulationBall& b : s.balls) out.push_back(b.state.position);
  return out;
}

bool placeable(const Shot& s, Vec2 p, double margin = 0.0) { return is_free_spot(s.table, positions(s), p, s.radius(), margin); }

std::size_t add_ball(Shot& s, Vec2 p, BallState state = {}) {
  const int id = static_cast<int>(s.balls.size());
  state.position = p;
  s.balls.push_back({id, id == 0 ? "cue" : std::to_string(id), state});
  return s.balls.size() - 1;
}

Vec2 random_spot(const Shot& s, RandomStream& rng, double margin = 0.0) {
  const std::optional<Vec2> p = random_free_spot(s.table, positions(s), s.radius(), rng, 20000, {}, margin);
  if (!p) throw Unplaceable{};
  return *p;
}

void add_random_balls(Shot& s, RandomStream& rng, int count) {
  for (int k = 0; k < count; ++k) add_ball(s, random_spot(s, rng));
}

// The long cushions (rails), not the pocket facings.
std::vector<std::size_t> rails(const Table& t) {
  std::vector<std::size_t> out;
  for (std::size_t c = 0; c < t.cushions.size(); ++c)
    if (norm(t.cushions[c].end - t.cushions[c].start) > 0.3) out.push_back(c);
  return out;
}

Vec2 rail_direction(const CushionSegment& c) { return (c.end - c.start) / norm(c.end - c.start); }

// The centre of a ball touching rail c at fraction f of its length, `inset`
// metres inside the exact contact distance (0: exactly frozen).
Vec2 on_rail(const Shot& s, std::size_t c, double f, double inset = 0.0) {
  const CushionSegment& seg = s.table.cushions[c];
  const Vec2 foot = seg.start + f * (seg.end - seg.start);
  return foot + (cushion_contact_distance(seg.contact_height, s.radius()) - inset) * inward_normal(seg);
}

// Tip offsets (side, height) in ball radii, uniform over the disc of radius
// `limit` (at most the miscue limit 0.5).
std::pair<double, double> random_tip(RandomStream& rng, double limit = kMiscueOffsetFraction) {
  const double r = limit * std::sqrt(rng.unit());
  const double a = rng.uniform(-kPi, kPi);
  return {r * std::cos(a), r * std::sin(a)};
}

// A large side offset (|side| in [lo, 0.5) R) and a height that keeps the tip
// inside the miscue limit.
std::pair<double, double> side_heavy_tip(RandomStream& rng, double lo) {
  const double side = rng.sign() * rng.uniform(lo, 0.499);
  const double room = std::sqrt(std::max(0.0, 0.25 - side * side)) * 0.999;
  return {side, rng.uniform(-room, room)};
}

// Strikes ball i with the library's cue strike: cue along `aim` (rad), butt
// raised by `elevation`, tip offsets in ball radii, with the cue speed chosen
// so that the ball leaves at `ball_speed` m/s (the ball's speed is linear in
// the cue's; capped at the fastest cue, kMaxCueSpeed). Throws InvalidArgument
// for a strike the library refuses.
void strike(Shot& s, std::size_t i, double ball_speed, double aim, double elevation, std::pair<double, double> tip) {
  const BallParameters& ball = s.settings.parameters.ball;
  const CueParameters cue;
  CueStrike k{1.0, aim, elevation, tip.first * ball.radius, tip.second * ball.radius};
  const double per_unit = norm(strike_ball(k, s.balls[i].state.position, ball, cue).velocity);
  k.speed = std::min(kMaxCueSpeed, ball_speed / per_unit);
  s.balls[i].state = strike_ball(k, s.balls[i].state.position, ball, cue);
  s.what += fmt("; ball %d struck: ball speed %.4g m/s (cue %.4g m/s), aim %.3f deg, elevation %.2f deg, "
                "tip side %.3f R height %.3f R",
                s.balls[i].id, norm(s.balls[i].state.velocity), k.speed, aim / kDeg, elevation / kDeg, tip.first,
                tip.second);
}

// A ball set moving directly (a nudge, not a cue strike): speed v along
// `aim`, rolling (no slip) or sliding without spin, and some side spin.
void nudge(Shot& s, std::size_t i, double v, double aim, bool rolling, double side_spin) {
  BallState& st = s.balls[i].state;
  const Vec2 u = v * direction(aim);
  st.velocity = u;
  const double r = s.radius();
  // Rolling: slip u + R z^ x w = 0, i.e. w_y = v_x / R, w_x = -v_y / R.
  st.angular_velocity = rolling ? Vec3{-u.y / r, u.x / r, side_spin} : Vec3{0.0, 0.0, side_spin};
  s.what += fmt("; ball %d nudged: %.4g m/s, aim %.3f deg, %s, w_z %.3g rad/s", s.balls[i].id, v, aim / kDeg,
                rolling ? "rolling" : "sliding", side_spin);
}

// Spin that drives a resting ball along unit vector n by cloth friction: the
// slip R z^ x w points along -n, so friction pushes along n. `slip` m/s.
Vec3 spin_driving_along(Vec2 n, double slip, double radius, double side_spin) {
  return {-n.y * slip / radius, n.x * slip / radius, side_spin};
}

// ------------------------------------------------------------------ the shot classes

// 1. break: the opening shot of every rack the library has (9-ball and 8-ball
// on the 9-ft pool table, snooker on the 12-ft table), frozen or with small
// random gaps, hard (8-14 m/s at the ball), aim jittered, any tip offset, cue
// raised 0-20 deg. The everyday case: it must be clean (no false positives).
void make_break(Shot& s, RandomStream& rng) {
  const int variant = rng.integer(0, 2);
  s = new_shot(variant == 2 ? 1 : 0);
  RackOptions options;
  options.gap_sigma = rng.chance(0.5) ? 0.0 : rng.uniform(0.0, 5e-4);
  options.seed = rng.bits() & 0x7fffffffULL;
  const std::vector<PlacedBall> placed = variant == 0   ? rack_nine_ball(s.table, options)
                                         : variant == 1 ? rack_eight_ball(s.table, options)
                                                        : rack_snooker(s.table, options);
  s.what = fmt("%s break on %s, rack gap_sigma %.3g m, rack seed %llu", variant == 0 ? "9-ball" : variant == 1 ? "8-ball" : "snooker",
               table_label(s.table), options.gap_sigma, static_cast<unsigned long long>(options.seed));
  std::size_t cue = 0;
  for (const PlacedBall& b : placed) {
    s.balls.push_back({b.id, b.name, {b.position, {}, {}}});
    if (b.id == 0) cue = s.balls.size() - 1;
  }
  // Move the cue ball somewhere behind the head string (pool) or in the D (snooker).
  const double r = s.radius();
  for (int attempt = 0; attempt < 1000; ++attempt) {
    Vec2 p;
    if (variant == 2) {
      const SnookerSpots spots = snooker_spots(s.table);
      const double a = rng.uniform(0.5 * kPi, 1.5 * kPi), d = spots.d_radius * std::sqrt(rng.unit());
      p = spots.brown + d * direction(a);
    } else {
      p = {rng.uniform(0.3, head_string_x(s.table) - r), rng.uniform(0.25, s.table.width - 0.25)};
    }
    if (ball_on_table(s.table, p, r) && ball_gap(s, p, cue) >= 0.0) {
      s.balls[cue].state.position = p;
      break;
    }
  }
  // Aim: pool at the apex (the 1); snooker at a random red (the pack's edge or inside).
  std::size_t target = 0;
  if (variant == 2) {
    const int red = rng.integer(1, 15);
    for (std::size_t i = 0; i < s.balls.size(); ++i)
      if (s.balls[i].id == red) target = i;
  } else {
    for (std::size_t i = 0; i < s.balls.size(); ++i)
      if (s.balls[i].id == 1) target = i;
  }
  const double aim = angle_of(s.balls[target].state.position - s.balls[cue].state.position) + rng.uniform(-1.5, 1.5) * kDeg;
  strike(s, cue, rng.uniform(8.0, 14.0), aim, rng.uniform(0.0, 20.0) * kDeg, random_tip(rng));
}

// 2. random: 2-16 balls anywhere on any table, the cue ball struck in any
// direction at 0.05-8 m/s (log-uniform), cue raised 0-60 deg, any tip offset
// within the miscue limit. Broad coverage of ordinary play.
void make_random(Shot& s, RandomStream& rng) {
  s = new_shot(rng.integer(0, 2));
  const int n = rng.integer(2, 16);
  s.what = fmt("%d random balls on %s", n, table_label(s.table));
  add_random_balls(s, rng, n);
  strike(s, 0, rng.log_uniform(0.05, 8.0), rng.uniform(-kPi, kPi), rng.uniform(0.0, 60.0) * kDeg, random_tip(rng));
}

// 3. rail_frozen: the cue ball frozen to a rail (its centre exactly at the
// contact distance), struck along the rail or a few degrees into or away from
// it, with the cue raised 10-80 deg and side spin. Swerve and masse off a rail
// press the ball into the cushion while it is in contact: the case of the
// 38 mm penetration in shared/repro/rail_swerve_pool_penetrates_38mm.json.
void make_rail_frozen(Shot& s, RandomStream& rng) {
  s = new_shot(rng.integer(0, 2));
  const std::vector<std::size_t> rs = rails(s.table);
  for (int attempt = 0;; ++attempt) {
    if (attempt > 1000) throw Unplaceable{};
    const std::size_t c = rs[static_cast<std::size_t>(rng.integer(0, static_cast<int>(rs.size()) - 1))];
    const double f = rng.uniform(0.03, 0.97);
    const Vec2 p = on_rail(s, c, f);
    if (!ball_on_table(s.table, p, s.radius())) continue;
    add_ball(s, p);
    const CushionSegment& seg = s.table.cushions[c];
    const Vec2 along = rng.sign() * rail_direction(seg);
    // Positive angles turn away from the rail (towards the table), negative into it.
    const double which = rng.unit();
    const double angle = which < 0.25 ? 0.0 : which < 0.8 ? rng.uniform(-10.0, 10.0) : rng.uniform(-45.0, 45.0);
    const double turn = cross(along, inward_normal(seg)) > 0 ? 1.0 : -1.0;  // sign that turns `along` towards the table
    s.what = fmt("cue ball frozen to cushion %zu of %s at %.3f of its length, cue %.2f deg %s the rail", c,
                 table_label(s.table), f, std::abs(angle), angle >= 0 ? "away from" : "into");
    add_random_balls(s, rng, rng.integer(0, 3));
    strike(s, 0, rng.log_uniform(0.05, 6.0), angle_of(along) + turn * angle * kDeg, rng.uniform(10.0, 80.0) * kDeg,
           rng.chance(0.7) ? side_heavy_tip(rng, 0.1) : random_tip(rng));
    return;
  }
}

// The round-off overlaps of the validator's limit: exactly touching, or
// overlapping by 1e-15 m, 1e-12 m or up to (just under) 1e-9 m.
double touching_overlap(RandomStream& rng, double limit) {
  const double w = rng.unit();
  if (w < 0.35) return 0.0;
  if (w < 0.5) return 1e-15;
  if (w < 0.6) return std::min(limit, 1e-12);
  if (w < 0.7) return 0.99 * limit;
  return rng.uniform(0.0, 0.99 * limit);
}

// 4. ball_frozen: two balls frozen together (centres 2R apart, or closer by
// up to the validator's 1e-9 m), the cue ball struck along their common
// tangent, into the other ball or anywhere, with raised cue and side spin.
// Tests the touching-but-separating rule and the pair's prediction at contact.
void make_ball_frozen(Shot& s, RandomStream& rng) {
  s = new_shot(rng.integer(0, 2));
  const double r = s.radius();
  for (int attempt = 0;; ++attempt) {
    if (attempt > 1000) throw Unplaceable{};
    s.balls.clear();
    const Vec2 a = random_spot(s, rng);
    const double phi = rng.uniform(-kPi, kPi);
    const double overlap = touching_overlap(rng, 1e-9);
    const Vec2 b = a + (2.0 * r - overlap) * direction(phi);
    if (!ball_on_table(s.table, b, r)) continue;
    add_ball(s, a);
    s.balls.push_back({1, "1", {b, {}, {}}});
    const double which = rng.unit();
    const double aim = which < 0.4   ? phi + rng.sign() * 0.5 * kPi + (rng.chance(0.5) ? 0.0 : rng.uniform(-1.0, 1.0) * kDeg)
                       : which < 0.7 ? phi + rng.uniform(-30.0, 30.0) * kDeg
                                     : rng.uniform(-kPi, kPi);
    s.what = fmt("cue ball frozen to ball 1 on %s (centres 2R - %.3g m apart), aim %.2f deg from the line of centres",
                 table_label(s.table), overlap, std::remainder(aim - phi, 2 * kPi) / kDeg);
    add_random_balls(s, rng, rng.integer(0, 3));
    strike(s, 0, rng.log_uniform(0.01, 6.0), aim, rng.chance(0.3) ? 0.0 : rng.uniform(0.0, 80.0) * kDeg,
           rng.chance(0.6) ? side_heavy_tip(rng, 0.1) : random_tip(rng));
    return;
  }
}

// 5. cluster: frozen groups of 3-10 balls (straight rows, triangles, random
// chains, Newton's-cradle lines with a cue ball behind them, rows against a
// rail), struck or nudged at 1 mm/s - 5 m/s. Chains of simultaneous contacts
// are where pairwise impulses can cascade without end (pitfall 6;
// shared/repro/frozen_cluster_event_limit_zeno.json).
void make_cluster(Shot& s, RandomStream& rng) {
  s = new_shot(rng.integer(0, 2));
  const double r = s.radius(), d = 2.0 * r;
  const int shape = rng.integer(0, 4);  // row, triangle, chain, cradle, against a rail
  static const char* const names[] = {"row", "triangle", "chain", "Newton's cradle", "row against a rail"};
  for (int attempt = 0;; ++attempt) {
    if (attempt > 2000) throw Unplaceable{};
    s.balls.clear();
    std::vector<Vec2> p;
    Vec2 u = direction(rng.uniform(-kPi, kPi));
    if (shape == 4) {
      const std::vector<std::size_t> rs = rails(s.table);
      const std::size_t c = rs[static_cast<std::size_t>(rng.integer(0, static_cast<int>(rs.size()) - 1))];
      const CushionSegment& seg = s.table.cushions[c];
      const Vec2 start = on_rail(s, c, rng.uniform(0.05, 0.95));
      const bool along = rng.chance(0.5);  // along the rail (all frozen to it) or out from it
      u = along ? rail_direction(seg) : inward_normal(seg);
      const int n = rng.integer(2, 8);
      for (int k = 0; k < n; ++k) p.push_back(start + (d * k) * u);
    } else if (shape == 1) {
      const int rows = rng.integer(2, 4);  // 3, 6 or 10 balls
      const Vec2 apex = {rng.uniform(0.0, s.table.length), rng.uniform(0.0, s.table.width)};
      const Vec2 v = perp(u);
      for (int i = 0; i < rows; ++i)
        for (int k = 0; k <= i; ++k)
          p.push_back(apex + (std::sqrt(3.0) * r * i) * u + (d * (k - 0.5 * i)) * v);
    } else {
      const int n = rng.integer(3, 10);
      p.push_back({rng.uniform(0.0, s.table.length), rng.uniform(0.0, s.table.width)});
      double heading = angle_of(u);
      bool ok = true;
      for (int k = 1; k < n && ok; ++k) {
        if (shape == 2) heading += rng.uniform(-0.5 * kPi, 0.5 * kPi);
        const Vec2 q = p.back() + d * direction(heading);
        for (std::size_t j = 0; j + 1 < p.size(); ++j) ok = ok && norm(q - p[j]) >= d;
        p.push_back(q);
      }
      if (!ok) continue;
    }
    bool ok = true;
    for (const Vec2& q : p) ok = ok && ball_on_table(s.table, q, r);
    if (!ok) continue;
    for (const Vec2& q : p) add_ball(s, q);
    s.what = fmt("%s of %zu frozen balls on %s", names[shape], p.size(), table_label(s.table));
    const double speed = rng.log_uniform(1e-3, 5.0);
    if (shape == 3 || (shape == 4 && rng.chance(0.5)) || rng.chance(0.3)) {
      // A cue ball behind the first ball of the line (or at a random spot), frozen or at a gap.
      const double gap = rng.chance(0.3) ? 0.0 : rng.log_uniform(1e-3, 0.3);
      Vec2 c = p.front() - (d + gap) * u;
      if (!placeable(s, c)) c = random_spot(s, rng);
      const std::size_t cue = add_ball(s, c);
      std::swap(s.balls[0].state, s.balls[cue].state);  // the cue ball is id 0
      const double aim = angle_of(p.front() - c) + (rng.chance(0.5) ? 0.0 : rng.uniform(-2.0, 2.0) * kDeg);
      s.what += fmt(", cue ball %.3g m behind ball 1", norm(p.front() - c) - d);
      strike(s, 0, speed, aim, rng.chance(0.5) ? 0.0 : rng.uniform(0.0, 40.0) * kDeg, random_tip(rng));
    } else if (rng.chance(0.5)) {
      // One ball of the cluster struck: into its neighbour, or anywhere.
      const std::size_t k = rng.chance(0.5) ? 0 : static_cast<std::size_t>(rng.integer(0, static_cast<int>(p.size()) - 1));
      const Vec2 to = p[k == 0 ? 1 : k - 1] - p[k];
      const double aim = rng.chance(0.6) ? angle_of(to) + rng.uniform(-5.0, 5.0) * kDeg : rng.uniform(-kPi, kPi);
      strike(s, k, speed, aim, rng.chance(0.5) ? 0.0 : rng.uniform(0.0, 60.0) * kDeg, random_tip(rng));
    } else {
      const std::size_t k = static_cast<std::size_t>(rng.integer(0, static_cast<int>(p.size()) - 1));
      Vec2 centroid{};
      for (const Vec2& q : p) centroid = centroid + q / static_cast<double>(p.size());
      const Vec2 to = centroid - p[k];
      const double aim = norm(to) > 1e-9 && rng.chance(0.6) ? angle_of(to) : rng.uniform(-kPi, kPi);
      nudge(s, k, speed, aim, rng.chance(0.5), rng.chance(0.5) ? 0.0 : rng.uniform(-30.0, 30.0));
    }
    return;
  }
}

// 6. jaw: balls touching a jaw (centre exactly at the jaw's contact
// distance) or in a pocket's mouth, struck themselves or hit by the cue ball,
// slow (1 cm/s - 0.5 m/s) and fast (1-10 m/s). The jaws are the only curved
// cushions and meet the nose and facing segments tangentially.
void make_jaw(Shot& s, RandomStream& rng) {
  s = new_shot(rng.integer(0, 1));
  const double r = s.radius();
  for (int attempt = 0;; ++attempt) {
    if (attempt > 5000) throw Unplaceable{};
    s.balls.clear();
    Vec2 p;
    std::size_t pocket = 0;
    const bool touching = rng.chance(0.5);
    if (touching) {
      const std::size_t j = static_cast<std::size_t>(rng.integer(0, static_cast<int>(s.table.jaws.size()) - 1));
      const JawArc& jaw = s.table.jaws[j];
      p = jaw.centre + jaw_contact_distance(jaw, r) * direction(rng.uniform(-kPi, kPi));
      for (std::size_t q = 0; q < s.table.pockets.size(); ++q)
        if (norm(s.table.pockets[q].centre - jaw.centre) < norm(s.table.pockets[pocket].centre - jaw.centre)) pocket = q;
      s.what = fmt("ball touching jaw %zu of %s", j, table_label(s.table));
    } else {
      pocket = static_cast<std::size_t>(rng.integer(0, static_cast<int>(s.table.pockets.size()) - 1));
      const Pocket& q = s.table.pockets[pocket];
      p = q.centre + rng.uniform(q.radius, q.radius + 0.08) * direction(rng.uniform(-kPi, kPi));
      s.what = fmt("ball in the mouth of pocket %s of %s", q.name.c_str(), table_label(s.table));
    }
    if (!ball_on_table(s.table, p, r)) continue;
    const double speed = rng.chance(0.5) ? rng.log_uniform(0.01, 0.5) : rng.uniform(1.0, 10.0);
    const Vec2 to_pocket = s.table.pockets[pocket].centre - p;
    if (rng.chance(0.5)) {
      add_ball(s, p);  // the ball at the jaw is the cue ball
      add_random_balls(s, rng, rng.integer(0, 2));
      const double aim = rng.chance(0.5) ? angle_of(to_pocket) + rng.uniform(-30.0, 30.0) * kDeg : rng.uniform(-kPi, kPi);
      strike(s, 0, speed, aim, rng.uniform(0.0, 30.0) * kDeg, random_tip(rng));
    } else {
      add_ball(s, {});  // placeholder for the cue ball, id 0
      s.balls[0].state.position = {-1.0, -1.0};
      add_ball(s, p);
      Vec2 c{};
      bool found = false;
      for (int k = 0; k < 200 && !found; ++k) {
        // The cue ball on the far side of the object ball from the pocket, 5 cm - 1 m away.
        const Vec2 from = -1.0 * to_pocket / std::max(norm(to_pocket), 1e-12);
        c = p + rng.uniform(0.05, 1.0) * direction(angle_of(from) + rng.uniform(-60.0, 60.0) * kDeg);
        found = placeable(s, c);
      }
      if (!found) continue;
      s.balls[0].state.position = c;
      add_random_balls(s, rng, rng.integer(0, 2));
      // A cut: aim at a point up to one ball width beside the object ball's centre.
      const Vec2 target = p + rng.uniform(-1.0, 1.0) * r * perp((p - c) / norm(p - c));
      s.what += ", hit by the cue ball";
      strike(s, 0, speed, angle_of(target - c), rng.uniform(0.0, 30.0) * kDeg, random_tip(rng));
    }
    return;
  }
}

// 7. roundoff: balls placed exactly at the contact distance from each other
// and from cushions and jaws, or inside it by the validator's round-off
// allowance (1e-9 m between balls, 1e-12 m at cushions), at rest or moving at
// 1e-9 m/s, with spin whose cloth friction drives them into the contact.
// Pitfall 4: a contact that starts already touching (or overlapping by
// round-off) must not be missed (shared/repro/overlap_passthrough_roundoff_1e-15.json,
// frozen_to_cushion_spinning_penetrates_5mm.json).
void make_roundoff(Shot& s, RandomStream& rng) {
  s = new_shot(rng.integer(0, 2));
  const double r = s.radius();
  const int variant = s.table.jaws.empty() ? rng.integer(0, 2) : rng.integer(0, 3);
  const auto creep = [&rng]() { return rng.chance(0.5) ? Vec2{} : 1e-9 * direction(rng.uniform(-kPi, kPi)); };
  const auto w_z = [&rng]() { return rng.chance(0.5) ? 0.0 : rng.uniform(-50.0, 50.0); };
  for (int attempt = 0;; ++attempt) {
    if (attempt > 2000) throw Unplaceable{};
    s.balls.clear();
    if (variant == 0) {  // two balls, B spun into A (and maybe A into B)
      const Vec2 a = random_spot(s, rng);
      const double phi = rng.uniform(-kPi, kPi);
      const double overlap = touching_overlap(rng, 1e-9);
      const Vec2 b = a + (2.0 * r - overlap) * direction(phi);
      if (!ball_on_table(s.table, b, r)) continue;
      add_ball(s, b);
      add_ball(s, a);
      const Vec2 into = -1.0 * direction(phi);  // from B towards A
      s.balls[0].state.velocity = creep();
      s.balls[0].state.angular_velocity = spin_driving_along(into, rng.uniform(0.01, 3.0), r, w_z());
      if (rng.chance(0.3)) s.balls[1].state.angular_velocity = spin_driving_along(-1.0 * into, rng.uniform(0.01, 3.0), r, w_z());
      s.what = fmt("ball 0 touching ball 1 on %s (centres 2R - %.3g m apart), spun into it", table_label(s.table), overlap);
    } else if (variant == 1 || variant == 2) {  // a ball frozen to a rail, spun into it; maybe a second ball against it
      const std::vector<std::size_t> rs = rails(s.table);
      const std::size_t c = rs[static_cast<std::size_t>(rng.integer(0, static_cast<int>(rs.size()) - 1))];
      const CushionSegment& seg = s.table.cushions[c];
      const double inset = touching_overlap(rng, 1e-12);
      const Vec2 p = on_rail(s, c, rng.uniform(0.03, 0.97), inset);
      if (!ball_on_table(s.table, p, r)) continue;
      add_ball(s, p);
      // Into the cushion, tilted by up to 60 deg along it.
      const Vec2 into = direction(angle_of(-1.0 * inward_normal(seg)) + rng.uniform(-60.0, 60.0) * kDeg);
      s.balls[0].state.velocity = creep();
      s.balls[0].state.angular_velocity = spin_driving_along(into, rng.uniform(0.01, 3.0), r, w_z());
      s.what = fmt("ball frozen to cushion %zu of %s (%.3g m inside the contact distance), spun into it", c,
                   table_label(s.table), inset);
      if (variant == 2) {  // a second ball touching the first, along the rail or out from it, spun into it
        const Vec2 n = rng.chance(0.5) ? rng.sign() * rail_direction(seg) : inward_normal(seg);
        const Vec2 q = p + (2.0 * r - touching_overlap(rng, 1e-9)) * n;
        if (!ball_on_table(s.table, q, r)) continue;
        const std::size_t k = add_ball(s, q);
        s.balls[k].state.velocity = creep();
        s.balls[k].state.angular_velocity = spin_driving_along(-1.0 * n, rng.uniform(0.01, 3.0), r, w_z());
        s.what += ", ball 1 touching it and spun into it";
      }
    } else {  // a ball touching a jaw, spun into it
      const std::size_t j = static_cast<std::size_t>(rng.integer(0, static_cast<int>(s.table.jaws.size()) - 1));
      const JawArc& jaw = s.table.jaws[j];
      const Vec2 n = direction(rng.uniform(-kPi, kPi));
      const double inset = touching_overlap(rng, 1e-12);
      const Vec2 p = jaw.centre + (jaw_contact_distance(jaw, r) - inset) * n;
      if (!ball_on_table(s.table, p, r)) continue;
      add_ball(s, p);
      const Vec2 into = direction(angle_of(-1.0 * n) + rng.uniform(-60.0, 60.0) * kDeg);
      s.balls[0].state.velocity = creep();
      s.balls[0].state.angular_velocity = spin_driving_along(into, rng.uniform(0.01, 3.0), r, w_z());
      s.what = fmt("ball touching jaw %zu of %s (%.3g m inside), spun into it", j, table_label(s.table), inset);
    }
    add_random_balls(s, rng, rng.integer(0, 2));
    return;
  }
}

// 8. slow: ball speeds of 0.1 mm/s - 5 cm/s (the simulator's plastic-push
// regime is below 1 cm/s), alone, into a ball at a gap of 0 - 5 cm, into a
// rail, or a touching pair. Slow contacts are where bounces could shrink
// without end (inelastic collapse) and where tolerances matter most.
void make_slow(Shot& s, RandomStream& rng) {
  s = new_shot(rng.integer(0, 2));
  const double r = s.radius();
  const double speed = rng.log_uniform(1e-4, 0.05);
  const auto gap = [&rng]() { return rng.chance(0.25) ? 0.0 : rng.log_uniform(1e-9, 0.05); };
  const int variant = rng.integer(0, 3);
  for (int attempt = 0;; ++attempt) {
    if (attempt > 2000) throw Unplaceable{};
    s.balls.clear();
    double aim = rng.uniform(-kPi, kPi);
    if (variant == 0) {
      add_ball(s, random_spot(s, rng));
      s.what = fmt("one slow ball on %s", table_label(s.table));
    } else if (variant == 1 || variant == 3) {  // a ball at a gap (or touching), aimed at another
      const Vec2 a = random_spot(s, rng);
      const double phi = rng.uniform(-kPi, kPi), g = variant == 3 ? 0.0 : gap();
      const Vec2 b = a + (2.0 * r + g) * direction(phi);
      if (!ball_on_table(s.table, b, r)) continue;
      add_ball(s, a);
      add_ball(s, b);
      aim = phi + rng.uniform(-60.0, 60.0) * kDeg;
      s.what = fmt("slow ball %.3g m from ball 1 on %s, aim %.1f deg off the line of centres", g, table_label(s.table),
                   (aim - phi) / kDeg);
    } else {  // a ball at a gap from a rail, aimed into it
      const std::vector<std::size_t> rs = rails(s.table);
      const std::size_t c = rs[static_cast<std::size_t>(rng.integer(0, static_cast<int>(rs.size()) - 1))];
      const CushionSegment& seg = s.table.cushions[c];
      const double g = gap();
      const Vec2 p = on_rail(s, c, rng.uniform(0.03, 0.97), -g);
      if (!ball_on_table(s.table, p, r)) continue;
      add_ball(s, p);
      aim = angle_of(-1.0 * inward_normal(seg)) + rng.uniform(-85.0, 85.0) * kDeg;
      s.what = fmt("slow ball %.3g m from cushion %zu of %s, aimed into it", g, c, table_label(s.table));
    }
    add_random_balls(s, rng, rng.integer(0, 3));
    if (rng.chance(0.7))
      strike(s, 0, speed, aim, rng.uniform(0.0, 30.0) * kDeg, random_tip(rng));
    else
      nudge(s, 0, speed, aim, rng.chance(0.5), rng.chance(0.5) ? 0.0 : rng.uniform(-5.0, 5.0));
    return;
  }
}

// 9. masse: the cue raised 50-85 deg with a large side offset (0.3-0.5 R),
// the ball near a rail (0-10 cm, or frozen) or near another ball: a strongly
// curving, long-sliding path with spin about a horizontal axis, pressed into
// whatever it touches.
void make_masse(Shot& s, RandomStream& rng) {
  s = new_shot(rng.integer(0, 2));
  const double r = s.radius();
  for (int attempt = 0;; ++attempt) {
    if (attempt > 2000) throw Unplaceable{};
    s.balls.clear();
    double aim = rng.uniform(-kPi, kPi);
    if (rng.chance(0.5)) {
      const std::vector<std::size_t> rs = rails(s.table);
      const std::size_t c = rs[static_cast<std::size_t>(rng.integer(0, static_cast<int>(rs.size()) - 1))];
      const CushionSegment& seg = s.table.cushions[c];
      const double g = rng.chance(0.3) ? 0.0 : rng.uniform(0.0, 0.1);
      const Vec2 p = on_rail(s, c, rng.uniform(0.03, 0.97), -g);
      if (!ball_on_table(s.table, p, r)) continue;
      add_ball(s, p);
      if (rng.chance(0.6)) aim = angle_of(rng.sign() * rail_direction(seg)) + rng.uniform(-20.0, 20.0) * kDeg;
      s.what = fmt("masse %.3g m from cushion %zu of %s", g, c, table_label(s.table));
    } else {
      const Vec2 a = random_spot(s, rng);
      const double phi = rng.uniform(-kPi, kPi), g = rng.chance(0.3) ? 0.0 : rng.uniform(0.0, 0.1);
      const Vec2 b = a + (2.0 * r + g) * direction(phi);
      if (!ball_on_table(s.table, b, r)) continue;
      add_ball(s, a);
      add_ball(s, b);
      if (rng.chance(0.6)) aim = phi + rng.uniform(-90.0, 90.0) * kDeg;
      s.what = fmt("masse %.3g m from ball 1 on %s", g, table_label(s.table));
    }
    add_random_balls(s, rng, rng.integer(0, 3));
    strike(s, 0, rng.log_uniform(0.1, 4.0), aim, rng.uniform(50.0, 85.0) * kDeg, side_heavy_tip(rng, 0.3));
    return;
  }
}

struct ShotClass {
  const char* name;
  const char* summary;
  void (*make)(Shot&, RandomStream&);
};

constexpr std::array<ShotClass, 9> kClasses{{
    {"break", "9-ball, 8-ball and snooker breaks at 8-14 m/s", make_break},
    {"random", "2-16 balls anywhere, any strike", make_random},
    {"rail_frozen", "cue ball frozen to a rail, raised cue and side spin", make_rail_frozen},
    {"ball_frozen", "two balls frozen together, struck along the tangent or anywhere", make_ball_frozen},
    {"cluster", "frozen rows, triangles, chains, cradles, rows on a rail; struck or nudged", make_cluster},
    {"jaw", "balls touching jaws or in pocket mouths, slow and fast", make_jaw},
    {"roundoff", "balls at (or round-off inside) contact distance, spun into the contact", make_roundoff},
    {"slow", "0.1 mm/s - 5 cm/s shots into touching balls and rails", make_slow},
    {"masse", "cue raised 50-85 deg, large side offsets, near rails and balls", make_masse},
}};

// ------------------------------------------------------------------ the checks

enum Kind {
  kOverlap, kCushion, kJaw, kOffTable, kRestPlacement, kNan, kEnergy, kEvents, kError, kDeterminism, kCrash,
  kKinds
};
constexpr std::array<const char*, kKinds> kKindNames{"overlap", "cushion", "jaw", "off_table", "rest_placement", "nan",
                                                     "energy", "events", "error", "determinism", "crash"};
constexpr std::array<const char*, kKinds> kKindUnits{"m", "m", "m", "m", "m", "", "J", "events", "", "", ""};

struct Finding {
  double value = -1.0;  // < 0: not found
  std::string detail;
};

struct Findings {
  std::array<Finding, kKinds> kind;
  // Keeps the largest value of the kind; the detail is only formatted when it is kept.
  template <class Detail>
  void add(Kind k, double value, Detail&& detail) {
    if (value > kind[k].value) {
      kind[k].value = value;
      kind[k].detail = detail();
    }
  }
  bool any() const {  // any violation (notes do not count)
    for (std::size_t k = 0; k < kKinds; ++k)
      if (kind[k].value >= 0.0) return true;
    return false;
  }
};

// Per table: the contact distances, and the radius of each pocket's mouth
// circle (about the pocket's centre, holding the contact circles of the jaws
// nearest to it), inside which a ball may be beyond the nose rectangle.
struct Geometry {
  const Table& table;
  double radius;
  std::vector<double> cushion_contact, jaw_contact, mouth;

  Geometry(const Table& t, double r) : table(t), radius(r) {
    for (const CushionSegment& c : t.cushions) cushion_contact.push_back(cushion_contact_distance(c.contact_height, r));
    for (const JawArc& j : t.jaws) jaw_contact.push_back(jaw_contact_distance(j, r));
    for (const Pocket& q : t.pockets) mouth.push_back(q.radius);
    for (std::size_t j = 0; j < t.jaws.size(); ++j) {
      std::size_t best = SIZE_MAX;
      for (std::size_t q = 0; q < t.pockets.size(); ++q)
        if (best == SIZE_MAX || norm(t.jaws[j].centre - t.pockets[q].centre) < norm(t.jaws[j].centre - t.pockets[best].centre)) best = q;
      if (best == SIZE_MAX) continue;
      const double dist = norm(t.jaws[j].centre - t.pockets[best].centre);
      if (dist <= 0.3) mouth[best] = std::max(mouth[best], dist + jaw_contact[j]);
    }
  }
};

// How far a centre p is inside the contact distance of cushion c. In front of
// the nose line (or beside the segment's ends) the distance to the finite
// segment counts; a centre that has crossed the nose line (behind it, its foot
// on the segment) is the contact distance plus its distance behind the line
// deep, so a ball that passed through a cushion reads as deep as it is.
double cushion_depth(const Geometry& g, std::size_t c, Vec2 p) {
  const CushionSegment& s = g.table.cushions[c];
  const Vec2 d = s.end - s.start, rel = p - s.start;
  const double along = dot(rel, d) / dot(d, d);
  const double side = cross(d, rel);  // > 0: on the playing surface (left of start -> end)
  if (side < 0.0 && along >= 0.0 && along <= 1.0) return g.cushion_contact[c] - side / norm(d);
  return g.cushion_contact[c] - distance_to_segment(s, p);
}

bool finite(const BallState& s) { return is_finite(s.position) && is_finite(s.velocity) && is_finite(s.angular_velocity); }

bool in_a_mouth(const Geometry& g, Vec2 p) {
  for (std::size_t m = 0; m < g.table.pockets.size(); ++m)
    if (norm(p - g.table.pockets[m].centre) <= g.mouth[m]) return true;
  return false;
}

// A ball at rest at p that ball_on_table() refuses: a rest_placement
// violation (inside a cushion's or jaw's contact distance, over a pocket's
// hole, or off the table). A ball hanging in a pocket's jaws, beyond the nose
// rectangle, is a valid place to start the next shot from.
void check_rest(const Geometry& g, int id, Vec2 p, const char* when, Findings& f) {
  const Table& t = g.table;
  double depth = 0.0;
  std::string what = "refused by ball_on_table";
  for (std::size_t c = 0; c < t.cushions.size(); ++c) {
    const double d = cushion_depth(g, c, p);
    if (d > depth) depth = d, what = fmt("inside the contact distance of cushion %zu", c);
  }
  for (std::size_t j = 0; j < t.jaws.size(); ++j) {
    const double d = g.jaw_contact[j] - norm(p - t.jaws[j].centre);
    if (d > depth) depth = d, what = fmt("inside the contact distance of jaw %zu", j);
  }
  for (const Pocket& q : t.pockets) {
    const double d = q.radius - norm(p - q.centre);
    if (d >= depth && d >= 0.0) depth = d, what = "over the hole of pocket " + q.name + " but not pocketed";
  }
  const double outside = std::max({-p.x, p.x - t.length, -p.y, p.y - t.width, 0.0});
  // ball_on_table() allows kPlacementTolerance at cushions and jaws (not at pockets).
  if (depth <= kPlacementTolerance && what.rfind("over the hole", 0) != 0) depth = 0.0;
  if (depth <= 0.0 && outside > 0.0 && !in_a_mouth(g, p)) {
    depth = outside;
    what = "off the table";
  }
  f.add(kRestPlacement, depth, [&] {
    return fmt("ball %d at rest at (%.17g, %.17g) %s: %.3g m, %s", id, p.x, p.y, what.c_str(), depth, when);
  });
}

// Every invariant at every checked time of one simulated shot.
void check_result(const Shot& shot, const SimulationResult& r, Findings& f) {
  const Parameters& p = shot.settings.parameters;
  const Geometry g(shot.table, p.ball.radius);
  const Table& t = shot.table;
  const double r2 = 2.0 * p.ball.radius;
  const std::size_t n = r.balls.size();
  const auto id = [&r](std::size_t i) { return r.balls[i].id; };

  const int events = static_cast<int>(r.events.size());
  if (events >= kEventViolation) f.add(kEvents, events, [&] { return fmt("%d events, end at t = %.6g s", events, r.end_time); });

  // The checked times, in order.
  std::vector<double> times{0.0};
  for (const Event& e : r.events) {
    if (!std::isfinite(e.time)) {
      f.add(kNan, 1.0, [&] { return fmt("event %s of ball %d at a non-finite time", to_string(e.type), e.ball); });
      return;
    }
    if (e.time > times.back()) times.push_back(e.time);
  }
  if (!std::isfinite(r.end_time)) {
    f.add(kNan, 1.0, [] { return std::string("non-finite end time"); });
    return;
  }
  if (r.end_time > times.back()) times.push_back(r.end_time);
  std::vector<double> samples;
  samples.reserve(times.size() * (kInteriorPoints + 3));
  for (std::size_t k = 0; k + 1 < times.size(); ++k) {
    const double a = times[k], b = times[k + 1], near = std::min(kNearEvent, (b - a) * 1e-3);
    samples.push_back(a);
    if (a + near > a) samples.push_back(a + near);
    for (int j = 1; j <= kInteriorPoints; ++j) samples.push_back(a + (b - a) * j / (kInteriorPoints + 1));
    if (b - near < b && b - near > a) samples.push_back(b - near);
  }
  samples.push_back(times.back());

  std::vector<BallState> st(n);
  std::vector<char> active(n);
  std::vector<Vec2> rest_checked(n, Vec2{std::nan(""), 0.0});
  double previous_energy = std::numeric_limits<double>::infinity();
  double previous_time = 0.0;
  for (const double tau : samples) {
    double energy = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const BallTrajectory& b = r.balls[i];
      active[i] = !(b.pocketed && tau >= b.pocket_time);
      st[i] = r.state_at(i, tau, p);
      energy += kinetic_energy(st[i], p.ball);
    }
    if (std::isfinite(previous_energy) && energy > previous_energy * (1.0 + kEnergyRelative) + kEnergyAbsolute)
      f.add(kEnergy, energy - previous_energy, [&] {
        return fmt("kinetic energy %.9g J at t = %.9g s -> %.9g J at t = %.9g s", previous_energy, previous_time, energy, tau);
      });
    previous_energy = energy;
    previous_time = tau;
    for (std::size_t i = 0; i < n; ++i) {
      if (!active[i]) continue;
      const BallState& s = st[i];
      if (!finite(s)) {
        f.add(kNan, 1.0, [&] { return fmt("ball %d at t = %.9g s", id(i), tau); });
        continue;
      }
      const Vec2 q = s.position;
      for (std::size_t c = 0; c < t.cushions.size(); ++c) {
        const double depth = cushion_depth(g, c, q);
        if (depth > kTolerance)
          f.add(kCushion, depth, [&] { return fmt("ball %d %.4g m into cushion %zu at t = %.9g s", id(i), depth, c, tau); });
      }
      for (std::size_t j = 0; j < t.jaws.size(); ++j) {
        const double depth = g.jaw_contact[j] - norm(q - t.jaws[j].centre);
        if (depth > kTolerance)
          f.add(kJaw, depth, [&] { return fmt("ball %d %.4g m into jaw %zu at t = %.9g s", id(i), depth, j, tau); });
      }
      const double outside = std::max({-q.x, q.x - t.length, -q.y, q.y - t.width});
      if (outside > kTolerance) {
        bool in_mouth = false;
        if (outside <= kOffTableBox) in_mouth = in_a_mouth(g, q);
        if (!in_mouth)
          f.add(kOffTable, outside, [&] {
            return fmt("ball %d at (%.6f, %.6f), %.4g m off the table, at t = %.9g s", id(i), q.x, q.y, outside, tau);
          });
      }
      if (s.velocity.x == 0.0 && s.velocity.y == 0.0 && !(q == rest_checked[i])) {
        rest_checked[i] = q;
        if (!ball_on_table(t, q, p.ball.radius)) check_rest(g, id(i), q, fmt("from t = %.9g s", tau).c_str(), f);
      }
      for (std::size_t j = 0; j < i; ++j) {
        if (!active[j]) continue;
        const double depth = r2 - norm(q - st[j].position);
        if (depth > kTolerance)
          f.add(kOverlap, depth, [&] { return fmt("balls %d and %d overlap by %.4g m at t = %.9g s", id(j), id(i), depth, tau); });
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const BallTrajectory& b = r.balls[i];
    if (!finite(b.final_state)) f.add(kNan, 1.0, [&] { return fmt("final state of ball %d", id(i)); });
    if (!b.pocketed && finite(b.final_state) && !ball_on_table(t, b.final_state.position, p.ball.radius))
      check_rest(g, id(i), b.final_state.position, "at the end", f);
  }
}

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }
bool same_bits(const BallState& a, const BallState& b) {
  return same_bits(a.position.x, b.position.x) && same_bits(a.position.y, b.position.y) &&
         same_bits(a.velocity.x, b.velocity.x) && same_bits(a.velocity.y, b.velocity.y) &&
         same_bits(a.angular_velocity.x, b.angular_velocity.x) && same_bits(a.angular_velocity.y, b.angular_velocity.y) &&
         same_bits(a.angular_velocity.z, b.angular_velocity.z);
}

// Empty when the two runs agree in every bit; else what differs first.
std::string difference(const SimulationResult& a, const SimulationResult& b) {
  if (a.events.size() != b.events.size()) return fmt("%zu events vs %zu", a.events.size(), b.events.size());
  for (std::size_t k = 0; k < a.events.size(); ++k) {
    const Event &x = a.events[k], &y = b.events[k];
    if (!same_bits(x.time, y.time) || x.type != y.type || x.ball != y.ball || x.other != y.other)
      return fmt("event %zu: %s %d/%d at %.17g vs %s %d/%d at %.17g", k, to_string(x.type), x.ball, x.other, x.time,
                 to_string(y.type), y.ball, y.other, y.time);
  }
  if (!same_bits(a.end_time, b.end_time)) return "end time";
  if (a.balls.size() != b.balls.size()) return "ball count";
  for (std::size_t i = 0; i < a.balls.size(); ++i) {
    const BallTrajectory &x = a.balls[i], &y = b.balls[i];
    if (x.pocketed != y.pocketed || x.pocket != y.pocket || !same_bits(x.pocket_time, y.pocket_time))
      return fmt("ball %d pocketing", x.id);
    if (!same_bits(x.final_state, y.final_state)) return fmt("ball %d final state", x.id);
    if (x.segments.size() != y.segments.size()) return fmt("ball %d segment count", x.id);
    for (std::size_t k = 0; k < x.segments.size(); ++k)
      if (!same_bits(x.segments[k].start_time, y.segments[k].start_time) || !same_bits(x.segments[k].state, y.segments[k].state))
        return fmt("ball %d segment %zu", x.id, k);
  }
  return {};
}

// ------------------------------------------------------------------ one shot, start to end

struct Outcome {
  bool rejected = false;
  std::string rejection;
  int events = 0;
  Findings findings;
};

// Simulates and checks a shot; never throws. `twice`: also the determinism check.
Outcome run_shot(const Shot& shot, bool twice) {
  Outcome out;
  try {
    try {
      validate_simulation_input(shot.table, shot.balls, shot.settings);
    } catch (const InvalidArgument& e) {
      out.rejected = true;
      out.rejection = e.what();
      return out;
    }
    SimulationResult result;
    try {
      result = simulate(shot.table, shot.balls, shot.settings);
    } catch (const SimulationError& e) {
      out.findings.add(kError, 1.0, [&] { return std::string(e.what()); });
      return out;
    }
    out.events = static_cast<int>(result.events.size());
    check_result(shot, result, out.findings);
    if (twice) {
      const SimulationResult again = simulate(shot.table, shot.balls, shot.settings);
      const std::string diff = difference(result, again);
      if (!diff.empty()) out.findings.add(kDeterminism, 1.0, [&] { return diff; });
    }
  } catch (const std::exception& e) {
    out.findings.add(kCrash, 1.0, [&] { return std::string("exception: ") + e.what(); });
  } catch (...) {
    out.findings.add(kCrash, 1.0, [] { return std::string("unknown exception"); });
  }
  return out;
}

// Generates shot `seed` of a class. False (with the reason) when the library
// refused the strike or the generator could not place the balls.
bool generate(const ShotClass& c, std::uint64_t seed, Shot& shot, std::string& why) {
  try {
    RandomStream rng(splitmix64(seed));
    c.make(shot, rng);
    return true;
  } catch (const InvalidArgument& e) {
    why = std::string("strike refused: ") + e.what();
  } catch (const Unplaceable&) {
    why = "the generator could not place the balls";
  } catch (const std::exception& e) {
    why = std::string("exception while generating: ") + e.what();
  }
  return false;
}

// ------------------------------------------------------------------ results of a class

struct Worst {
  double value = 0.0;
  std::uint64_t seed = 0;
  std::string detail;
};

struct KindStats {
  long long shots = 0;       // shots with this violation
  std::vector<Worst> worst;  // largest values first; ties: smallest seed first
};

struct ClassStats {
  long long shots = 0, rejected = 0, failing = 0;
  long long events = 0;
  int most_events = -1;
  std::uint64_t most_events_seed = 0;
  std::string first_rejection;
  std::uint64_t first_rejection_seed = 0;
  std::array<KindStats, kKinds> kinds;

  static bool before(const Worst& a, const Worst& b) { return a.value > b.value || (a.value == b.value && a.seed < b.seed); }

  void keep(KindStats& k, Worst w, std::size_t top) {
    k.worst.insert(std::upper_bound(k.worst.begin(), k.worst.end(), w, before), std::move(w));
    if (k.worst.size() > top) k.worst.pop_back();
  }

  void add(const Outcome& o, std::uint64_t seed, std::size_t top) {
    ++shots;
    if (o.rejected) {
      if (rejected == 0 || seed < first_rejection_seed) {
        first_rejection = o.rejection;
        first_rejection_seed = seed;
      }
      ++rejected;
      return;
    }
    events += o.events;
    if (o.events > most_events || (o.events == most_events && seed < most_events_seed)) {
      most_events = o.events;
      most_events_seed = seed;
    }
    if (o.findings.any()) ++failing;
    for (int k = 0; k < kKinds; ++k) {
      const Finding& f = o.findings.kind[static_cast<std::size_t>(k)];
      if (f.value < 0.0) continue;
      ++kinds[static_cast<std::size_t>(k)].shots;
      keep(kinds[static_cast<std::size_t>(k)], {f.value, seed, f.detail}, top);
    }
  }

  void merge(const ClassStats& o, std::size_t top) {
    shots += o.shots;
    if (o.rejected > 0 && (rejected == 0 || o.first_rejection_seed < first_rejection_seed)) {
      first_rejection = o.first_rejection;
      first_rejection_seed = o.first_rejection_seed;
    }
    rejected += o.rejected;
    failing += o.failing;
    events += o.events;
    if (o.most_events > most_events || (o.most_events == most_events && o.most_events_seed < most_events_seed)) {
      most_events = o.most_events;
      most_events_seed = o.most_events_seed;
    }
    for (std::size_t k = 0; k < kKinds; ++k) {
      kinds[k].shots += o.kinds[k].shots;
      for (const Worst& w : o.kinds[k].worst) keep(kinds[k], w, top);
    }
  }
};

// ------------------------------------------------------------------ scenario JSON out

std::string vec_json(Vec2 v) { return "[" + num(v.x) + ", " + num(v.y) + "]"; }
std::string vec_json(Vec3 v) { return "[" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + "]"; }
// The shot as a scenario that `cueball simulate FILE` reads (scenario.hpp):
// the balls' states after the strike, every constant written out with 17
// digits, so the file reproduces the shot bit for bit.
std::string scenario_json(const Shot& s) {
  const Parameters& p = s.settings.parameters;
  const BallCollisionParameters& c = s.settings.ball_collision;
  const std::string label = table_label(s.table);
  std::string out = "{\n";
  out += " \"table\": " + (label == "custom table" ? table_to_json(s.table) : quoted(label)) + ",\n";
  out += " \"parameters\": {\"mass\": " + num(p.ball.mass) + ", \"radius\": " + num(p.ball.radius) +
         ", \"mu_s\": " + num(p.cloth.sliding_friction) + ", \"mu_r\": " + num(p.cloth.rolling_resistance) +
         ", \"mu_sp\": " + num(p.cloth.spin_friction) + ", \"g\": " + num(p.cloth.gravity) + "},\n";
  out += " \"cushion\": {\"model\": \"" + std::string(to_string(s.settings.cushion.model)) +
         "\", \"restitution\": " + num(s.settings.cushion.restitution) +
         ", \"friction\": " + num(s.settings.cushion.friction) + "},\n";
  out += " \"ball_collision\": {\"model\": \"" + std::string(to_string(s.settings.ball_collision_model)) +
         "\", \"restitution\": " + num(c.restitution) + ", \"friction\": " + num(c.friction) +
         (s.settings.ball_collision_model == BallCollisionModel::coulomb_impulse  // mathavan_2014's reader refuses them
              ? ", \"friction_excess\": " + num(c.friction_excess) + ", \"friction_decay\": " + num(c.friction_decay)
              : std::string()) +
         "},\n";
  out += " \"max_events\": " + std::to_string(s.settings.max_events) + ",\n";
  out += " \"balls\": [\n";
  for (std::size_t i = 0; i < s.balls.size(); ++i) {
    const SimulationBall& b = s.balls[i];
    out += "  {\"id\": " + std::to_string(b.id) + ", \"name\": " + quoted(b.name) +
           ", \"position\": " + vec_json(b.state.position) + ", \"velocity\": " + vec_json(b.state.velocity) +
           ", \"angular_velocity\": " + vec_json(b.state.angular_velocity) + "}" + (i + 1 < s.balls.size() ? ",\n" : "\n");
  }
  out += " ]\n}\n";
  return out;
}

// ------------------------------------------------------------------ report

void print_kinds(const ClassStats& st, const ShotClass& c) {
  std::printf("    %-15s %7s  %-12s %-20s %s\n", "violation", "shots", "worst", "seed", "where");
  for (std::size_t k = 0; k < kKinds; ++k) {
    const KindStats& ks = st.kinds[k];
    if (ks.shots == 0) {
      std::printf("    %-15s %7d  -\n", kKindNames[k], 0);
      continue;
    }
    for (std::size_t w = 0; w < ks.worst.size(); ++w) {
      const Worst& x = ks.worst[w];
      const std::string value = kKindUnits[k][0] ? fmt("%.4g %s", x.value, kKindUnits[k]) : std::string("yes");
      std::printf("    %-15s %7s  %-12s %-20llu %s\n", w == 0 ? kKindNames[k] : "", w == 0 ? std::to_string(ks.shots).c_str() : "",
                  value.c_str(), static_cast<unsigned long long>(x.seed), x.detail.substr(0, 300).c_str());
      Shot shot;
      std::string why;
      if (generate(c, x.seed, shot, why)) std::printf("    %-15s %7s  %-12s %-20s shot: %s\n", "", "", "", "", shot.what.c_str());
    }
  }
}

// ------------------------------------------------------------------ flags

struct Options {
  std::vector<const ShotClass*> classes;
  long long shots = 1000;
  std::uint64_t seed = 1;
  int threads = 1;
  std::size_t report_worst = 1;
  std::string dump_dir;
  std::vector<std::string> scenarios;
  long long games = 0;                // --games: random-agent games per discipline (game_stress.cpp)
  std::vector<GameKind> game_kinds;   // --game
};

std::string class_list() {
  std::string s = "all";
  for (const ShotClass& c : kClasses) s += std::string(", ") + c.name;
  return s + " (or a comma-separated list)";
}

void usage() {
  std::printf(
      "usage: cueball-stress [--class NAME] [--shots N] [--seed S] [--threads T] [--report-worst K] [--dump-worst DIR]\n"
      "                      [--cushion-model NAME] [--ball-collision-model NAME] [--cushion-exact-tolerance T]\n"
      "       cueball-stress --scenario FILE [--scenario FILE ...]\n"
      "       cueball-stress --games N [--game KIND] [--seed S] [--threads T]\n"
      "Random seeded shots of each class, simulated and checked for overlaps, cushion and jaw\n"
      "penetration, balls off the table, NaN, energy gain, runaway event counts, errors, crashes\n"
      "and determinism, at every event and between events. Shot k uses seed S + k.\n"
      "  --class NAME        %s (default all)\n"
      "  --shots N           shots per class, [1, 1000000000] (default 1000)\n"
      "  --seed S            seed of the first shot, [0, 1e18] (default 1)\n"
      "  --threads T         worker threads, [1, 256] (default 1); results do not depend on it\n"
      "  --report-worst K    the K worst shots of each violation kind, [1, 100] (default 1)\n"
      "  --dump-worst DIR    write each class's worst shot of each kind as DIR/CLASS-KIND.json (cueball simulate FILE)\n"
      "  --cushion-model M   the cushion model of every generated shot, with its own constants: %s\n"
      "                      (default mathavan_2010)\n"
      "  --cushion-exact-tolerance T  mathavan_2010's exact solver: local error per step, [1e-11, 1e-7] (default 1e-8)\n"
      "  --ball-collision-model M  the ball-ball model of every generated shot, with its own constants: %s\n"
      "                      (default coulomb_impulse)\n"
      "  --scenario FILE     check one scenario file (cueball's scenario JSON) instead; its event limit is raised to %d\n"
      "  --games N           play N whole games between random agents instead, of each discipline, [1, 1e9];\n"
      "                      game k uses seed S + k; every step checked for the rules' invariants\n"
      "  --game KIND         the disciplines of --games: all (default) or a comma-separated list of %s\n"
      "Exit status: 0 no violation, 1 violations, 2 bad flags.\n",
      class_list().c_str(), cushion_model_names("").c_str(), ball_collision_model_names("").c_str(), kMaxEvents,
      game_kind_names().c_str());
}

Options parse(int argc, char** argv) {
  Options o;
  double exact_tolerance = CushionSettings{}.exact_tolerance;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--help" || flag == "-h") {
      usage();
      std::exit(0);
    }
    static const char* const known[] = {"--class",      "--shots",      "--seed",          "--threads",
                                        "--report-worst", "--dump-worst", "--cushion-model", "--ball-collision-model",
                                        "--cushion-exact-tolerance", "--scenario", "--games", "--game"};
    if (std::find_if(std::begin(known), std::end(known), [&](const char* k) { return flag == k; }) == std::end(known))
      kFlags.bad("flag", flag,
               "--class, --shots, --seed, --threads, --report-worst, --dump-worst, --cushion-model, "
               "--ball-collision-model, --cushion-exact-tolerance, --scenario, --games, --game, --help");
    if (i + 1 >= argc) kFlags.bad(flag, "", "a value after the flag");
    const std::string value = argv[++i];
    if (flag == "--class") {
      o.classes.clear();
      std::stringstream list(value);
      std::string name;
      while (std::getline(list, name, ',')) {
        if (name == "all") {
          for (const ShotClass& c : kClasses) o.classes.push_back(&c);
          continue;
        }
        const auto it = std::find_if(kClasses.begin(), kClasses.end(), [&](const ShotClass& c) { return name == c.name; });
        if (it == kClasses.end()) kFlags.bad(flag, value, class_list());
        o.classes.push_back(&*it);
      }
      if (o.classes.empty()) kFlags.bad(flag, value, class_list());
    } else if (flag == "--games") {
      o.games = kFlags.integer(flag, value, 1, 1000000000);
    } else if (flag == "--game") {
      std::stringstream list(value);
      std::string name;
      while (std::getline(list, name, ',')) {
        if (name == "all") {
          o.game_kinds.insert(o.game_kinds.end(), kGameKinds.begin(), kGameKinds.end());
          continue;
        }
        const std::optional<GameKind> kind = game_kind_from_string(name);
        if (!kind) kFlags.bad(flag, value, "all or a comma-separated list of " + game_kind_names());
        o.game_kinds.push_back(*kind);
      }
      if (o.game_kinds.empty()) kFlags.bad(flag, value, "all or a comma-separated list of " + game_kind_names());
    } else if (flag == "--shots") {
      o.shots = kFlags.integer(flag, value, 1, 1000000000);
    } else if (flag == "--seed") {
      o.seed = static_cast<std::uint64_t>(kFlags.integer(flag, value, 0, 1000000000000000000LL));
    } else if (flag == "--threads") {
      o.threads = static_cast<int>(kFlags.integer(flag, value, 1, 256));
    } else if (flag == "--report-worst") {
      o.report_worst = static_cast<std::size_t>(kFlags.integer(flag, value, 1, 100));
    } else if (flag == "--dump-worst") {
      if (value.empty()) kFlags.bad(flag, value, "a directory (created when missing)");
      o.dump_dir = value;
    } else if (flag == "--cushion-model") {
      const std::optional<CushionModel> model = cushion_model_from_string(value);
      if (!model) kFlags.bad(flag, value, cushion_model_names(""));
      g_cushion = default_cushion_settings(*model);
    } else if (flag == "--cushion-exact-tolerance") {
      exact_tolerance = kFlags.number(flag, value, kMinExactTolerance, kMaxExactTolerance, "a number in [1e-11, 1e-7]");
    } else if (flag == "--ball-collision-model") {
      const std::optional<BallCollisionModel> model = ball_collision_model_from_string(value);
      if (!model) kFlags.bad(flag, value, ball_collision_model_names(""));
      g_ball_collision_model = *model;
    } else {
      o.scenarios.push_back(value);
    }
  }
  if (o.classes.empty())
    for (const ShotClass& c : kClasses) o.classes.push_back(&c);
  g_cushion.exact_tolerance = exact_tolerance;
  return o;
}

// ------------------------------------------------------------------ the two modes

int check_scenarios(const Options& o) {
  bool violated = false;
  for (const std::string& path : o.scenarios) {
    std::ifstream in(path);
    if (!in) kFlags.bad("--scenario", path, "a readable scenario JSON file");
    std::stringstream text;
    text << in.rdbuf();
    Shot shot;
    try {
      const Scenario s = scenario_from_json(text.str());
      shot.table = s.table;
      shot.settings = s.settings;
      shot.settings.max_events = std::max(shot.settings.max_events, kMaxEvents);
      shot.balls = balls_after_strike(s);
    } catch (const std::exception& e) {
      std::printf("%s: rejected by the library: %s\n", path.c_str(), e.what());
      violated = true;
      continue;
    }
    const auto start = std::chrono::steady_clock::now();
    const Outcome out = run_shot(shot, true);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (out.rejected) {
      std::printf("%s: rejected: %s\n", path.c_str(), out.rejection.c_str());
      violated = true;
      continue;
    }
    std::printf("%s: %d events (%.3f s), %s\n", path.c_str(), out.events, seconds,
                out.findings.any() ? "VIOLATIONS" : "no violation");
    for (std::size_t k = 0; k < kKinds; ++k) {
      const Finding& f = out.findings.kind[k];
      if (f.value < 0.0) continue;
      violated = true;
      const std::string value = kKindUnits[k][0] ? fmt("%.4g %s", f.value, kKindUnits[k]) : std::string("yes");
      std::printf("    %-15s %-12s %s\n", kKindNames[k], value.c_str(), f.detail.substr(0, 400).c_str());
    }
  }
  return violated ? 1 : 0;
}

int run_classes(const Options& o) {
  std::printf("cueball-stress: %lld shots per class, seeds %llu..%llu, %d thread%s; tolerance %.0e m, energy %.0e relative + %.0e J, "
              "%d points inside each interval between events\n",
              o.shots, static_cast<unsigned long long>(o.seed), static_cast<unsigned long long>(o.seed + static_cast<std::uint64_t>(o.shots) - 1),
              o.threads, o.threads == 1 ? "" : "s", kTolerance, kEnergyRelative, kEnergyAbsolute, kInteriorPoints);
  bool violated = false;
  long long total_shots = 0, total_failing = 0, total_rejected = 0;
  const auto run_start = std::chrono::steady_clock::now();
  for (const ShotClass* c : o.classes) {
    std::atomic<long long> next{0};
    std::vector<ClassStats> per_thread(static_cast<std::size_t>(o.threads));
    const auto start = std::chrono::steady_clock::now();
    const auto work = [&](ClassStats& st) {
      for (long long k = next++; k < o.shots; k = next++) {
        const std::uint64_t seed = o.seed + static_cast<std::uint64_t>(k);
        Shot shot;
        std::string why;
        Outcome out;
        if (!generate(*c, seed, shot, why)) {
          out.rejected = true;
          out.rejection = why;
        } else {
          out = run_shot(shot, k % 10 == 0);
        }
        st.add(out, seed, o.report_worst);
      }
    };
    std::vector<std::thread> workers;
    for (int t = 1; t < o.threads; ++t) workers.emplace_back(work, std::ref(per_thread[static_cast<std::size_t>(t)]));
    work(per_thread[0]);
    for (std::thread& w : workers) w.join();
    ClassStats st;
    for (const ClassStats& p : per_thread) st.merge(p, o.report_worst);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    const long long simulated = st.shots - st.rejected;
    std::printf("\nclass %s: %s\n", c->name, c->summary);
    std::printf("  %lld shots, %lld rejected, %lld with violations; %.2f s (%.3f ms/shot); events/shot mean %.1f, most %d (seed %llu)\n",
                st.shots, st.rejected, st.failing, seconds, 1e3 * seconds / static_cast<double>(st.shots),
                simulated > 0 ? static_cast<double>(st.events) / static_cast<double>(simulated) : 0.0, st.most_events,
                static_cast<unsigned long long>(st.most_events_seed));
    if (st.rejected > 0)
      std::printf("  first rejection (seed %llu): %s\n", static_cast<unsigned long long>(st.first_rejection_seed),
                  st.first_rejection.c_str());
    print_kinds(st, *c);
    if (st.failing > 0) {
      violated = true;
      std::uint64_t first = 0;
      for (std::size_t k = 0; k < kKinds; ++k)
        if (st.kinds[k].shots > 0) {
          first = st.kinds[k].worst.front().seed;
          break;
        }
      std::printf("  reproduce one: cueball-stress --class %s --seed %llu --shots 1\n", c->name, static_cast<unsigned long long>(first));
    }
    if (!o.dump_dir.empty()) {
      std::filesystem::create_directories(o.dump_dir);
      for (std::size_t k = 0; k < kKinds; ++k) {
        if (st.kinds[k].worst.empty()) continue;
        const Worst& w = st.kinds[k].worst.front();
        Shot shot;
        std::string why;
        if (!generate(*c, w.seed, shot, why)) continue;
        const std::string file = (std::filesystem::path(o.dump_dir) / (std::string(c->name) + "-" + kKindNames[k] + ".json")).string();
        std::ofstream(file) << scenario_json(shot);
        std::printf("  worst %s shot (seed %llu: %s) written to %s\n", kKindNames[k], static_cast<unsigned long long>(w.seed),
                    shot.what.c_str(), file.c_str());
      }
    }
    total_shots += st.shots;
    total_failing += st.failing;
    total_rejected += st.rejected;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - run_start).count();
  std::printf("\ntotal: %lld shots, %lld rejected, %lld with violations, %.2f s\n", total_shots, total_rejected, total_failing, seconds);
  return violated ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  try {
    if (o.games > 0) {
      const std::vector<GameKind> kinds =
          o.game_kinds.empty() ? std::vector<GameKind>(kGameKinds.begin(), kGameKinds.end()) : o.game_kinds;
      return run_game_stress(kinds, o.games, o.seed, o.threads);
    }
    return o.scenarios.empty() ? run_classes(o) : check_scenarios(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cueball-stress: error: %s\n", e.what());
    return 1;
  }
}
