// The game driver (game.hpp): what every discipline shares. A shot is a
// short sequence of named steps over one ShotRun: validate the action,
// set the table (the cue ball placed), strike with the config's noise,
// simulate, read the facts, judge by the discipline's rules, apply the
// bound on shots.
#include "cueball/games/game.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "core/enum_names.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/core/random.hpp"
#include "games/rules.hpp"

namespace cueball {

namespace {

constexpr std::array kDecisions{Decision::play,    Decision::pass,         Decision::rerack_and_break,
                                Decision::rerack_opponent_breaks, Decision::respot_eight, Decision::rerack,
                                Decision::restore};

constexpr double kDeg = std::numbers::pi / 180.0;

// Where the action's strike must lie (ShotAction, batch.hpp).
constexpr double kMaxCueSpeedInAction = 12.0;
constexpr double kMaxElevationDeg = 89.0;
constexpr double kMaxTipOffset = 0.5;

std::string num(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.9g", x);
  return b;
}

std::string ids(const std::vector<int>& v) {
  std::string s;
  for (const int id : v) s += (s.empty() ? "" : ", ") + std::to_string(id);
  return s.empty() ? "none" : s;
}

bool contains(const std::vector<int>& v, int id) { return std::find(v.begin(), v.end(), id) != v.end(); }

}  // namespace

// ------------------------------------------------------------------ names

const char* to_string(GameKind kind) {
  switch (kind) {
    case GameKind::nine_ball: return "nine_ball";
    case GameKind::eight_ball: return "eight_ball";
    case GameKind::ten_ball: return "ten_ball";
    case GameKind::snooker: return "snooker";
    case GameKind::three_cushion: return "three_cushion";
  }
  return "?";
}
std::optional<GameKind> game_kind_from_string(std::string_view name) { return value_named(kGameKinds, name); }
std::string game_kind_names() { return names_of(kGameKinds, ""); }

const char* to_string(Decision d) {
  switch (d) {
    case Decision::play: return "play";
    case Decision::pass: return "pass";
    case Decision::rerack_and_break: return "rerack_and_break";
    case Decision::rerack_opponent_breaks: return "rerack_opponent_breaks";
    case Decision::respot_eight: return "respot_eight";
    case Decision::rerack: return "rerack";
    case Decision::restore: return "restore";
  }
  return "?";
}
std::optional<Decision> decision_from_string(std::string_view name) { return value_named(kDecisions, name); }
std::string decision_names() { return names_of(kDecisions, ""); }

const char* to_string(GamePhase p) {
  switch (p) {
    case GamePhase::break_shot: return "break";
    case GamePhase::play: return "play";
    case GamePhase::decision: return "decision";
    case GamePhase::over: return "over";
  }
  return "?";
}

const char* to_string(Group g) {
  switch (g) {
    case Group::none: return "none";
    case Group::solids: return "solids";
    case Group::stripes: return "stripes";
  }
  return "?";
}

const char* to_string(Foul f) {
  switch (f) {
    case Foul::scratch: return "scratch";
    case Foul::wrong_ball_first: return "wrong_ball_first";
    case Foul::no_contact: return "no_contact";
    case Foul::no_rail_after_contact: return "no_rail_after_contact";
    case Foul::illegal_break: return "illegal_break";
    case Foul::ball_off_table: return "ball_off_table";
    case Foul::wrong_pocket: return "wrong_pocket";
    case Foul::cue_ball_not_out_of_kitchen: return "cue_ball_not_out_of_kitchen";
    case Foul::bad_cue_ball: return "bad_cue_ball";
    case Foul::miscue: return "miscue";
  }
  return "?";
}

// ------------------------------------------------------------------ config

GameConfig default_config(GameKind kind) {
  GameConfig c;
  c.kind = kind;
  switch (kind) {
    case GameKind::nine_ball:
    case GameKind::eight_ball:
    case GameKind::ten_ball:
      c.table = "pool_9ft";
      c.rack.gap_sigma = kDefaultRackGapSigma;
      break;
    case GameKind::snooker:
      c.table = "snooker_12ft";
      c.max_shots = 2000;  // a frame takes more shots than a rack
      break;
    case GameKind::three_cushion:
      c.table = "carom_10ft";
      c.max_shots = 2000;
      break;
  }
  return c;
}

void validate(const GameConfig& config) {
  if (std::find(kGameKinds.begin(), kGameKinds.end(), config.kind) == kGameKinds.end())
    throw InvalidArgument("kind", "unknown game; allowed: " + game_kind_names());
  (void)preset_table_spec(config.table);  // InvalidArgument("preset", ...) for an unknown name
  validate(config.rack);
  validate(config.noise);
  if (config.max_shots < 1 || config.max_shots > 100000)
    throw InvalidArgument("max_shots", num(config.max_shots) + " is out of range [1, 100000]");
  if (config.fouls_to_lose != 0 && (config.fouls_to_lose < 2 || config.fouls_to_lose > 10))
    throw InvalidArgument("fouls_to_lose", num(config.fouls_to_lose) + " is out of range: 0 (off) or [2, 10]");
  if (config.reds != 6 && config.reds != 10 && config.reds != 15)
    throw InvalidArgument("reds", num(config.reds) + " is not one of 6, 10, 15");
  if (config.race_to < 1 || config.race_to > 1000)
    throw InvalidArgument("race_to", num(config.race_to) + " is out of range [1, 1000]");
  if (config.break_scratch_region != PlacementRegion::Kind::behind_head_string &&
      config.break_scratch_region != PlacementRegion::Kind::anywhere)
    throw InvalidArgument("break_scratch_region", std::string(to_string(config.break_scratch_region)) +
                                                      " is not one of behind_head_string, anywhere");
}

// ------------------------------------------------------------------ state

int GameState::cue_ball() const {
  if (config.kind == GameKind::three_cushion) return to_shoot == 0 ? 0 : 1;
  return 0;
}

bool operator==(const GameState& a, const GameState& b) {
  auto same_balls = [](const std::vector<SimulationBall>& x, const std::vector<SimulationBall>& y) {
    if (x.size() != y.size()) return false;
    for (std::size_t i = 0; i < x.size(); ++i)
      if (x[i].id != y[i].id || x[i].name != y[i].name || x[i].state.position.x != y[i].state.position.x ||
          x[i].state.position.y != y[i].state.position.y)
        return false;
    return true;
  };
  auto same_region = [](const std::optional<PlacementRegion>& x, const std::optional<PlacementRegion>& y) {
    if (x.has_value() != y.has_value()) return false;
    if (!x) return true;
    return x->kind == y->kind && x->x_min == y->x_min && x->x_max == y->x_max && x->y_min == y->y_min &&
           x->y_max == y->y_max;
  };
  return a.config.kind == b.config.kind && a.config.table == b.config.table && a.table.table == b.table.table &&
         same_balls(a.table.balls, b.table.balls) && a.phase == b.phase && a.to_shoot == b.to_shoot &&
         a.breaker == b.breaker && same_region(a.ball_in_hand, b.ball_in_hand) &&
         a.cue_must_leave_kitchen == b.cue_must_leave_kitchen && a.scores == b.scores &&
         a.fouls_in_a_row == b.fouls_in_a_row && a.on == b.on && a.groups == b.groups && a.decisions == b.decisions &&
         a.push_out_available == b.push_out_available && a.free_ball == b.free_ball &&
         a.misses_in_a_row == b.misses_in_a_row && a.colour_on == b.colour_on &&
         same_balls(a.before_miss, b.before_miss) && a.shots == b.shots && a.inning_points == b.inning_points &&
         a.over == b.over && a.winner == b.winner && a.truncated == b.truncated && a.end_reason == b.end_reason;
}

std::vector<int> object_balls(const GameState& state) {
  std::vector<int> out;
  for (const SimulationBall& b : state.table.balls) {
    const bool cue = state.config.kind == GameKind::three_cushion ? b.id == 0 || b.id == 1 : b.id == 0;
    if (!cue) out.push_back(b.id);
  }
  return out;
}

// ------------------------------------------------------------------ shared helpers (rules.hpp)

std::vector<SimulationBall> balls_at_rest(const std::vector<PlacedBall>& placed) {
  std::vector<SimulationBall> balls;
  for (const PlacedBall& p : placed) {
    SimulationBall b;
    b.id = p.id;
    b.name = p.name;
    b.state.position = p.position;
    balls.push_back(std::move(b));
  }
  return balls;
}

void put_ball(Scenario& table, int id, Vec2 position) {
  const std::size_t i = index_of(table.balls, id);
  if (i < table.balls.size()) {
    table.balls[i].state = BallState{};
    table.balls[i].state.position = position;
    return;
  }
  SimulationBall b;
  b.id = id;
  b.name = id == 0 ? "cue" : std::to_string(id);
  b.state.position = position;
  table.balls.push_back(std::move(b));
  // Keep the balls in id order, as the racks give them (the cue ball first).
  std::stable_sort(table.balls.begin(), table.balls.end(),
                   [](const SimulationBall& x, const SimulationBall& y) { return x.id < y.id; });
}

bool on_table(const Scenario& table, int id) { return find_ball(table.balls, id) != nullptr; }

LegalActions base_legal_actions(const GameState& state) {
  LegalActions a;
  a.player = state.to_shoot;
  a.cue_ball = state.cue_ball();
  a.shoot = state.phase != GamePhase::decision;
  if (!a.shoot) {
    a.decisions = state.decisions;
    return a;
  }
  a.on = state.on;
  a.ball_in_hand = state.ball_in_hand;
  a.cue_must_leave_kitchen = state.cue_must_leave_kitchen;
  return a;
}

Scenario table_after_shot(const ShotContext& shot) { return table_after(shot.shot, shot.after); }

void end_game(GameState& next, Ruling& ruling, int winner, std::string reason) {
  next.over = true;
  next.phase = GamePhase::over;
  next.winner = winner;
  next.decisions.clear();
  next.ball_in_hand.reset();
  next.end_reason = reason;
  ruling.game_over = true;
  ruling.winner = winner;
  ruling.turn_over = true;
  if (!ruling.reason.empty()) ruling.reason += "; ";
  ruling.reason += std::move(reason);
}

// ------------------------------------------------------------------ dispatch

GameState new_game(const GameConfig& config, std::uint64_t seed) {
  validate(config);
  GameState base;
  base.config = config;
  if (config.rack.gap_sigma > 0.0) base.config.rack.seed = seed;
  base.table.table = preset_table(config.table);
  base.table.settings.parameters = default_parameters(base.table.table);
  switch (config.kind) {
    case GameKind::nine_ball: return nine_ball_new_game(std::move(base));
    case GameKind::eight_ball: return eight_ball_new_game(std::move(base));
    case GameKind::ten_ball: return ten_ball_new_game(std::move(base));
    case GameKind::snooker: return snooker_new_game(std::move(base));
    case GameKind::three_cushion: return three_cushion_new_game(std::move(base));
  }
  throw InvalidArgument("kind", "unknown game");
}

LegalActions legal_actions(const GameState& state) {
  if (state.over) {
    LegalActions none;
    none.player = state.to_shoot;
    none.cue_ball = state.cue_ball();
    none.shoot = false;
    return none;
  }
  switch (state.config.kind) {
    case GameKind::nine_ball: return nine_ball_legal_actions(state);
    case GameKind::eight_ball: return eight_ball_legal_actions(state);
    case GameKind::ten_ball: return ten_ball_legal_actions(state);
    case GameKind::snooker: return snooker_legal_actions(state);
    case GameKind::three_cushion: return three_cushion_legal_actions(state);
  }
  throw InvalidArgument("kind", "unknown game");
}

namespace {

Judgement judge_shot(const ShotContext& shot) {
  switch (shot.before.config.kind) {
    case GameKind::nine_ball: return nine_ball_judge_shot(shot);
    case GameKind::eight_ball: return eight_ball_judge_shot(shot);
    case GameKind::ten_ball: return ten_ball_judge_shot(shot);
    case GameKind::snooker: return snooker_judge_shot(shot);
    case GameKind::three_cushion: return three_cushion_judge_shot(shot);
  }
  throw InvalidArgument("kind", "unknown game");
}

Judgement decide(const GameState& state, Decision d) {
  switch (state.config.kind) {
    case GameKind::nine_ball: return nine_ball_decide(state, d);
    case GameKind::eight_ball: return eight_ball_decide(state, d);
    case GameKind::ten_ball: return ten_ball_decide(state, d);
    case GameKind::snooker: return snooker_decide(state, d);
    case GameKind::three_cushion: return three_cushion_decide(state, d);
  }
  throw InvalidArgument("kind", "unknown game");
}

// ------------------------------------------------------------------ validating an action

void validate_strike(const ShotAction& s) {
  if (!(s.speed > 0.0 && s.speed <= kMaxCueSpeedInAction))
    throw InvalidArgument("speed", num(s.speed) + " m/s is out of range (0, 12]");
  if (!(std::abs(s.aim_deg) <= 360.0)) throw InvalidArgument("aim_deg", num(s.aim_deg) + " is out of range [-360, 360]");
  if (!(s.elevation_deg >= 0.0 && s.elevation_deg <= kMaxElevationDeg))
    throw InvalidArgument("elevation_deg", num(s.elevation_deg) + " is out of range [0, 89]");
  if (!(std::abs(s.side) <= kMaxTipOffset)) throw InvalidArgument("side", num(s.side) + " is out of range [-0.5, 0.5]");
  if (!(std::abs(s.height) <= kMaxTipOffset))
    throw InvalidArgument("height", num(s.height) + " is out of range [-0.5, 0.5]");
  if (std::hypot(s.side, s.height) > kMaxTipOffset)
    throw InvalidArgument("side", "tip offset sqrt(side^2 + height^2) = " + num(std::hypot(s.side, s.height)) +
                                      " is beyond the miscue limit 0.5");
}

void validate_placement(const GameState& state, const LegalActions& legal, const Action& action) {
  const int cue = legal.cue_ball;
  if (!legal.ball_in_hand) {
    if (action.place)
      throw InvalidArgument("place", "the cue ball is not in hand: it is played from where it lies");
    return;
  }
  if (!action.place) {
    if (!on_table(state.table, cue))
      throw InvalidArgument("place", "the cue ball is in hand (" + std::string(to_string(legal.ball_in_hand->kind)) +
                                         ") and off the table: give its spot");
    return;  // left where it lies (the break's spot, or after a foul that left it on the table)
  }
  const Vec2 p = *action.place;
  const Table& t = state.table.table;
  if (!std::isfinite(p.x) || !std::isfinite(p.y))
    throw InvalidArgument("place", "the spot must be finite");
  if (!in_region(t, *legal.ball_in_hand, p))
    throw InvalidArgument("place", "(" + num(p.x) + ", " + num(p.y) + ") is outside the region " +
                                       to_string(legal.ball_in_hand->kind));
  std::vector<Vec2> others;
  for (const SimulationBall& b : state.table.balls)
    if (b.id != cue) others.push_back(b.state.position);
  if (!is_free_spot(t, others, p, t.ball.radius))
    throw InvalidArgument("place", "(" + num(p.x) + ", " + num(p.y) +
                                       ") is not a free spot: on a ball, off the bed or over a pocket");
}

void validate_call(const GameState& state, const LegalActions& legal, const Action& action) {
  if (!legal.call_required) {
    if (action.called_ball || action.called_pocket)
      throw InvalidArgument(action.called_ball ? "called_ball" : "called_pocket", "no call is needed for this shot");
    return;
  }
  if (!action.called_ball) throw InvalidArgument("called_ball", "this shot needs a called ball; allowed: " + ids(legal.callable));
  if (!contains(legal.callable, *action.called_ball))
    throw InvalidArgument("called_ball", std::to_string(*action.called_ball) + " may not be called; allowed: " +
                                             ids(legal.callable));
  const int pockets = static_cast<int>(state.table.table.pockets.size());
  if (!action.called_pocket) throw InvalidArgument("called_pocket", "this shot needs a called pocket");
  if (*action.called_pocket < 0 || *action.called_pocket >= pockets)
    throw InvalidArgument("called_pocket", std::to_string(*action.called_pocket) + " is out of range [0, " +
                                               std::to_string(pockets - 1) + "]");
}

}  // namespace

void validate_action(const GameState& state, const Action& action) {
  if (state.over) throw InvalidArgument("action", "the game is over (" + state.end_reason + ")");
  const LegalActions legal = legal_actions(state);
  if (action.decision) {
    if (std::find(legal.decisions.begin(), legal.decisions.end(), *action.decision) == legal.decisions.end()) {
      std::string open;
      for (const Decision d : legal.decisions) open += (open.empty() ? "" : ", ") + std::string(to_string(d));
      throw InvalidArgument("decision", std::string(to_string(*action.decision)) + " is not open; open: " +
                                            (open.empty() ? "none (a shot is due)" : open));
    }
    return;
  }
  if (!legal.shoot) {
    std::string open;
    for (const Decision d : legal.decisions) open += (open.empty() ? "" : ", ") + std::string(to_string(d));
    throw InvalidArgument("decision", "a decision is due before the next shot; open: " + open);
  }
  validate_strike(action.strike);
  validate_placement(state, legal, action);
  validate_call(state, legal, action);
  if (action.push_out && !legal.push_out)
    throw InvalidArgument("push_out", "a push-out is only allowed on the shot after the break (WPA 2.4)");
  if (legal.nominate_required && !action.nominate)
    throw InvalidArgument("nominate", "nominate the ball on; allowed: " + ids(legal.nominable));
  if (action.nominate && !contains(legal.nominable, *action.nominate))
    throw InvalidArgument("nominate", std::to_string(*action.nominate) + " may not be nominated; allowed: " +
                                          ids(legal.nominable));
  if (action.aim_at) {
    if (*action.aim_at == legal.cue_ball || !on_table(state.table, *action.aim_at))
      throw InvalidArgument("aim_at", std::to_string(*action.aim_at) + " is not an object ball on the table");
  }
}

// ------------------------------------------------------------------ playing a shot

namespace {

// Everything one shot needs, filled by the steps below in order.
struct ShotRun {
  const GameState& state;
  const Action& action;
  std::uint64_t seed = 0;
  int cue_ball = 0;
  Scenario shot;
  std::optional<CueStrike> played;
  bool miscue = false;
  SimulationResult result;
  ShotFacts facts;
  std::vector<BallAfterShot> after;
  std::string failure;  // the simulator's bound, when reached
};

// Step 1: the table as struck: the cue ball placed when in hand.
void set_table(ShotRun& run) {
  run.shot = run.state.table;
  run.shot.cue.reset();
  if (run.action.place) put_ball(run.shot, run.cue_ball, *run.action.place);
}

// Step 2: the strike as played: aimed, with the config's execution noise
// drawn from the seed (the same draws as shot 0 of a batch seeded so,
// batch.hpp), reflected into the limits; beyond the miscue limit nothing is
// struck.
void strike(ShotRun& run) {
  const double radius = run.shot.table.ball.radius;
  ShotAction a = run.action.strike;
  if (run.action.aim_at) {
    const Vec2 from = run.shot.balls[index_of(run.shot.balls, run.cue_ball)].state.position;
    const Vec2 to = run.shot.balls[index_of(run.shot.balls, *run.action.aim_at)].state.position;
    a.aim_deg = std::atan2(to.y - from.y, to.x - from.x) / kDeg;
  }
  CueStrike s = to_strike(a, radius);
  const CueStrikeNoise& sigma = run.state.config.noise;
  if (sigma.speed > 0 || sigma.aim > 0 || sigma.elevation > 0 || sigma.side_offset > 0 || sigma.height_offset > 0)
    s = reflect_into_limits(with_noise(s, sigma, shot_normals(run.seed, 0))).strike;
  run.played = s;
  run.miscue = !cue_tip_offset_ok(s, run.shot.table.ball);
  ShotStrike cue;
  cue.ball = run.cue_ball;
  cue.strike = s;
  run.shot.cue = cue;
}

// Step 3: the simulation; a shot beyond the simulator's bound is reported,
// not thrown.
void simulate_shot(ShotRun& run) {
  if (run.miscue) {
    Scenario still = run.shot;
    still.cue.reset();
    run.result = simulate(still.table, still.balls, still.settings);
  } else {
    try {
      run.result = run_scenario(run.shot);
    } catch (const SimulationError& e) {
      run.failure = e.what();
      return;
    }
  }
  run.facts = shot_facts(run.shot.table, run.shot.settings.parameters, run.result, run.cue_ball);
  run.after = balls_after_shot(run.result);
}

// Step 4: the discipline's judgement, or the truncation a failed shot causes.
Judgement judge(const ShotRun& run) {
  if (!run.failure.empty()) {
    Judgement j{{}, run.state};
    j.next.over = true;
    j.next.phase = GamePhase::over;
    j.next.truncated = true;
    j.next.end_reason = "truncated: the shot reached the simulator's bound (" + run.failure + ")";
    j.ruling.game_over = true;
    j.ruling.truncated = true;
    j.ruling.reason = j.next.end_reason;
    return j;
  }
  const ShotContext context{run.state, run.action, run.state.to_shoot, run.cue_ball, run.shot,
                            run.result, run.facts,  run.after,          run.miscue};
  Judgement j = judge_shot(context);
  j.ruling.push_out = j.ruling.push_out || run.action.push_out;
  return j;
}

// Step 5: the bound on shots.
void count_shot(GameState& next, Ruling& ruling) {
  next.shots += 1;
  if (!next.over && next.shots >= next.config.max_shots) {
    next.over = true;
    next.phase = GamePhase::over;
    next.truncated = true;
    next.decisions.clear();
    next.end_reason = "truncated: " + std::to_string(next.config.max_shots) + " shots played (max_shots)";
    ruling.game_over = true;
    ruling.truncated = true;
    ruling.reason += (ruling.reason.empty() ? "" : "; ") + next.end_reason;
  }
}

}  // namespace

namespace {

// The legal Action of a foul stroke (play_foul_stroke): the cue ball's
// spot, the call and the nomination the rules ask for.
Action foul_stroke_action(const GameState& state, const LegalActions& legal, std::optional<Vec2> place,
                          std::uint64_t seed) {
  Action a;
  a.strike.speed = 1.0;
  if (legal.ball_in_hand) {
    const Table& t = state.table.table;
    std::vector<Vec2> others;
    for (const SimulationBall& b : state.table.balls)
      if (b.id != legal.cue_ball) others.push_back(b.state.position);
    if (place && std::isfinite(place->x) && std::isfinite(place->y) && in_region(t, *legal.ball_in_hand, *place) &&
        is_free_spot(t, others, *place, t.ball.radius))
      a.place = place;
    else if (!on_table(state.table, legal.cue_ball)) {
      RandomStream rng(seed);
      a.place = random_free_spot(t, others, t.ball.radius, rng, 10000, *legal.ball_in_hand);
      if (!a.place) throw SimulationError("no free spot for the cue ball in hand");
    }
  }
  if (legal.call_required) {
    a.called_ball = legal.callable.empty() ? std::optional<int>{} : legal.callable.front();
    a.called_pocket = 0;
  }
  if (legal.nominate_required && !legal.nominable.empty()) a.nominate = legal.nominable.front();
  return a;
}

// Step 6: the shot's GameStep, the bound on shots counted.
GameStep shot_step(const Action& action, ShotRun& run, Judgement j) {
  count_shot(j.next, j.ruling);
  GameStep step;
  step.action = action;
  step.played = run.played;
  step.shot = std::move(run.shot);
  step.result = std::move(run.result);
  step.facts = std::move(run.facts);
  step.ruling = std::move(j.ruling);
  step.next = std::move(j.next);
  return step;
}

}  // namespace

GameStep play_foul_stroke(const GameState& state, std::optional<Vec2> place, std::uint64_t seed,
                          const std::string& why) {
  if (state.over) throw InvalidArgument("action", "the game is over (" + state.end_reason + ")");
  const LegalActions legal = legal_actions(state);
  if (!legal.shoot) throw InvalidArgument("action", "a decision is due: a foul stroke needs a shot");
  const Action action = foul_stroke_action(state, legal, place, seed);
  ShotRun run{state, action, seed, state.cue_ball(), {}, {}, true, {}, {}, {}, {}};
  set_table(run);
  simulate_shot(run);
  Judgement j = judge(run);
  j.ruling.reason = why + (j.ruling.reason.empty() ? "" : "; ") + j.ruling.reason;
  return shot_step(action, run, std::move(j));
}

GameStep play(const GameState& state, const Action& action, std::uint64_t seed) {
  validate_action(state, action);
  GameStep step;
  step.action = action;
  if (action.decision) {
    Judgement j = decide(state, *action.decision);
    count_shot(j.next, j.ruling);
    step.shot = state.table;
    step.ruling = std::move(j.ruling);
    step.next = std::move(j.next);
    return step;
  }
  ShotRun run{state, action, seed, state.cue_ball(), {}, {}, false, {}, {}, {}, {}};
  set_table(run);
  strike(run);
  simulate_shot(run);
  return shot_step(action, run, judge(run));
}

}  // namespace cueball
