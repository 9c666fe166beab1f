// cueball-planner-benchmark: how good are plan_shot's choices, and at what
// cost? (issue 13, item 4). Method and measured results: docs/planner-benchmark.md.
//
// Suite "single": layouts of the cue ball (id 0), the target (id 1) and 0-5
// other balls (ids 2..6) placed uniformly at random on the 9-ft pool table
// (the default pool preset), layout k from seed S + k (splitmix64 into
// std::mt19937_64, uniforms from the 53 high bits, as stress/stress.cpp does).
// Three methods choose a strike on each layout:
//   planner     plan_shot (shot_planner.hpp) with its defaults (direct and
//               bank, tournament noise, centre ball then draw/follow) and
//               --planner-simulations engine runs, seeded with the layout's seed;
//               with --fallback-kinds, where none of its kinds is feasible,
//               a plan of those (the agents' fallback) with that budget again;
//   ghost_ball  the ghost-ball agent's aim, ghost_ball_shot() (agents/agent.hpp;
//               D. G. Alciatore, "The Illustrated Principles of Pool and
//               Billiards", 2004): the cue ball aimed at the ghost ball
//               G = O - 2R u for the pocket whose straight paths are clear
//               of the other balls and whose small-angle aim tolerance
//               cos(cut) / (|CG| |OP|) is largest (cut <= 80 deg, as the
//               planner), centre ball, cue speed kGhostBallSpeed, the lowest
//               clear elevation (lowest_clear_elevation_deg); no simulation;
//   exhaustive  a dense grid (aims every kGridAimStepDeg over every direction
//               in which the cue ball meets the target first in a straight
//               line, x kGridSpeeds x kGridSpins, each at the lowest clear
//               elevation), in three stages: (1) every cell simulated once
//               noise-free; (2) in each (speed, spin) slice the aim whose
//               Gaussian-smoothed pot indicator (sigma = the aim noise) is
//               highest, and the kScreenSlices best slices; (3) each of those
//               screened with kScreenShots noisy shots on common draws; the
//               best screened cell is the choice.
// The success probability of each choice is then measured by --repeats
// independent noisy repeats (tournament_noise(), simulate_many) on a seed
// stream different from the planner's and the screens' own. A shot succeeds
// when the cue ball's first contact is the target, the target drops (in any
// pocket: 9-ball is not call-pocket) and the cue ball is not pocketed; a
// miscue or an event-limit failure is a miss. A method without a shot scores 0.
//
// Suite "runout": 9-ball racks (rack_nine_ball with random gaps), broken by
// the engine (a seeded break: cue ball behind the head string, aimed at the 1
// with a small jitter, 6.5-8.5 m/s), then cue ball in hand placed by the
// ghost-ball agent's rule (ghost_ball_in_hand_spot: a straight-in on the 1,
// kGhostBallInHandBack behind the ghost ball of the easiest clear pocket).
// That table is a 9-ball GameState in play (games/game.hpp; with --in-hand
// planner, the default, the cue ball is in hand anywhere), and the agent
// (--agent: by default strongest_agent(), agents/agent.hpp: the safety
// planner with position play and kicks; or the planner) plays it through
// play() with tournament noise until the 9 drops (a run-out), a shot is a
// foul (wrong first contact, scratch, miscue: the Ruling's foul), pots
// nothing, the agent finds no feasible shot of its kinds (--kinds, then
// --fallback-kinds) or it chooses a safety (the safety planner, when no pot
// is likely enough). A 9 potted on the
// break is spotted. With --break recommended the rack is the game's own
// (new_game: the default gaps) broken by recommended_break with tournament
// noise through play(); only a legal break that makes a ball is run out, from
// where the break left the cue ball (a 9 on the break is a run-out), and the
// share of such breaks and the run-out rate after them are reported.
//
// Everything is seeded: the same flags give the same choices and
// probabilities whatever --threads (the timings of course vary).
// Uses only the public API.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <vector>


#include "tool_support.hpp"
#include "cueball/agents/agent.hpp"
#include "cueball/games/break_shot.hpp"
#include "cueball/games/game.hpp"
#include "cueball/io/scenario_json.hpp"
#include "cueball/simulation/batch.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/core/random.hpp"
#include "cueball/planning/ball_in_hand.hpp"
#include "cueball/planning/position_play.hpp"
#include "cueball/table/placement.hpp"
#include "cueball/table/rack.hpp"
#include "cueball/simulation/scenario.hpp"
#include "cueball/planning/shot_planner.hpp"
#include "cueball/table/table.hpp"
#include "cueball/core/vec.hpp"

