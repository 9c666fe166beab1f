// The carom_search agent (agent.hpp): a simple search with the engine for a
// three-cushion point. Every strike it tries is played through play() on a
// copy of the state, so the game's own rules judge it (the opening shot on
// the red, the frozen balls, the cushions before the second ball). A short
// driver over one Search context, in four steps that share the budget
// AgentOptions::simulations (engine runs, never exceeded; the screen stops
// when a full round no longer fits, so part of it may be left):
//
//   1. scan    half of it: strikes spread evenly round the whole circle of
//              aims (the start drawn from the seed), each with a speed and a
//              spin drawn from a small set, played noise-free;
//   2. refine  a quarter: around the best strike not yet refined (a point,
//              else the nearest miss), aim nudged by 0.1 to 1.2 deg, speed
//              by 10 %, side by 0.15 ball radii; the new strikes join the
//              pool, so this climbs towards points and maps their neighbours;
//   3. screen  the rest: the points found, ranked first by how many of their
//              refined neighbours also scored, then played with the planning
//              noise on common seeds, four repeats a round, the worse half
//              dropped each round (successive halving); the one that scored
//              most often is chosen;
//   4. centre  what is left: the chosen point's aim moved to the middle of
//              its noise-free aim window, kept when it scores at least as
//              often on the same noisy seeds.
//
// Position (AgentOptions::position_simulations > 0), between 3 and 4: the
// screen halves down to kCaromPositionFinalists points instead of one; each is
// played noise-free and the next point searched on the table it leaves
// (this search again, min(position_simulations, simulations) runs, no
// position of its own); the one played maximises the points expected from
// this shot and the next, rate x (1 + next rate), rate the share of its
// noisy repeats that scored (a point that wins the game counts the next as
// certain). The one-shot lookahead of the pool agents' position play
// (planning/position_play.hpp) for a game in which the shooter plays on
// after a point. The decision then spends at most simulations +
// kCaromPositionFinalists x (min(position_simulations, simulations) + 1) runs.
//
// When nothing scores, the best near miss is played: both balls touched with
// the most cushions before the second, else one ball touched after the most
// cushions. The planning noise is options.noise, else the game's, else
// tournament_noise() (planning/shot_planner.hpp). Deterministic for the seed.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "cueball/agents/agent.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/core/random.hpp"
#include "cueball/planning/shot_planner.hpp"
#include "core/angles.hpp"