namespace {

using namespace cueball;
using cueball::tools::fmt;
using cueball::tools::thread_cpu_seconds;
using cueball::tools::quoted;
constexpr tools::Flags kFlags{"cueball-planner-benchmark"};

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

// The exhaustive grid.
constexpr double kGridAimStepDeg = 0.05;  // 0.4 sigma of the tournament aim noise
constexpr double kGridSpeeds[] = {1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.5};  // cue speed, m/s
struct Spin {
  double side, height;  // ball radii
};
constexpr Spin kGridSpins[] = {{0.0, 0.0},   {0.0, -0.35}, {0.0, 0.35},  {-0.2, 0.0}, {0.2, 0.0},
                               {-0.2, -0.3}, {0.2, -0.3},  {-0.2, 0.3}, {0.2, 0.3}};
constexpr int kScreenSlices = 16;
constexpr int kScreenShots = 200;
// Seed streams: layout seed x -> planner seed x, screen seed mix(x, 1), measurement seed mix(x, 2).
constexpr std::uint64_t kScreenStream = 1, kMeasureStream = 2, kBreakStream = 3;

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

double angle_deg(Vec2 v) { return std::atan2(v.y, v.x) / kDeg; }

// ------------------------------------------------------------------ table and balls

struct Setup {
  Scenario base;  // pool_9ft, pool preset, tournament noise, cue ball 0, no balls
  double radius = 0.0;
};

Setup make_setup() {
  Setup s;
  s.base = default_scenario();
  s.base.balls.clear();
  s.base.cue = ShotStrike{};
  s.base.cue->ball = 0;
  s.base.noise = tournament_noise();
  s.radius = s.base.settings.parameters.ball.radius;
  return s;
}

std::vector<Vec2> positions(const std::vector<SimulationBall>& balls) {
  std::vector<Vec2> out;
  for (const SimulationBall& b : balls) out.push_back(b.state.position);
  return out;
}

bool placeable(const Setup& st, const std::vector<SimulationBall>& balls, Vec2 p) {
  return is_free_spot(st.base.table, positions(balls), p, st.radius);
}

void add_ball(std::vector<SimulationBall>& balls, int id, Vec2 p) {
  SimulationBall b;
  b.id = id;
  b.name = id == 0 ? "cue" : std::to_string(id);
  b.state.position = p;
  balls.push_back(b);
}

Vec2 random_spot(const Setup& st, const std::vector<SimulationBall>& balls, RandomStream& rng) {
  const std::optional<Vec2> p = random_free_spot(st.base.table, positions(balls), st.radius, rng, 100000);
  if (!p) throw std::runtime_error("could not place a ball");
  return *p;
}

// Single-pot layout k: cue ball, target, then 0-5 others, uniform on the bed.
Scenario single_layout(const Setup& st, std::uint64_t seed, int& others) {
  RandomStream rng(splitmix64(seed));
  others = rng.integer(0, 5);
  Scenario s = st.base;
  for (int id = 0; id < 2 + others; ++id) add_ball(s.balls, id, random_spot(st, s.balls, rng));
  return s;
}

// The lowest clear elevation (lowest_clear_elevation_deg, the ghost-ball agent's), or NaN.
double clear_elevation(const Scenario& s, const ShotAction& a) {
  return lowest_clear_elevation_deg(s, 0, a).value_or(std::numeric_limits<double>::quiet_NaN());
}

// ------------------------------------------------------------------ measuring

struct Hits {
  int hits = 0;
  int shots = 0;
};

bool success(const ManyResult& m, std::size_t k, std::size_t cue, std::size_t target, int target_id) {
  const auto n = static_cast<std::size_t>(m.balls);
  return !m.miscue[k] && !m.failure[k] && m.first_contact[k] == target_id && m.pocketed[k * n + target] &&
         !m.pocketed[k * n + cue];
}

// Successes of `shots` noisy copies of `a` drawn from (seed, 0 ..).
Hits noisy_hits(const Scenario& s, const ShotAction& a, int shots, std::uint64_t seed, int target_id) {
  const std::vector<ShotAction> actions(static_cast<std::size_t>(shots), a);
  ManyOptions o;
  o.seed = seed;
  o.noise = true;
  const ManyResult m = simulate_many(s, actions, {}, o);
  Hits h;
  h.shots = shots;
  const std::size_t cue = index_of(s.balls, 0), target = index_of(s.balls, target_id);
  for (std::size_t k = 0; k < static_cast<std::size_t>(shots); ++k) h.hits += success(m, k, cue, target, target_id) ? 1 : 0;
  return h;
}

// ------------------------------------------------------------------ the methods

struct Choice {
  bool found = false;
  ShotAction action;
  int simulations = 0;
  double seconds = 0.0;      // wall clock
  double cpu_seconds = 0.0;  // the thread's CPU time
  std::string what;          // kind and pocket, for the per-layout record
  double success_probability = -1.0;       // the planner's own estimate; -1: no shot
  double next_success_probability = -1.0;  // position play: the leave's next-shot estimate; -1: none
};

// The single-pot suite's planner: plan_shot with its defaults and the budget;
// where none of its kinds is feasible, a plan of `fallback` (when given: the
// agents' fallback, --fallback-kinds) with the same budget again.
Choice single_planner_choice(const Scenario& s, int target, std::uint64_t seed, int simulations,
                             const std::vector<ShotKind>& fallback) {
  Choice c;
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = thread_cpu_seconds();
  PlanRequest q;
  q.target = target;
  q.seed = seed;
  q.simulations = simulations;
  try {
    std::optional<ShotPlanResult> first;
    try {
      first = plan_shot(s, q);
    } catch (const NoFeasibleShot&) {
      if (fallback.empty()) throw;
      q.kinds = fallback;
    }
    const ShotPlanResult r = first ? *first : plan_shot(s, q);
    c.found = true;
    c.action = r.shot.strike;
    c.simulations = r.simulations + (first ? 0 : simulations);  // a fallback plan: both budgets
    c.success_probability = r.shot.success_probability;
    c.what = fmt("%s %s%s%s (window %.3f, screen %.3f)", to_string(r.shot.kind), r.shot.pocket_name.c_str(),
                 r.shot.cushion.empty() ? "" : " off ", r.shot.cushion.c_str(), r.shot.window_probability,
                 r.shot.success_probability);
  } catch (const NoFeasibleShot& e) {
    // The API does not report them: the budget (of both plans with a fallback) is the upper bound.
    c.simulations = fallback.empty() ? simulations : 2 * simulations;
    c.what = std::string(e.what()).substr(0, 2000);
  }
  c.seconds = seconds_since(start);
  c.cpu_seconds = thread_cpu_seconds() - cpu_start;
  return c;
}

// The ghost-ball agent's aim (ghost_ball_shot, agents/agent.hpp).
Choice ghost_choice(const Scenario& s, int target) {
  Choice c;
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = thread_cpu_seconds();
  const std::optional<GhostBallShot> g = ghost_ball_shot(s, 0, {target}, kGhostBallSpeed);
  c.found = g.has_value();
  if (g) c.action = g->strike;
  c.what = g ? "ghost " + s.table.pockets[static_cast<std::size_t>(g->pocket)].name : "no clear pocket";
  c.seconds = seconds_since(start);
  c.cpu_seconds = thread_cpu_seconds() - cpu_start;
  return c;
}

struct ExhaustiveStats {
  int cells = 0;      // grid cells
  int simulated = 0;  // cells the cue clears (simulated noise-free)
  int potting = 0;    // of those, cells that pot noise-free
};

Choice exhaustive_choice(const Setup& st, const Scenario& s, int target_id, std::uint64_t screen_seed, ExhaustiveStats& stats) {
  Choice c;
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = thread_cpu_seconds();
  const double R = st.radius;
  const Vec2 C = s.balls[index_of(s.balls, 0)].state.position, O = s.balls[index_of(s.balls, target_id)].state.position;
  const double d = norm(O - C);
  const double half = std::asin(std::min(1.0, 2.0 * R / d)) / kDeg;
  const int J = static_cast<int>(std::floor(half / kGridAimStepDeg));
  const int aims = 2 * J + 1;
  constexpr int kSpeeds = static_cast<int>(std::size(kGridSpeeds));
  constexpr int kSpins = static_cast<int>(std::size(kGridSpins));
  const double centre = angle_deg(O - C);
  // Stage 1: every cell the cue clears, noise-free. Cell (spin, speed, aim).
  std::vector<ShotAction> actions;
  std::vector<int> cell_of;  // action -> cell
  stats.cells = aims * kSpeeds * kSpins;
  for (int k = 0; k < kSpins; ++k)
    for (int i = 0; i < aims; ++i) {
      ShotAction a;
      a.aim_deg = centre + (i - J) * kGridAimStepDeg;
      a.side = kGridSpins[k].side;
      a.height = kGridSpins[k].height;
      a.speed = kGridSpeeds[0];
      a.elevation_deg = clear_elevation(s, a);
      if (std::isnan(a.elevation_deg)) continue;
      for (int v = 0; v < kSpeeds; ++v) {
        a.speed = kGridSpeeds[v];
        actions.push_back(a);
        cell_of.push_back((k * kSpeeds + v) * aims + i);
      }
    }
  std::vector<char> pots(static_cast<std::size_t>(stats.cells), 0);
  std::vector<ShotAction> cell_action(static_cast<std::size_t>(stats.cells));
  stats.simulated = static_cast<int>(actions.size());
  if (!actions.empty()) {
    const ManyResult m = simulate_many(s, actions, {}, ManyOptions{});
    const std::size_t cue = index_of(s.balls, 0), target = index_of(s.balls, target_id);
    for (std::size_t k = 0; k < actions.size(); ++k) {
      const auto cell = static_cast<std::size_t>(cell_of[k]);
      cell_action[cell] = actions[k];
      pots[cell] = success(m, k, cue, target, target_id) ? 1 : 0;
      stats.potting += pots[cell];
    }
  }
  c.simulations = stats.simulated;
  // Stage 2: per (spin, speed) slice, the aim with the highest pot indicator
  // smoothed by a Gaussian of the aim noise's sigma; the best slices.
  const double sigma_cells = s.noise.aim / kDeg / kGridAimStepDeg;
  const int reach = static_cast<int>(std::ceil(3.0 * sigma_cells));
  std::vector<double> w(static_cast<std::size_t>(2 * reach + 1));
  double wsum = 0.0;
  for (int j = -reach; j <= reach; ++j) wsum += (w[static_cast<std::size_t>(j + reach)] = std::exp(-0.5 * j * j / (sigma_cells * sigma_cells)));
  struct Slice {
    double score;
    int cell;
  };
  std::vector<Slice> slices;
  for (int sl = 0; sl < kSpins * kSpeeds; ++sl) {
    Slice best{0.0, -1};
    for (int i = 0; i < aims; ++i) {
      if (!pots[static_cast<std::size_t>(sl * aims + i)]) continue;
      double sum = 0.0;
      for (int j = -reach; j <= reach; ++j)
        if (i + j >= 0 && i + j < aims) sum += w[static_cast<std::size_t>(j + reach)] * pots[static_cast<std::size_t>(sl * aims + i + j)];
      if (sum / wsum > best.score) best = {sum / wsum, sl * aims + i};
    }
    if (best.cell >= 0) slices.push_back(best);
  }
  std::stable_sort(slices.begin(), slices.end(), [](const Slice& a, const Slice& b) { return a.score > b.score; });
  if (slices.size() > static_cast<std::size_t>(kScreenSlices)) slices.resize(kScreenSlices);
  // Stage 3: the noisy screen on common draws.
  int best_hits = -1;
  for (const Slice& sl : slices) {
    const ShotAction& a = cell_action[static_cast<std::size_t>(sl.cell)];
    const Hits h = noisy_hits(s, a, kScreenShots, screen_seed, target_id);
    c.simulations += kScreenShots;
    if (h.hits > best_hits) {
      best_hits = h.hits;
      c.found = true;
      c.action = a;
    }
  }
  c.what = c.found ? fmt("grid: speed %.2f side %.2f height %.2f", c.action.speed, c.action.side, c.action.height) : "no potting cell";
  c.seconds = seconds_since(start);
  c.cpu_seconds = thread_cpu_seconds() - cpu_start;
  return c;
}

// ------------------------------------------------------------------ single pots

struct MethodResult {
  double p = 0.0;  // measured success probability (0 without a shot)
  int simulations = 0;
  double seconds = 0.0;
  double cpu_seconds = 0.0;
  bool found = false;
  std::string what;
  ShotAction action;
};

struct SingleRecord {
  std::uint64_t seed = 0;
  int others = 0;
  MethodResult m[3];  // planner, ghost_ball, exhaustive
  ExhaustiveStats grid;
};

const char* const kMethodNames[3] = {"planner", "ghost_ball", "exhaustive"};

MethodResult measured(const Scenario& s, const Choice& c, int repeats, std::uint64_t seed) {
  MethodResult r;
  r.found = c.found;
  r.simulations = c.simulations;
  r.seconds = c.seconds;
  r.cpu_seconds = c.cpu_seconds;
  r.what = c.what;
  r.action = c.action;
  if (c.found) {
    const Hits h = noisy_hits(s, c.action, repeats, seed, 1);
    r.p = static_cast<double>(h.hits) / h.shots;
  }
  return r;
}

SingleRecord run_single(const Setup& st, std::uint64_t seed, int repeats, int planner_simulations,
                        const std::vector<ShotKind>& fallback) {
  SingleRecord rec;
  rec.seed = seed;
  const Scenario s = single_layout(st, seed, rec.others);
  const std::uint64_t measure = stream_seed(seed, kMeasureStream);
  rec.m[0] = measured(s, single_planner_choice(s, 1, seed, planner_simulations, fallback), repeats, measure);
  rec.m[1] = measured(s, ghost_choice(s, 1), repeats, measure);
  rec.m[2] = measured(s, exhaustive_choice(st, s, 1, stream_seed(seed, kScreenStream), rec.grid), repeats, measure);
  return rec;
}

// ------------------------------------------------------------------ run-outs

enum class Stop { run_out, miss, scratch, wrong_first_contact, no_feasible_shot, miscue, failure, rejected, dry_break, safety };
const char* const kStopNames[] = {"run_out", "miss", "scratch", "wrong_first_contact", "no_feasible_shot", "miscue", "failure", "rejected_layout",
                                  "dry_break", "safety"};
constexpr int kStops = 10;
// The run-outs' goals: issue 27's for the strongest agent (9-ball from ball
// in hand at tournament noise), issue 13's for the planner agents.
constexpr double kStrongestRunOutGoal = 0.60;
constexpr double kPlannerRunOutGoal = 0.40;

struct RackRecord {
  std::uint64_t seed = 0;
  int on_break = 0;      // object balls potted on the break (a potted 9 spotted, not counted)
  bool made_break = false;  // --break recommended: the break was legal and made a ball
  int potted = 0;        // object balls potted by the planner's run
  int shots = 0;         // planned shots played
  Stop stop = Stop::miss;
  std::vector<double> decision_seconds, decision_cpu_seconds;
  long long simulations = 0;
  std::string detail;
  // Per shot played: the planner's estimate and (position play) its leave's next-shot estimate.
  std::vector<double> planned, planned_next;
};

Scenario with_balls_at(const Scenario& s, const ManyResult& m, std::size_t shot, std::vector<int>& potted_ids) {
  const auto n = static_cast<std::size_t>(m.balls);
  std::vector<BallAfterShot> after;
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t e = shot * n + j;
    if (m.pocketed[e]) potted_ids.push_back(s.balls[j].id);
    after.push_back({s.balls[j].id, {m.final_position[2 * e], m.final_position[2 * e + 1]}, m.pocketed[e] != 0, m.pocket[e]});
  }
  Scenario out = table_after(s, after);
  out.cue = s.cue;  // the break's scenario keeps its strike for the caller to replace
  return out;
}

// The rack after the engine's break, the cue ball in hand by the rule.
Scenario broken_rack(const Setup& st, std::uint64_t seed, int& on_break) {
  RandomStream rng(splitmix64(stream_seed(seed, kBreakStream)));
  RackOptions ro;
  ro.gap_sigma = rng.uniform(0.0, 5e-4);
  ro.seed = rng.bits() & 0x7fffffffULL;
  Scenario s = st.base;
  for (const PlacedBall& b : rack_nine_ball(s.table, ro)) add_ball(s.balls, b.id, b.position);
  SimulationBall& cue = s.balls[index_of(s.balls, 0)];
  cue.state.position.y += rng.uniform(-0.25, 0.25);
  const Vec2 one = s.balls[index_of(s.balls, 1)].state.position;
  ShotAction brk;
  brk.speed = rng.uniform(6.5, 8.5);
  brk.aim_deg = angle_deg(one - cue.state.position) + rng.uniform(-0.5, 0.5);
  brk.elevation_deg = 2.0;
  brk.height = rng.uniform(-0.1, 0.1);
  const ManyResult m = simulate_many(s, std::vector<ShotAction>{brk}, {}, ManyOptions{});
  if (m.failure[0]) throw std::runtime_error("break failed");
  std::vector<int> potted;
  Scenario after = with_balls_at(s, m, 0, potted);
  on_break = 0;
  for (const int id : potted) {
    if (id == 9) {  // spotted on the foot spot, or behind it on the long string
      Vec2 p = foot_spot(after.table);
      while (!placeable(st, after.balls, p)) p.x += 0.005;
      add_ball(after.balls, 9, p);
    } else if (id != 0) {
      ++on_break;
    }
  }
  // Ball in hand: the ghost-ball agent's rule (ghost_ball_in_hand_spot: a
  // straight-in on the lowest ball, kGhostBallInHandBack behind the ghost
  // ball of the nearest clear pocket); else a random free spot.
  std::vector<SimulationBall> objects;
  for (const SimulationBall& b : after.balls)
    if (b.id != 0) objects.push_back(b);
  int lowest = 99;
  for (const SimulationBall& b : objects) lowest = std::min(lowest, b.id);
  const std::optional<Vec2> spot = ghost_ball_in_hand_spot(after, 0, {lowest}, PlacementRegion{});
  Scenario out = after;
  out.cue.reset();
  out.balls = objects;
  add_ball(out.balls, 0, spot ? *spot : random_spot(st, objects, rng));
  std::rotate(out.balls.rbegin(), out.balls.rbegin() + 1, out.balls.rend());  // the cue ball first
  return out;
}