namespace cueball {

namespace {

// The speeds (m/s), sides and heights (ball radii) the scan draws from.
constexpr std::array kSpeeds{2.5, 3.5, 4.5, 6.0};
constexpr std::array kSides{-0.3, 0.0, 0.3};
constexpr std::array kHeights{-0.2, 0.1, 0.3};
// The refinement's nudges.
constexpr std::array kAimNudgesDeg{0.1, 0.2, 0.4, 0.8, 1.2};
constexpr double kSpeedNudge = 0.1;  // relative
constexpr double kSideNudge = 0.15;  // ball radii
// Neighbours counted for a point's support: the same speed and spin, aim within this, deg.
constexpr double kNeighbourAimDeg = 0.5;
// The screen: points entering it, noisy repeats each a round, repeats at most.
constexpr std::size_t kScreenedPoints = 16;
constexpr int kRepeatsPerRound = 4;
constexpr int kMaxRepeats = 64;
// The centring of the chosen point's aim, deg.
constexpr double kCentreStepDeg = 0.025;
constexpr double kCentreReachDeg = 1.0;
// Scores of a strike (points are all worth kPointScore before the screen).
constexpr double kPointScore = 10.0;
constexpr double kFoulScore = -1.0;

struct Candidate {
  ShotAction strike;
  double score = 0.0;
  bool point = false;
  bool refined = false;
  int noisy_points = 0;
  int noisy_tries = 0;
};

struct Search {
  const GameState& state;
  std::uint64_t seed = 0;
  int budget = 0;
  int used = 0;
  GameState quiet;  // the state played noise-free
  GameState noisy;  // the state played with the planning noise
  std::vector<Candidate> pool;
};

bool is_zero(const CueStrikeNoise& n) {
  return n.speed == 0.0 && n.aim == 0.0 && n.elevation == 0.0 && n.side_offset == 0.0 && n.height_offset == 0.0;
}

// How good a noise-free strike is: a point, else how near it came.
double score_of(const GameStep& step, int shooter) {
  if (step.ruling.points[static_cast<std::size_t>(shooter)] > 0) return kPointScore;
  if (step.ruling.foul || step.ruling.truncated) return kFoulScore;
  const ShotFacts& f = step.facts;
  int first = -1;
  for (const CueCushionsBeforeContact& c : f.cue_cushions_before_contact) {
    if (first < 0) {
      first = c.ball;
    } else if (c.ball != first) {
      return 2.0 + std::min(c.cushions, 2) / 3.0;  // both touched, too few cushions between
    }
  }
  const double cushions = std::min(f.cushion_count(f.cue_ball), 3) / 3.0;
  return first >= 0 ? 1.0 + cushions : 0.5 * cushions;
}

// One noise-free engine run of `strike`, added to the pool.
void try_strike(Search& s, const ShotAction& strike) {
  if (s.used >= s.budget) return;
  Action a;
  a.strike = strike;
  const GameStep step = play(s.quiet, a, 0);
  s.used += 1;
  Candidate c;
  c.strike = strike;
  c.score = score_of(step, s.state.to_shoot);
  c.point = c.score >= kPointScore;
  s.pool.push_back(c);
}

// Step 1.
void scan(Search& s, int shots) {
  RandomStream rng(stream_seed(s.seed, 1));
  const double start = rng.uniform(-180.0, 180.0);
  for (int i = 0; i < shots; ++i) {
    ShotAction a;
    a.aim_deg = wrapped_deg(start + 360.0 * static_cast<double>(i) / static_cast<double>(shots));
    a.speed = kSpeeds[static_cast<std::size_t>(rng.integer(0, static_cast<int>(kSpeeds.size()) - 1))];
    a.side = kSides[static_cast<std::size_t>(rng.integer(0, static_cast<int>(kSides.size()) - 1))];
    a.height = kHeights[static_cast<std::size_t>(rng.integer(0, static_cast<int>(kHeights.size()) - 1))];
    try_strike(s, a);
  }
}

// The neighbours of a strike the refinement tries.
std::vector<ShotAction> nudges(const ShotAction& a) {
  std::vector<ShotAction> out;
  for (const double d : kAimNudgesDeg) {
    for (const double sign : {-1.0, 1.0}) {
      ShotAction n = a;
      n.aim_deg = wrapped_deg(a.aim_deg + sign * d);
      out.push_back(n);
    }
  }
  for (const double f : {1.0 - kSpeedNudge, 1.0 + kSpeedNudge}) {
    ShotAction n = a;
    n.speed = std::min(a.speed * f, 8.0);
    out.push_back(n);
  }
  for (const double d : {-kSideNudge, kSideNudge}) {
    ShotAction n = a;
    n.side = std::clamp(a.side + d, -0.35, 0.35);
    if (std::hypot(n.side, n.height) <= 0.45) out.push_back(n);
  }
  return out;
}

// Step 2.
void refine(Search& s, int until) {
  while (s.used < until) {
    std::size_t best = s.pool.size();
    for (std::size_t i = 0; i < s.pool.size(); ++i)
      if (!s.pool[i].refined && (best == s.pool.size() || s.pool[i].score > s.pool[best].score)) best = i;
    if (best == s.pool.size()) return;
    s.pool[best].refined = true;
    const ShotAction centre = s.pool[best].strike;
    for (const ShotAction& n : nudges(centre)) {
      if (s.used >= until) return;
      try_strike(s, n);
    }
  }
}

bool same_stroke(const ShotAction& a, const ShotAction& b) {
  return a.speed == b.speed && a.side == b.side && a.height == b.height && a.elevation_deg == b.elevation_deg;
}

// Share of the strike's evaluated neighbours (same stroke, aim close) that scored.
double support(const Search& s, const Candidate& c) {
  int near = 0;
  int scored = 0;
  for (const Candidate& o : s.pool) {
    if (&o == &c || !same_stroke(o.strike, c.strike)) continue;
    if (std::abs(wrapped_deg(o.strike.aim_deg - c.strike.aim_deg)) > kNeighbourAimDeg) continue;
    near += 1;
    scored += o.point ? 1 : 0;
  }
  return static_cast<double>(scored + 1) / static_cast<double>(near + 2);
}

double noisy_rate(const Candidate& c) {
  return c.noisy_tries == 0 ? 0.0 : static_cast<double>(c.noisy_points) / static_cast<double>(c.noisy_tries);
}

// Noisy repeats of a strike until it has `to` of them, on the screen's
// common seeds (every candidate meets the same noise draws), within the budget.
void repeat_noisy(Search& s, Candidate& c, int to) {
  Action a;
  a.strike = c.strike;
  while (c.noisy_tries < to && s.used < s.budget) {
    const GameStep step = play(s.noisy, a, stream_seed(s.seed, 1000 + static_cast<std::uint64_t>(c.noisy_tries)));
    s.used += 1;
    c.noisy_tries += 1;
    c.noisy_points += step.ruling.points[static_cast<std::size_t>(s.state.to_shoot)] > 0 ? 1 : 0;
  }
}

// Step 3: the points left in the screen, best first (empty when none): one,
// or with position play up to kCaromPositionFinalists.
std::vector<std::size_t> screen(Search& s, std::size_t finalists) {
  std::vector<std::pair<double, std::size_t>> ranked;
  for (std::size_t i = 0; i < s.pool.size(); ++i)
    if (s.pool[i].point) ranked.push_back({support(s, s.pool[i]), i});
  if (ranked.empty()) return {};
  std::stable_sort(ranked.begin(), ranked.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  std::vector<std::size_t> alive;
  for (std::size_t k = 0; k < ranked.size() && k < kScreenedPoints; ++k) alive.push_back(ranked[k].second);
  while (true) {
    const int round_cost = kRepeatsPerRound * static_cast<int>(alive.size());
    if (s.budget - s.used < round_cost || s.pool[alive.front()].noisy_tries >= kMaxRepeats) break;
    for (const std::size_t i : alive) repeat_noisy(s, s.pool[i], s.pool[i].noisy_tries + kRepeatsPerRound);
    std::stable_sort(alive.begin(), alive.end(),
                     [&](std::size_t x, std::size_t y) { return noisy_rate(s.pool[x]) > noisy_rate(s.pool[y]); });
    if (alive.size() > finalists) alive.resize(std::max(finalists, (alive.size() + 1) / 2));
  }
  if (alive.size() > finalists) alive.resize(finalists);
  return alive;
}

// Position: of the finalists, the one with the most points expected from
// this shot and the next (header comment); `next_rate` gets its next rate.
std::size_t play_for_position(Search& s, const AgentOptions& options, const std::vector<std::size_t>& finalists,
                              double& next_rate) {
  AgentOptions next = options;
  next.simulations = std::min(options.position_simulations, options.simulations);
  next.position_simulations = 0;
  std::size_t best = finalists.front();
  double best_value = -1.0;
  for (std::size_t k = 0; k < finalists.size(); ++k) {
    Candidate& c = s.pool[finalists[k]];
    Action a;
    a.strike = c.strike;
    const GameStep step = play(s.quiet, a, 0);
    s.used += 1;
    double rate = 0.0;  // the next point's, on the table this one leaves
    if (step.ruling.points[static_cast<std::size_t>(s.state.to_shoot)] > 0) {
      if (step.next.over) {
        rate = 1.0;
      } else if (step.next.to_shoot == s.state.to_shoot) {
        const CaromSearchResult n = carom_search(next, step.next, stream_seed(s.seed, 5000 + k));
        s.used += n.simulations;
        rate = n.point && n.noisy_tries > 0 ? static_cast<double>(n.noisy_points) / n.noisy_tries : 0.0;
      }
    }
    const double value = noisy_rate(c) * (1.0 + rate);
    if (value > best_value) best_value = value, best = finalists[k], next_rate = rate;
  }
  return best;
}

// One noise-free run: does the strike score?
bool point_quiet(Search& s, const ShotAction& strike) {
  Action a;
  a.strike = strike;
  s.used += 1;
  return play(s.quiet, a, 0).ruling.points[static_cast<std::size_t>(s.state.to_shoot)] > 0;
}

// Step 4: the chosen point moved to the middle of its aim window (noise-free,
// steps of kCentreStepDeg up to kCentreReachDeg each way), kept when it
// scores as often on the same noisy seeds.
std::size_t centre(Search& s, std::size_t chosen) {
  const ShotAction start = s.pool[chosen].strike;
  double edge[2] = {0.0, 0.0};
  for (int side = 0; side < 2; ++side) {
    const double sign = side == 0 ? -1.0 : 1.0;
    for (double d = kCentreStepDeg; d <= kCentreReachDeg; d += kCentreStepDeg) {
      if (s.budget - s.used < 2 + s.pool[chosen].noisy_tries) return chosen;
      ShotAction n = start;
      n.aim_deg = wrapped_deg(start.aim_deg + sign * d);
      if (!point_quiet(s, n)) break;
      edge[side] = sign * d;
    }
  }
  const double shift = 0.5 * (edge[0] + edge[1]);
  if (std::abs(shift) < 0.5 * kCentreStepDeg) return chosen;
  Candidate c;
  c.strike = start;
  c.strike.aim_deg = wrapped_deg(start.aim_deg + shift);
  c.point = true;
  c.score = kPointScore;
  s.pool.push_back(c);
  repeat_noisy(s, s.pool.back(), s.pool[chosen].noisy_tries);
  const Candidate& moved = s.pool.back();
  if (moved.noisy_tries == s.pool[chosen].noisy_tries && moved.noisy_points >= s.pool[chosen].noisy_points)
    return s.pool.size() - 1;
  return chosen;
}

}  // namespace

CaromSearchResult carom_search(const AgentOptions& options, const GameState& state, std::uint64_t seed) {
  validate(options);
  if (state.config.kind != GameKind::three_cushion)
    throw InvalidArgument("kind", std::string("carom_search plays three_cushion, not ") + to_string(state.config.kind));
  if (state.over) throw InvalidArgument("state", "the game is over (" + state.end_reason + ")");
  Search s{state, seed, options.simulations, 0, state, state, {}};
  s.quiet.config.noise = CueStrikeNoise{};
  CueStrikeNoise noise = options.noise ? *options.noise : state.config.noise;
  if (is_zero(noise)) noise = tournament_noise();
  s.noisy.config.noise = noise;

  scan(s, std::max(1, s.budget / 2));
  refine(s, std::max(s.used, s.budget - s.budget / 4));
  const bool position = options.position_simulations > 0;
  const std::vector<std::size_t> finalists = screen(s, position ? kCaromPositionFinalists : 1);
  std::size_t chosen = s.pool.size();
  double next_rate = -1.0;
  if (finalists.size() > 1) {
    chosen = play_for_position(s, options, finalists, next_rate);
  } else if (!finalists.empty()) {
    chosen = finalists.front();
  }
  if (chosen < s.pool.size()) chosen = centre(s, chosen);

  CaromSearchResult r;
  r.simulations = s.used;
  r.next_point_rate = next_rate;
  if (chosen < s.pool.size()) {
    r.action.strike = s.pool[chosen].strike;
    r.point = true;
    r.noisy_points = s.pool[chosen].noisy_points;
    r.noisy_tries = s.pool[chosen].noisy_tries;
    return r;
  }
  std::size_t best = 0;  // the nearest miss (the scan always plays at least one strike)
  for (std::size_t i = 1; i < s.pool.size(); ++i)
    if (s.pool[i].score > s.pool[best].score) best = i;
  r.action.strike = s.pool[best].strike;
  return r;
}

Action carom_search_action(const AgentOptions& options, const GameState& state, std::uint64_t seed) {
  return carom_search(options, state, seed).action;
}

}  // namespace cueball