// The run-out's game: 9-ball in play on the broken rack (the planner agent
// to shoot, tournament noise, no push-out), the cue ball at the rule's spot,
// in hand anywhere when the planner places it (--in-hand planner).
GameState broken_game(const Setup& st, std::uint64_t seed, bool in_hand_planner, int& on_break) {
  GameConfig config = default_config(GameKind::nine_ball);
  config.noise = st.base.noise;
  GameState g = new_game(config);
  g.table = broken_rack(st, seed, on_break);
  g.phase = GamePhase::play;
  g.ball_in_hand.reset();
  if (in_hand_planner) g.ball_in_hand = PlacementRegion{};
  int lowest = 99;
  for (const SimulationBall& b : g.table.balls)
    if (b.id != 0) lowest = std::min(lowest, b.id);
  g.on = {lowest};
  g.push_out_available = false;
  return g;
}

// --break recommended: a 9-ball game as new_game racks it (the default
// gaps, the rack seeded by the rack's seed), broken by recommended_break
// through play() with tournament noise; the breaker goes on from where the
// break left the cue ball when the break is legal and makes a ball (no
// push-out: the run-out is played), and a 9 on the break is a run-out.
// Otherwise the rack ends as a dry break.
std::optional<GameState> engine_break(const Setup& st, std::uint64_t seed, RackRecord& rec) {
  GameConfig config = default_config(GameKind::nine_ball);
  config.noise = st.base.noise;
  const GameState g = new_game(config, seed);
  const GameStep step = play(g, recommended_break(g), stream_seed(seed, kBreakStream));
  const Ruling& r = step.ruling;
  for (const int id : r.pocketed) rec.on_break += id != 0 ? 1 : 0;
  rec.made_break = !r.truncated && !r.foul && rec.on_break > 0;
  if (rec.made_break && r.game_over) rec.stop = Stop::run_out;
  if (!rec.made_break) {
    rec.stop = Stop::dry_break;
    rec.detail = r.truncated || r.foul ? r.reason : "nothing pocketed on the break";
  }
  if (!rec.made_break || r.game_over) return std::nullopt;
  GameState next = step.next;
  next.push_out_available = false;
  return next;
}

// play()'s seed whose noise draw is the one simulate_many drew for shot
// `shot` of the stream `stream` (batch.hpp: play draws shot_normals(seed, 0),
// simulate_many shot_normals(stream, shot), and shot_normals(x, k) depends on
// x ^ splitmix64(k)): the run-outs keep the noise they were measured with.
std::uint64_t play_seed(std::uint64_t stream, std::uint64_t shot) {
  return stream ^ splitmix64(shot) ^ splitmix64(0);
}

// The agent's choice: the planner's or the safety planner's.
// Under --seconds, planned in rounds (agents/agent.hpp plan_in_time()), the
// last round's choice played.
PlannerChoice agent_choice(const AgentOptions& agent, const GameState& g, std::uint64_t seed) {
  const auto plan = [&](const AgentOptions& a) {
    return a.kind == AgentKind::safety_planner ? safety_planner_choice(a, g, seed) : planner_choice(a, g, seed);
  };
  if (!(agent.seconds > 0.0)) return plan(agent);
  PlannerChoice c;
  (void)plan_in_time(agent, [&](const AgentOptions& round) { c = plan(round); });
  return c;
}

RackRecord run_rack(const Setup& st, std::uint64_t seed, const AgentOptions& agent, bool in_hand_planner,
                    bool real_break) {
  RackRecord rec;
  rec.seed = seed;
  GameState g;
  if (real_break) {
    std::optional<GameState> after = engine_break(st, seed, rec);
    if (!after) return rec;
    g = std::move(*after);
  } else {
    g = broken_game(st, seed, in_hand_planner, rec.on_break);
  }
  const std::uint64_t noise_stream = stream_seed(seed, kMeasureStream);
  for (;;) {
    const int target = g.on.front();
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = thread_cpu_seconds();
    PlannerChoice c;
    try {
      c = agent_choice(agent, g, stream_seed(seed, 100 + static_cast<std::uint64_t>(rec.shots)));
    } catch (const std::exception& e) {  // the layout the engine left (never seen)
      rec.stop = Stop::rejected;
      rec.detail = e.what();
      return rec;
    }
    rec.decision_seconds.push_back(seconds_since(start));
    rec.decision_cpu_seconds.push_back(thread_cpu_seconds() - cpu_start);
    rec.simulations += c.simulations;
    if (c.kind == PlannerChoice::Kind::safety) {  // no pot of --kinds or --fallback-kinds, or one the agent would not risk
      rec.stop = c.success_probability >= 0.0 ? Stop::safety : Stop::no_feasible_shot;
      rec.detail = c.detail;
      return rec;
    }
    GameStep step;
    try {
      step = play(g, c.action, play_seed(noise_stream, static_cast<std::uint64_t>(rec.shots)));
    } catch (const std::exception& e) {
      rec.stop = Stop::rejected;
      rec.detail = e.what();
      return rec;
    }
    ++rec.shots;
    rec.planned.push_back(c.success_probability);
    rec.planned_next.push_back(c.next_success_probability);
    const Ruling& r = step.ruling;
    if (r.truncated) {
      rec.stop = Stop::failure;
      rec.detail = r.reason;
      return rec;
    }
    if (r.foul) {
      switch (*r.foul) {
        case Foul::miscue: rec.stop = Stop::miscue; break;
        case Foul::scratch: rec.stop = Stop::scratch; break;
        case Foul::wrong_ball_first:
        case Foul::no_contact: rec.stop = Stop::wrong_first_contact; break;
        default: rec.stop = Stop::miss; break;  // no rail after the contact: nothing potted
      }
      rec.detail = fmt("on the %d: %s", target, r.reason.c_str());
      return rec;
    }
    for (const int id : r.pocketed) rec.potted += id != 0 ? 1 : 0;
    if (r.game_over) {
      rec.stop = Stop::run_out;
      return rec;
    }
    if (r.turn_over) {
      rec.stop = Stop::miss;
      rec.detail = fmt("missed the %d (%s)", target, c.detail.c_str());
      return rec;
    }
    g = std::move(step.next);
  }
}

// ------------------------------------------------------------------ statistics

double mean(const std::vector<double>& x) {
  double s = 0.0;
  for (const double v : x) s += v;
  return x.empty() ? 0.0 : s / static_cast<double>(x.size());
}
double standard_error(const std::vector<double>& x) {
  if (x.size() < 2) return 0.0;
  const double m = mean(x);
  double s = 0.0;
  for (const double v : x) s += (v - m) * (v - m);
  return std::sqrt(s / static_cast<double>(x.size() - 1) / static_cast<double>(x.size()));
}
double median(std::vector<double> x) {
  if (x.empty()) return 0.0;
  std::sort(x.begin(), x.end());
  const std::size_t n = x.size();
  return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}
std::string num(double x) {
  if (!std::isfinite(x)) return "null";
  return fmt("%.6g", x);
}
// ------------------------------------------------------------------ flags

struct Options {
  int layouts = 1000;
  int racks = 1000;
  int repeats = 2000;
  std::uint64_t seed = 1;
  bool single = true, runout = true;
  int threads = 1;
  int planner_simulations = 4000;  // the single pots' plan_shot budget
  // The run-outs' agent: --agent, then the flags given over its options.
  std::string agent_name = "strongest";
  std::optional<int> agent_simulations;     // --planner-simulations
  std::optional<int> position_simulations;  // --position
  std::optional<int> noisy_leaves;          // --noisy-leaves
  std::optional<int> candidate_noisy_leaves;  // --candidate-noisy-leaves
  std::optional<int> depth;                 // --depth
  std::optional<LeaveValuation> valuation;  // --valuation
  std::optional<int> finalists;             // --finalists
  std::optional<int> varied_shots;          // --varied-shots
  std::optional<bool> game_ball_combinations;  // --game-ball-combinations
  double seconds = 0.0;                     // --seconds: AgentOptions::seconds (0: none)
  bool in_hand_planner = true;   // the run-outs' first cue ball placed by plan_ball_in_hand, not by the rule
  bool real_break = false;       // --break recommended: the game's own break, the run-out only after a made one
  std::optional<std::vector<ShotKind>> kinds;           // the run-outs' shot kinds
  std::optional<std::vector<ShotKind>> fallback_kinds;  // asked for when no shot of `kinds` is feasible; empty: none

  // The run-outs' agent: agent_named(agent_name) with the flags given.
  AgentOptions runout_agent() const {
    AgentOptions a = *agent_named(agent_name);
    if (agent_simulations) a.simulations = *agent_simulations;
    if (position_simulations) a.position_simulations = *position_simulations;
    if (noisy_leaves) a.position_noisy_leaves = *noisy_leaves;
    if (candidate_noisy_leaves) a.position_candidate_noisy_leaves = *candidate_noisy_leaves;
    if (depth) a.position_depth = *depth;
    if (valuation) a.position_valuation = *valuation;
    if (finalists) a.position_finalists = *finalists;
    if (varied_shots) a.position_varied_shots = *varied_shots;
    if (game_ball_combinations) a.game_ball_combinations = *game_ball_combinations;
    a.seconds = seconds;
    if (kinds) a.kinds = *kinds;
    if (fallback_kinds) a.fallback_kinds = *fallback_kinds;
    return a;
  }
  std::string json;
  std::string layouts_out;  // a folder: each single-pot layout written there as a scenario
  std::string suite = "all";
};

void usage() {
  std::printf(
      "usage: cueball-planner-benchmark [--suite single|runout|all] [--layouts N] [--racks N] [--repeats N]\n"
      "                                 [--seed S] [--planner-simulations N] [--position N] [--threads T]\n"
      "                                 [--in-hand rule|planner] [--break rule|recommended] [--kinds LIST]\n"
      "                                 [--fallback-kinds LIST] [--agent NAME] [--noisy-leaves N]\n"
      "                                 [--candidate-noisy-leaves N] [--depth D] [--valuation V] [--finalists F]\n"
      "                                 [--varied-shots N] [--seconds S] [--game-ball-combinations on|off]\n"
      "                                 [--json FILE] [--layouts-out DIR]\n"
      "The shot planner against a ghost-ball baseline and an exhaustive grid search (docs/planner-benchmark.md).\n"
      "  --suite S                single, runout or all (default all)\n"
      "  --layouts N              single-pot layouts, [1, 1000000] (default 1000); layout k from seed S + k\n"
      "  --racks N                9-ball racks for the run-outs, [1, 1000000] (default 1000); rack k from seed S + k\n"
      "  --repeats N              noisy repeats measuring each chosen shot, [10, 1000000] (default 2000)\n"
      "  --seed S                 first seed, [0, 1e18] (default 1)\n"
      "  --agent NAME             the run-outs' player: strongest (the default: the safety planner with\n"
      "                           position play and kicks, agents/agent.hpp strongest_agent()), safety_planner or\n"
      "                           planner (their default options); the flags below given override its options\n"
      "  --planner-simulations N  plan_shot's budget, [%d, %d] (default 4000, the planner's default)\n"
      "  --position N             run-outs played for position (plan_shot_for_position), N engine runs per\n"
      "                           next-shot plan, [%d, %d] (default: the agent's; strongest 1000)\n"
      "  --noisy-leaves N         position play: noisy outcomes of each finalist whose leaves are scored,\n"
      "                           [0, %d] (default: the agent's, %d; strongest %d; 0: the noise-free leave alone)\n"
      "  --candidate-noisy-leaves N  position play: noisy outcomes of every candidate whose leaves are valued\n"
      "                           before the finalists are chosen, [0, %d] (default: the agent's; strongest %d,\n"
      "                           the others 0: the noise-free leave alone)\n"
      "  --depth D                position play: shots looked ahead, [1, %d] (3: --valuation ghost_ball only) (default: the agent's; strongest 2, the others 1)\n"
      "  --valuation V            position play and ball in hand: how a leave is valued, windows (the planner's\n"
      "                           window search) or ghost_ball (no engine run at depth 1) (default: the agent's;\n"
      "                           strongest ghost_ball, the others windows)\n"
      "  --finalists F            position play: the candidates screened under noise, [1, %d] (default: the agent's;\n"
      "                           strongest %d, the others 3)\n"
      "  --varied-shots N         position play: the feasible shots whose spin and speed variants are candidate\n"
      "                           leaves, [1, %d] (default: the agent's; strongest %d, the others 3)\n"
      "  --game-ball-combinations on|off  the 9 by a combination through the ball on where it beats the\n"
      "                           run-out (AgentOptions::game_ball_combinations) (default: the agent's;\n"
      "                           strongest on, the others off)\n"
      "  --seconds S              the run-outs' decisions under a wall-clock budget, [0, 3600] s\n"
      "                           (AgentOptions::seconds: rounds from 500 runs up to the agent's; default 0: none)\n"
      "  --in-hand H              the run-outs' cue ball in hand after the break: planner (plan_ball_in_hand,\n"
      "                           with --position's budget, 1000 without it; the default) or rule (a straight-in\n"
      "                           on the lowest ball)\n"
      "  --break B                the run-outs' break: rule (a seeded engine break, then the cue ball in hand;\n"
      "                           the default) or recommended (new_game's rack broken by recommended_break with\n"
      "                           tournament noise; the run-out is played only after a legal break that makes\n"
      "                           a ball, from where it left the cue ball)\n"
      "  --kinds LIST             the run-outs' shot kinds, comma-separated: direct, bank, kick, combination\n"
      "                           (default direct,bank, the agent's)\n"
      "  --fallback-kinds LIST    the kinds asked for when no shot of --kinds pots the run-outs' ball, e.g. kick\n"
      "                           (single pots: none unless given; given, a plan of them where plan_shot's\n"
      "                           defaults find none, as the agents play)\n"
      "                           (default: the agent's, kick)\n"
      "  --threads T              layouts in parallel, [1, 256] (default 1); results do not depend on it, timings do\n"
      "  --json FILE              also write the results as JSON\n"
      "  --layouts-out DIR        write each single-pot layout as DIR/layout-<seed>.json (a scenario without a\n"
      "                           cue: the balls at rest, tournament noise), for cueball plan-shot --ball 1\n"
      "Exit status: 0 done, 1 an engine error, 2 bad flags.\n",
      kMinPlanSimulations, kMaxPlanSimulations, kMinPlanSimulations, kMaxPlanSimulations, kMaxPositionNoisyLeaves,
      kPositionNoisyLeaves, kStrongestNoisyLeaves, kMaxPositionNoisyLeaves, kStrongestCandidateNoisyLeaves,
      kMaxPositionDepth, kMaxPositionFinalists, kStrongestFinalists, kMaxPositionVariedShots, kStrongestVariedShots);
}

std::vector<ShotKind> kinds_flag(const std::string& flag, const std::string& value) {
  std::vector<ShotKind> kinds;
  std::size_t from = 0;
  while (from <= value.size()) {
    const std::size_t comma = std::min(value.find(',', from), value.size());
    const std::optional<ShotKind> kind = shot_kind_from_string(value.substr(from, comma - from));
    if (!kind) kFlags.bad(flag, value, "a comma-separated list of " + shot_kind_names(""));
    kinds.push_back(*kind);
    from = comma + 1;
  }
  return kinds;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--help" || flag == "-h") {
      usage();
      std::exit(0);
    }
    static const char* const known[] = {"--suite",  "--layouts", "--racks", "--repeats", "--seed", "--planner-simulations",
                                        "--position", "--kinds", "--fallback-kinds", "--threads", "--json", "--layouts-out",
                                        "--in-hand", "--break", "--agent", "--noisy-leaves", "--candidate-noisy-leaves", "--depth", "--valuation", "--finalists", "--varied-shots", "--seconds",
                                        "--game-ball-combinations"};
    if (std::find_if(std::begin(known), std::end(known), [&](const char* k) { return flag == k; }) == std::end(known))
      kFlags.bad("flag", flag,
               "--suite, --layouts, --racks, --repeats, --seed, --planner-simulations, --position, --kinds, "
               "--fallback-kinds, --threads, "
               "--json, --layouts-out, --in-hand, --break, --agent, --noisy-leaves, --candidate-noisy-leaves, --depth, --valuation, --finalists, --varied-shots, --seconds, --help");
    if (i + 1 >= argc) kFlags.bad(flag, "", "a value after the flag");
    const std::string value = argv[++i];
    if (flag == "--suite") {
      if (value != "single" && value != "runout" && value != "all") kFlags.bad(flag, value, "single, runout, all");
      o.suite = value;
      o.single = value != "runout";
      o.runout = value != "single";
    } else if (flag == "--layouts") {
      o.layouts = static_cast<int>(kFlags.integer(flag, value, 1, 1000000));
    } else if (flag == "--racks") {
      o.racks = static_cast<int>(kFlags.integer(flag, value, 1, 1000000));
    } else if (flag == "--repeats") {
      o.repeats = static_cast<int>(kFlags.integer(flag, value, 10, 1000000));
    } else if (flag == "--seed") {
      o.seed = static_cast<std::uint64_t>(kFlags.integer(flag, value, 0, 1000000000000000000LL));
    } else if (flag == "--noisy-leaves") {
      o.noisy_leaves = static_cast<int>(kFlags.integer(flag, value, 0, kMaxPositionNoisyLeaves));
    } else if (flag == "--candidate-noisy-leaves") {
      o.candidate_noisy_leaves = static_cast<int>(kFlags.integer(flag, value, 0, kMaxPositionNoisyLeaves));
    } else if (flag == "--seconds") {
      o.seconds = kFlags.number(flag, value, 0.0, kMaxAgentSeconds, "[0, 3600] s a decision");
    } else if (flag == "--depth") {
      o.depth = static_cast<int>(kFlags.integer(flag, value, 1, kMaxPositionDepth));
    } else if (flag == "--finalists") {
      o.finalists = static_cast<int>(kFlags.integer(flag, value, 1, kMaxPositionFinalists));
    } else if (flag == "--varied-shots") {
      o.varied_shots = static_cast<int>(kFlags.integer(flag, value, 1, kMaxPositionVariedShots));
    } else if (flag == "--game-ball-combinations") {
      if (value != "on" && value != "off") kFlags.bad(flag, value, "on, off");
      o.game_ball_combinations = value == "on";
    } else if (flag == "--valuation") {
      o.valuation = leave_valuation_from_string(value);
      if (!o.valuation) kFlags.bad(flag, value, leave_valuation_names());
    } else if (flag == "--agent") {
      const std::optional<AgentOptions> a = agent_named(value);
      if (!a || (a->kind != AgentKind::planner && a->kind != AgentKind::safety_planner))
        kFlags.bad(flag, value, "planner, safety_planner, strongest");
      o.agent_name = value;
    } else if (flag == "--kinds") {
      o.kinds = kinds_flag(flag, value);
    } else if (flag == "--fallback-kinds") {
      o.fallback_kinds = kinds_flag(flag, value);
    } else if (flag == "--break") {
      if (value != "rule" && value != "recommended") kFlags.bad(flag, value, "rule, recommended");
      o.real_break = value == "recommended";
    } else if (flag == "--in-hand") {
      if (value != "rule" && value != "planner") kFlags.bad(flag, value, "rule, planner");
      o.in_hand_planner = value == "planner";
    } else if (flag == "--position") {
      o.position_simulations = static_cast<int>(kFlags.integer(flag, value, kMinPlanSimulations, kMaxPlanSimulations));
    } else if (flag == "--planner-simulations") {
      o.planner_simulations = static_cast<int>(kFlags.integer(flag, value, kMinPlanSimulations, kMaxPlanSimulations));
      o.agent_simulations = o.planner_simulations;
    } else if (flag == "--threads") {
      o.threads = static_cast<int>(kFlags.integer(flag, value, 1, 256));
    } else if (flag == "--layouts-out") {
      if (value.empty()) kFlags.bad(flag, value, "a folder path");
      o.layouts_out = value;
    } else {
      if (value.empty()) kFlags.bad(flag, value, "a file path");
      o.json = value;
    }
  }
  // Three shots deep by the ghost ball only (position_play.hpp, kMaxWindowsDepth).
  if (o.depth && *o.depth > max_position_depth(o.runout_agent().position_valuation))
    kFlags.bad("--depth", std::to_string(*o.depth),
               "[1, " + std::to_string(kMaxWindowsDepth) + "] with valuation windows (deeper: --valuation ghost_ball)");
  return o;
}

// Runs job(k) for k in [0, n) on `threads` workers; the first exception is rethrown.
template <class Job>
void parallel_for(int n, int threads, const Job& job) {
  std::atomic<int> next{0};
  std::exception_ptr error;
  std::atomic<bool> failed{false};
  const auto work = [&]() {
    for (int k = next++; k < n && !failed; k = next++) {
      try {
        job(k);
      } catch (...) {
        if (!failed.exchange(true)) error = std::current_exception();
      }
    }
  };
  std::vector<std::thread> workers;
  for (int t = 1; t < threads; ++t) workers.emplace_back(work);
  work();
  for (std::thread& w : workers) w.join();
  if (error) std::rethrow_exception(error);
}

std::string action_json(const ShotAction& a) {
  return fmt("[%.9g, %.9g, %.4g, %.4g, %.4g]", a.speed, a.aim_deg, a.elevation_deg, a.side, a.height);
}

std::string kinds_text(const std::vector<ShotKind>& kinds) {
  std::string t;
  for (const ShotKind k : kinds) t += (t.empty() ? "" : ",") + std::string(to_string(k));
  return t;
}

int run(const Options& o) {
  const Setup st = make_setup();
  std::string json = "{\n \"tool\": \"cueball-planner-benchmark\",\n";
  const AgentOptions agent = o.runout_agent();
  json += fmt(" \"options\": {\"suite\": \"%s\", \"layouts\": %d, \"racks\": %d, \"repeats\": %d, \"seed\": %llu, "
              "\"planner_simulations\": %d, \"agent\": \"%s\", \"agent_simulations\": %d, \"position_simulations\": %d, \"noisy_leaves\": %d, \"candidate_noisy_leaves\": %d, \"depth\": %d, \"valuation\": \"%s\", \"finalists\": %d, \"varied_shots\": %d, \"seconds\": %g, "
              "\"in_hand\": \"%s\", \"break\": \"%s\", \"kinds\": \"%s\", "
              "\"fallback_kinds\": \"%s\", \"threads\": %d},\n",
              o.suite.c_str(), o.layouts, o.racks, o.repeats, static_cast<unsigned long long>(o.seed), o.planner_simulations,
              o.agent_name.c_str(), agent.simulations, agent.position_simulations, agent.position_noisy_leaves, agent.position_candidate_noisy_leaves, agent.position_depth,
              to_string(agent.position_valuation), agent.position_finalists, agent.position_varied_shots, agent.seconds, o.in_hand_planner ? "planner" : "rule",
              o.real_break ? "recommended" : "rule", kinds_text(agent.kinds).c_str(), kinds_text(agent.fallback_kinds).c_str(),
              o.threads);
  const CueStrikeNoise& n = st.base.noise;
  json += fmt(" \"noise\": {\"speed\": %g, \"aim_deg\": %g, \"elevation_deg\": %g, \"side\": %g, \"height\": %g},\n", n.speed,
              n.aim / kDeg, n.elevation / kDeg, n.side_offset / st.radius, n.height_offset / st.radius);
  std::printf("cueball-planner-benchmark: seed %llu, %d repeats per measured shot, planner budget %d, %d thread%s\n",
              static_cast<unsigned long long>(o.seed), o.repeats, o.planner_simulations, o.threads, o.threads == 1 ? "" : "s");
  bool first_suite = true;
  if (o.single) {
    const auto start = std::chrono::steady_clock::now();
    if (!o.layouts_out.empty())
      for (int k = 0; k < o.layouts; ++k) {
        const std::uint64_t seed = o.seed + static_cast<std::uint64_t>(k);
        int others = 0;
        const std::string path = o.layouts_out + "/layout-" + std::to_string(seed) + ".json";
        std::ofstream out(path);
        if (!out) kFlags.bad("--layouts-out", o.layouts_out, "an existing, writable folder");
        Scenario layout = single_layout(st, seed, others);
        layout.cue.reset();  // the table state only: the planner chooses the strike
        out << scenario_to_json(layout) << "\n";
      }
    std::vector<SingleRecord> recs(static_cast<std::size_t>(o.layouts));
    parallel_for(o.layouts, o.threads, [&](int k) {
      recs[static_cast<std::size_t>(k)] = run_single(st, o.seed + static_cast<std::uint64_t>(k), o.repeats, o.planner_simulations,
                                                       o.fallback_kinds.value_or(std::vector<ShotKind>{}));
    });
    const double wall = seconds_since(start);
    std::printf("\nsingle pots: %d layouts (seeds %llu..%llu), %.1f s\n", o.layouts, static_cast<unsigned long long>(o.seed),
                static_cast<unsigned long long>(o.seed + static_cast<std::uint64_t>(o.layouts) - 1), wall);
    std::printf("  %-11s %9s %8s %9s %12s %12s %10s %10s\n", "method", "mean p", "s.e.", "no shot", "sims/dec", "median cpu s",
                "median s", "mean s");
    double mean_p[3], mean_sims[3], med_s[3];
    json += " \"single\": {\n";
    json += fmt("  \"layouts\": %d, \"wall_seconds\": %s,\n  \"methods\": {\n", o.layouts, num(wall).c_str());
    for (int m = 0; m < 3; ++m) {
      std::vector<double> p, sims, secs, cpu;
      int none = 0;
      for (const SingleRecord& r : recs) {
        p.push_back(r.m[m].p);
        sims.push_back(r.m[m].simulations);
        secs.push_back(r.m[m].seconds);
        cpu.push_back(r.m[m].cpu_seconds);
        none += r.m[m].found ? 0 : 1;
      }
      mean_p[m] = mean(p);
      mean_sims[m] = mean(sims);
      med_s[m] = median(cpu);
      std::printf("  %-11s %9.4f %8.4f %9d %12.0f %12.4f %10.4f %10.4f\n", kMethodNames[m], mean_p[m], standard_error(p), none,
                  mean_sims[m], med_s[m], median(secs), mean(secs));
      json += fmt("   \"%s\": {\"mean_success\": %s, \"standard_error\": %s, \"no_shot\": %d, \"mean_simulations\": %s, "
                  "\"median_simulations\": %s, \"median_cpu_seconds\": %s, \"mean_cpu_seconds\": %s, \"median_seconds\": %s, "
                  "\"mean_seconds\": %s}%s\n",
                  kMethodNames[m], num(mean_p[m]).c_str(), num(standard_error(p)).c_str(), none, num(mean_sims[m]).c_str(),
                  num(median(sims)).c_str(), num(med_s[m]).c_str(), num(mean(cpu)).c_str(), num(median(secs)).c_str(),
                  num(mean(secs)).c_str(), m < 2 ? "," : "");
    }
    json += "  },\n";
    // Paired differences and the goals.
    std::vector<double> d_ex, d_gh;
    int planner_better = 0, exhaustive_better = 0;
    for (const SingleRecord& r : recs) {
      d_ex.push_back(r.m[0].p - r.m[2].p);
      d_gh.push_back(r.m[0].p - r.m[1].p);
      planner_better += r.m[0].p > r.m[2].p + 0.05 ? 1 : 0;
      exhaustive_better += r.m[2].p > r.m[0].p + 0.05 ? 1 : 0;
    }
    const double ratio = mean_p[2] > 0.0 ? mean_p[0] / mean_p[2] : 0.0;
    const double sims_ratio = mean_sims[0] > 0.0 ? mean_sims[2] / mean_sims[0] : 0.0;
    // The exhaustive search as the issue defines it: every cell the cue
    // clears measured like the chosen shots, with --repeats noisy shots.
    std::vector<double> cell_runs;
    for (const SingleRecord& r : recs) cell_runs.push_back(static_cast<double>(r.grid.simulated) * o.repeats);
    const double full_grid_ratio = mean_sims[0] > 0.0 ? mean(cell_runs) / mean_sims[0] : 0.0;
    std::printf("  planner - exhaustive: %+.4f +- %.4f (paired); planner / exhaustive = %.3f (goal >= 0.98)\n", mean(d_ex),
                standard_error(d_ex), ratio);
    std::printf("  planner - ghost_ball: %+.4f +- %.4f (paired)\n", mean(d_gh), standard_error(d_gh));
    std::printf("  exhaustive / planner simulations = %.1f (goal >= 50); planner median decision %.4f s CPU (goal < 0.1 s)\n", sims_ratio,
                med_s[0]);
    std::printf("  every grid cell measured with %d repeats (the issue's exhaustive search, not run): %.3g runs a decision, %.0f x the planner's\n",
                o.repeats, mean(cell_runs), full_grid_ratio);
    std::printf("  layouts where one beats the other by > 0.05: planner %d, exhaustive %d\n", planner_better, exhaustive_better);
    json += fmt("  \"planner_minus_exhaustive\": %s, \"planner_minus_exhaustive_se\": %s, \"planner_minus_ghost_ball\": %s, "
                "\"planner_minus_ghost_ball_se\": %s,\n",
                num(mean(d_ex)).c_str(), num(standard_error(d_ex)).c_str(), num(mean(d_gh)).c_str(), num(standard_error(d_gh)).c_str());
    json += fmt("  \"layouts_planner_better\": %d, \"layouts_exhaustive_better\": %d,\n", planner_better, exhaustive_better);
    json += fmt("  \"full_grid_simulations\": %s, \"full_grid_simulation_ratio\": %s,\n", num(mean(cell_runs)).c_str(),
                num(full_grid_ratio).c_str());
    json += fmt("  \"goals\": {\"success_ratio\": %s, \"success_ratio_met\": %s, \"simulation_ratio\": %s, \"simulation_ratio_met\": %s, "
                "\"above_ghost_ball\": %s, \"median_seconds_met\": %s},\n",
                num(ratio).c_str(), ratio >= 0.98 ? "true" : "false", num(sims_ratio).c_str(), sims_ratio >= 50.0 ? "true" : "false",
                mean(d_gh) > 2.0 * standard_error(d_gh) ? "true" : "false", med_s[0] < 0.1 ? "true" : "false");
    json += "  \"per_layout\": [\n";
    for (std::size_t k = 0; k < recs.size(); ++k) {
      const SingleRecord& r = recs[k];
      json += fmt("   {\"seed\": %llu, \"others\": %d, \"grid_cells\": %d, \"grid_simulated\": %d, \"grid_potting\": %d",
                  static_cast<unsigned long long>(r.seed), r.others, r.grid.cells, r.grid.simulated, r.grid.potting);
      for (int m = 0; m < 3; ++m)
        json += fmt(", \"%s\": {\"p\": %s, \"simulations\": %d, \"seconds\": %s, \"cpu_seconds\": %s, \"shot\": %s, \"action\": %s}",
                    kMethodNames[m], num(r.m[m].p).c_str(), r.m[m].simulations, num(r.m[m].seconds).c_str(), num(r.m[m].cpu_seconds).c_str(), quoted(r.m[m].what).c_str(),
                    r.m[m].found ? action_json(r.m[m].action).c_str() : "null");
      json += k + 1 < recs.size() ? "},\n" : "}\n";
    }
    json += "  ]\n }";
    first_suite = false;
  }
  if (o.runout) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<RackRecord> recs(static_cast<std::size_t>(o.racks));
    parallel_for(o.racks, o.threads, [&](int k) {
      recs[static_cast<std::size_t>(k)] =
          run_rack(st, o.seed + static_cast<std::uint64_t>(k), agent, o.in_hand_planner, o.real_break);
    });
    const double wall = seconds_since(start);
    int stops[kStops] = {};
    std::vector<double> potted, secs, cpu, shots, on_break;
    long long sims = 0;
    for (const RackRecord& r : recs) {
      ++stops[static_cast<int>(r.stop)];
      potted.push_back(r.potted);
      shots.push_back(r.shots);
      on_break.push_back(r.on_break);
      secs.insert(secs.end(), r.decision_seconds.begin(), r.decision_seconds.end());
      cpu.insert(cpu.end(), r.decision_cpu_seconds.begin(), r.decision_cpu_seconds.end());
      sims += r.simulations;
    }
    const double fraction = static_cast<double>(stops[0]) / o.racks;
    // The goal: issue 27's for the strongest agent, issue 13's for the others.
    const double goal = o.agent_name == "strongest" ? kStrongestRunOutGoal : kPlannerRunOutGoal;
    std::printf("\nrun-outs by %s (%d runs a plan, position %d, in hand: %s): %d racks (seeds %llu..%llu), %.1f s\n",
                o.agent_name.c_str(), agent.simulations, agent.position_simulations, o.in_hand_planner ? "planner" : "rule",
                o.racks, static_cast<unsigned long long>(o.seed),
                static_cast<unsigned long long>(o.seed + static_cast<std::uint64_t>(o.racks) - 1), wall);
    std::printf("  run out %.3f +- %.3f (goal >= %.2f); balls potted per rack %.2f (plus %.2f on the break); shots %.2f\n", fraction,
                std::sqrt(fraction * (1.0 - fraction) / o.racks), goal, mean(potted), mean(on_break), mean(shots));
    std::printf("  median decision %.4f s CPU (%.4f s wall), %.0f simulations per decision\n", median(cpu), median(secs),
                secs.empty() ? 0.0 : static_cast<double>(sims) / static_cast<double>(secs.size()));
    std::printf("  ended by:");
    for (int k = 0; k < kStops; ++k) std::printf(" %s %d%s", kStopNames[k], stops[k], k + 1 < kStops ? "," : "\n");
    // --break recommended: how often the break makes a ball, and how often a
    // made break is run out.
    int made = 0;
    for (const RackRecord& r : recs) made += r.made_break ? 1 : 0;
    const double made_share = static_cast<double>(made) / o.racks;
    const double after_made = made > 0 ? static_cast<double>(stops[0]) / made : 0.0;
    if (o.real_break)
      std::printf("  breaks that make a ball %.3f +- %.3f; run out after them %.3f +- %.3f (%d of %d)\n", made_share,
                  std::sqrt(made_share * (1.0 - made_share) / o.racks), after_made,
                  made > 0 ? std::sqrt(after_made * (1.0 - after_made) / made) : 0.0, stops[0], made);
    json += first_suite ? "" : ",\n";
    json += " \"runout\": {\n";
    json += fmt("  \"racks\": %d, \"wall_seconds\": %s, \"run_out_fraction\": %s, \"run_out_standard_error\": %s, "
                "\"mean_balls_potted\": %s, \"mean_potted_on_break\": %s, \"mean_shots\": %s, \"median_decision_cpu_seconds\": %s, "
                "\"median_decision_seconds\": %s, "
                "\"mean_simulations_per_decision\": %s, \"goal\": %s, \"goal_met\": %s,\n",
                o.racks, num(wall).c_str(), num(fraction).c_str(), num(std::sqrt(fraction * (1.0 - fraction) / o.racks)).c_str(),
                num(mean(potted)).c_str(), num(mean(on_break)).c_str(), num(mean(shots)).c_str(), num(median(cpu)).c_str(), num(median(secs)).c_str(),
                num(secs.empty() ? 0.0 : static_cast<double>(sims) / static_cast<double>(secs.size())).c_str(), num(goal).c_str(),
                fraction >= goal ? "true" : "false");
    if (o.real_break)
      json += fmt("  \"breaks_made\": %d, \"break_made_fraction\": %s, \"run_out_after_made_break\": %s,\n", made,
                  num(made_share).c_str(), num(after_made).c_str());
    json += "  \"ended_by\": {";
    for (int k = 0; k < kStops; ++k) json += fmt("\"%s\": %d%s", kStopNames[k], stops[k], k + 1 < kStops ? ", " : "},\n");
    json += "  \"per_rack\": [\n";
    for (std::size_t k = 0; k < recs.size(); ++k) {
      const RackRecord& r = recs[k];
      std::string planned, next;
      for (std::size_t j = 0; j < r.planned.size(); ++j) {
        planned += (j ? ", " : "") + num(r.planned[j]);
        next += (j ? ", " : "") + num(r.planned_next[j]);
      }
      json += fmt("   {\"seed\": %llu, \"on_break\": %d, \"potted\": %d, \"shots\": %d, \"ended_by\": \"%s\", "
                  "\"planned\": [%s], \"planned_next\": [%s], \"detail\": %s}%s\n",
                  static_cast<unsigned long long>(r.seed), r.on_break, r.potted, r.shots, kStopNames[static_cast<int>(r.stop)],
                  planned.c_str(), next.c_str(), quoted(r.detail).c_str(), k + 1 < recs.size() ? "," : "");
    }
    json += "  ]\n }";
  }
  json += "\n}\n";
  if (!o.json.empty()) tools::write_file(kFlags, "--json", o.json, json);
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return cueball::tools::tool_main("cueball-planner-benchmark", parse(argc, argv), run); }
