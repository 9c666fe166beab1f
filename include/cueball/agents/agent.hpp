// Players: each agent chooses an Action for a GameState from its
// legal_actions() (games/game.hpp), deterministically for a seed.
//
//   Action a = choose_action(AgentOptions{AgentKind::planner}, state, seed);
//
// One file per agent in src/agents/, chosen by AgentKind in agent.cpp:
//   random        any legal action, uniformly drawn (a baseline and the
//                 rules' stress test);
//   ghost_ball    ghost-ball aiming at the easiest clear pot of a ball on,
//                 no simulation (the planner benchmark's baseline);
//   planner       plan_shot (planning/shot_planner.hpp) over the legal
//                 targets, with position play, ball-in-hand placement,
//                 calls, nominations, a kick when nothing pots, and the
//                 decisions by a documented simple policy;
//   carom_search  three-cushion: searches strikes with the engine for a
//                 point (a simple search; the strong one is issue 27's);
//   safety_planner the planner, and when no pot is likely enough a safety:
//                 the legal strike that leaves the opponent the least
//                 (safety.cpp; its decisions by the same estimate).
//
// What the pool agents share (agent.cpp), so that every pocket game is
// played through legal_actions() alone:
//   - the break: break_action(), a fixed strong break (a small named
//     function, to be swapped for a better one);
//   - the decisions: decision_by_policy(), one documented simple policy;
//   - the balls a shot may aim at: shot_targets() (the balls on; when a
//     ball must be nominated, the nominable ones; when a call is needed, the
//     callable balls on; when the cue ball must leave the kitchen, those
//     beyond the head string);
//   - a plain hit of a ball on when nothing pots: safe_hit().
// The ghost-ball agent (ghost_ball.cpp) adds the ghost-ball aim and its
// in-hand rule; the planner agent (planner_agent.cpp) plan_shot, position
// play and plan_ball_in_hand. Neither plays three-cushion: there they hand
// the decision to carom_search_action().
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cueball/games/game.hpp"
#include "cueball/games/record.hpp"
#include "cueball/planning/ghost_ball.hpp"
#include "cueball/planning/position_play.hpp"
#include "cueball/planning/shot_planner.hpp"

namespace cueball {

enum class AgentKind : char { random, ghost_ball, planner, carom_search, safety_planner };

/// "random", "ghost_ball", "planner", "carom_search", "safety_planner".
const char* to_string(AgentKind kind);
std::optional<AgentKind> agent_kind_from_string(std::string_view name);
std::string agent_kind_names();

struct AgentOptions {
  AgentKind kind = AgentKind::planner;
  /// Engine runs of each plan (planner: PlanRequest::simulations; a plan
  /// for position or in hand spends more, position_play.hpp and
  /// ball_in_hand.hpp say how much), or of a decision (carom_search).
  int simulations = 2000;
  /// A wall-clock budget of a decision, s, [0, 3600]; 0 (the default):
  /// `simulations` alone sets the effort. Otherwise (planner,
  /// safety_planner, carom_search) the decision is planned in rounds at
  /// doubling budgets, kFirstTimedRoundSimulations runs a plan (or
  /// `simulations` when smaller), then twice that, ... up to `simulations`
  /// (position_simulations scaled with them, never below
  /// kMinPlanSimulations), each round only while the one before it says,
  /// by its own time scaled to the next round's runs, that it will end
  /// within `seconds` of the decision's start (fewer than twice the runs
  /// where only those fit, at least a quarter more); the last round's
  /// action is played. The first round always runs, so a decision can take
  /// longer than `seconds` when even that round does not fit. Budget in
  /// seconds or in runs, whichever runs out first (issue 27). The rounds played
  /// depend on the machine's speed: the reasoning's summary ends with them
  /// ("seconds 0.5: 3 rounds in 0.41 s, played at 2000 runs"), and the same
  /// options with those `simulations` and no `seconds` replay the decision
  /// exactly (timed_round_options()). A break is played as without it.
  double seconds = 0.0;
  /// Engine runs of each next-shot plan in position play (planner; 0: no
  /// position play); carom_search: of the next point's search on each
  /// finalist's leave, at most `simulations` (src/agents/carom_search.cpp).
  int position_simulations = 0;
  /// Position play: the noisy outcomes of each finalist whose leaves are
  /// scored (PositionRequest::noisy_leaves; 0: the noise-free leave alone).
  int position_noisy_leaves = kPositionNoisyLeaves;
  /// Position play: the noisy repeats of every candidate whose leaves are
  /// valued before the finalists are chosen
  /// (PositionRequest::candidate_noisy_leaves; 0: the noise-free leave alone).
  int position_candidate_noisy_leaves = 0;
  /// Position play: shots looked ahead (PositionRequest::depth), [1, kMaxPositionDepth].
  int position_depth = 1;
  /// Position play and ball in hand: how a leave is valued
  /// (PositionRequest::valuation).
  LeaveValuation position_valuation = LeaveValuation::windows;
  /// Position play: the finalists screened under noise (PositionRequest::finalists).
  int position_finalists = kPositionFinalists;
  /// Position play: the feasible shots whose spin and speed variants are
  /// candidate leaves (PositionRequest::varied_shots).
  int position_varied_shots = kPositionVariedShots;
  /// The execution noise the agent plans under (planner). None: the game's
  /// (GameConfig::noise), or tournament_noise() when the game has none (a
  /// plan under no noise cannot tell a safe pot from a thin one).
  std::optional<CueStrikeNoise> noise;
  /// The shot kinds the planner tries first (PlanRequest::kinds).
  std::vector<ShotKind> kinds{ShotKind::direct, ShotKind::bank};
  /// The kinds it asks for when none of `kinds` pots a ball on (the same
  /// decision planned again, the same seed); empty: none. The default: a
  /// kick when nothing else pots. Only when these fail too does it play
  /// safe_hit().
  std::vector<ShotKind> fallback_kinds{ShotKind::kick};
  /// 9-ball and 10-ball (planner, safety_planner): also plan the game ball
  /// by a combination through the ball on (plan_game_ball_combination()),
  /// played instead of the pot of the ball on where its chance beats that
  /// pot's run-out chance (run_out_chance()); and with position play by
  /// the ghost ball, value each leave by that combination too
  /// (PositionRequest::game_ball, later_shot_chance kRunOutShotChance).
  bool game_ball_combinations = false;
};

/// Throws InvalidArgument naming the field ("simulations", ...).
void validate(const AgentOptions& options);

/// AgentOptions::seconds: the runs a plan of the first timed round, and the
/// longest budget a decision may have.
inline constexpr int kFirstTimedRoundSimulations = 500;
inline constexpr double kMaxAgentSeconds = 3600.0;
/// The options of a timed decision's round at `simulations` runs a plan:
/// `options` with those simulations, position_simulations scaled by
/// simulations / options.simulations (at least kMinPlanSimulations when
/// position play is on, at most position_simulations), and seconds 0.
AgentOptions timed_round_options(const AgentOptions& options, int simulations);
/// What a decision under AgentOptions::seconds did.
struct TimedRounds {
  double budget = 0.0;   ///< AgentOptions::seconds
  int rounds = 0;
  int simulations = 0;   ///< the runs a plan of the last round, whose result is played
  double seconds = 0.0;  ///< wall-clock time of all the rounds
  /// "seconds 0.5: 3 rounds in 0.41 s, played at 2000 runs"
  std::string summary() const;
};
/// The rounds of AgentOptions::seconds: round(timed_round_options(options,
/// b)) for b = min(simulations, kFirstTimedRoundSimulations), 2b, 4b, ...
/// up to options.simulations, each while the one before says it fits (the
/// last one at what fits, when that is 1.25 b to 2 b); the
/// caller keeps the last round's result. choose() uses it; so can a caller
/// that plans with planner_choice() itself (the planner benchmark).
TimedRounds plan_in_time(const AgentOptions& options, const std::function<void(const AgentOptions&)>& round);

/// The strongest pool player of the agents (issue 27), and what the
/// planner benchmark's run-out suite measures by default: the safety
/// planner with each pot planned at kStrongestSimulations runs, played for
/// position with each leave valued by its ghost-ball chance
/// (LeaveValuation::ghost_ball) over kStrongestNoisyLeaves noisy leaves of
/// each of kStrongestFinalists finalists, the finalists chosen with every
/// candidate's leave valued over kStrongestCandidateNoisyLeaves noisy
/// outcomes besides the noise-free one, the candidates the spin and speed
/// variants of the kStrongestVariedShots best shots, kStrongestDepth shots deep (the next pot's strokes played
/// once each, the ball after it valued by its ghost-ball chance), a kick
/// when nothing else pots, the game ball by a combination through the ball
/// on where that beats the run-out (game_ball_combinations); three-cushion:
/// carom_search at the same budget, without position play (which did not
/// gain at equal runs). The ghost-ball valuation ran out as many 9-ball
/// racks as the planner's window search (36 and 31 of 90) and played it
/// even (18-22 in 40 games), at a quarter of the time a decision
/// (docs/planner-benchmark.md, "Leaves valued by the ghost ball"); two
/// shots deep, with the pockets' windows, it ran out 0.448 of 540 racks
/// against 0.400 one shot deep with one tolerance for every pocket
/// (docs/planner-benchmark.md, "The pocket's window, and two shots ahead");
/// with the candidates' noisy leaves, 0.546 of the same racks against 0.480
/// without (docs/planner-benchmark.md, "Every candidate's leave valued under
/// the noise"); with 6 finalists of the variants of 6 shots instead of 3 of
/// 3, 0.591 against 0.546 (docs/planner-benchmark.md, "More shots varied,
/// more finalists"); with the game ball by a combination, 1,394 of 2,340
/// racks not tuned on against 1,308 (docs/planner-benchmark.md, "The game
/// ball by a combination"); with each leave valued by that combination too,
/// 1,457 of them (0.623) against 1,394, and 2,070 of 3,420 with two fresh
/// sets (0.605; docs/planner-benchmark.md, "A leave that sets up the game
/// ball's combination").
/// kStrongestPositionSimulations, the runs of a next-shot plan, are spent
/// only with the windows valuation; position play is on while they are > 0.
inline constexpr int kStrongestSimulations = 4000;
inline constexpr int kStrongestPositionSimulations = 1000;
inline constexpr int kStrongestNoisyLeaves = 16;
inline constexpr int kStrongestCandidateNoisyLeaves = 8;
inline constexpr int kStrongestDepth = 2;
inline constexpr int kStrongestFinalists = 6;
inline constexpr int kStrongestVariedShots = 6;
AgentOptions strongest_agent();

/// An agent by the name a user gives (the CLI's --players, Python's
/// opponents): an AgentKind's name (agent_kind_names(), its default
/// options) or "strongest" (strongest_agent()). None for another name.
std::optional<AgentOptions> agent_named(std::string_view name);
/// The names agent_named() takes, comma-separated.
std::string agent_names();

/// The agent's action for the player to act in `state` (a game not over).
/// Always legal: play(state, choose_action(...), s) never throws
/// InvalidArgument for it.
Action choose_action(const AgentOptions& options, const GameState& state, std::uint64_t seed);

/// An action and why (games/record.hpp's Reasoning): the planner agents
/// give the shot planned, its estimates and the alternatives they weighed,
/// or the decision and the estimate behind it; carom_search its search's
/// outcome; the ghost-ball and random agents none (they weigh nothing).
struct AgentChoice {
  Action action;
  Reasoning reasoning;
};
/// choose_action() with its reasoning (the same action for the same seed).
AgentChoice choose(const AgentOptions& options, const GameState& state, std::uint64_t seed);

// The agents, one file each (src/agents/<agent>.cpp).
Action random_action(const GameState& state, std::uint64_t seed);
Action ghost_ball_action(const GameState& state, std::uint64_t seed);
Action planner_action(const AgentOptions& options, const GameState& state, std::uint64_t seed);
Action carom_search_action(const AgentOptions& options, const GameState& state, std::uint64_t seed);
Action safety_planner_action(const AgentOptions& options, const GameState& state, std::uint64_t seed);

/// What carom_search found, for tests and benchmarks: its action, the
/// engine runs it spent (never more than options.simulations without
/// position play; with it, options.position_simulations > 0, at most
/// kCaromPositionFinalists x (min(position_simulations, simulations) + 1) more:
/// src/agents/carom_search.cpp), whether the action scores noise-free, the
/// share of its noisy repeats that scored, and with position play the next
/// point's rate on the table it leaves (-1: not looked at).
/// carom_search's position play: the points whose leaves are searched.
inline constexpr std::size_t kCaromPositionFinalists = 3;
struct CaromSearchResult {
  Action action;
  int simulations = 0;
  bool point = false;
  int noisy_points = 0;
  int noisy_tries = 0;
  double next_point_rate = -1.0;
};
CaromSearchResult carom_search(const AgentOptions& options, const GameState& state, std::uint64_t seed);

// ------------------------------------------------------------------ shared by the pool agents (agent.cpp)

/// The break (GamePhase::break_shot): recommended_break()
/// (games/break_shot.hpp), the opening shot measured best for each
/// discipline (docs/break.md), the same for every seed.
Action break_action(const GameState& state);
/// Whether the planner agents play break_action() in `state` (its legal
/// actions `legal`): a pool or snooker break with no call or nomination
/// due (three-cushion's opening is searched by carom_search).
bool plays_break_action(const GameState& state, const LegalActions& legal);

/// The decision policy both pool agents follow, given whether the table as
/// it stands is good for the player deciding (`table_good`: the agent would
/// pot a ball from it; what that means is each agent's):
///   good: play; else respot_eight (8-ball, the 8 on the break: play on);
///   not good: restore (snooker miss: the offender plays again), else
///   rerack_and_break (8-ball illegal break: break yourself), else rerack,
///   else pass (9-ball, 10-ball push-out or wrongful pot, a foul's table:
///   the opponent shoots);
///   and the first open decision when none of those is open.
/// Throws InvalidArgument("decisions") when `open` is empty.
Decision decision_by_policy(const std::vector<Decision>& open, bool table_good);

/// The balls a shot may aim to pot first (shot_targets), from the legal
/// actions: the nominable balls when a nomination is required (the ball
/// nominated is the ball hit), else the balls on; when a call is required,
/// only the callable ones (none callable: the balls on); when the cue ball
/// must leave the kitchen (WPA 1.6), only those beyond the head string
/// (none: the balls on). Only balls on the table.
std::vector<int> shot_targets(const GameState& state, const LegalActions& legal);

/// A plain hit when nothing pots: the cue ball at the centre of the nearest
/// of `targets` whose straight path is clear (no other ball within two
/// radii of it), else of the nearest target, at kSafeHitSpeed, the lowest
/// clear elevation: it reaches a ball on and drives balls to a rail, so it
/// rarely fouls. `target` is set to the ball aimed at. None: no target on
/// the table (or the cue ball is not on it).
inline constexpr double kSafeHitSpeed = 2.5;
std::optional<ShotAction> safe_hit(const Scenario& table, int cue_ball, const std::vector<int>& targets, int& target);

/// The lowest of the elevations 0, 2, 5, 10, 15, 20, 25, 30 degrees at which
/// the cue, aligned for `action` on the cue ball, is not obstructed
/// (cue_obstructed()); none when it is at all of them.
std::optional<double> lowest_clear_elevation_deg(const Scenario& table, int cue_ball, ShotAction action);

/// The pocket nearest ball `ball` (an index into table.pockets), for calls.
int nearest_pocket(const Scenario& table, int ball);

// ------------------------------------------------------------------ the ghost-ball agent (ghost_ball.cpp)

/// The ghost-ball agent's cue speed, m/s (a medium pace, inside the
/// 1.4-2.3 m/s the planner chose on the planner benchmark's first layouts).
inline constexpr double kGhostBallSpeed = 1.5;
/// Its placement in hand: the cue ball this far behind the ghost ball, m.
inline constexpr double kGhostBallInHandBack = 0.3;

/// A ghost-ball pot: the cue ball aimed at the ghost ball G = O - 2R u of
/// `target` for `pocket` (u from the ball O to the point P it is sent to,
/// GhostBallAim; D. G.
/// Alciatore, "The Illustrated Principles of Pool and Billiards", 2004).
struct GhostBallShot {
  int target = -1;
  int pocket = -1;     ///< index into table.pockets
  ShotAction strike;   ///< centre ball, the given speed, the lowest clear elevation
  double score = 0.0;  ///< cos(cut) / (|CG| |OP|): the geometry's part of the aim tolerance, larger is easier
  double aim_tolerance = 0.0;  ///< rad, GhostBallPot::aim_tolerance: with the pocket's window
};

/// The easiest clear ghost-ball pot of any of `targets` (in their order,
/// then the pockets' order; the first of equal scores): pockets whose cut is
/// at most kMaxCutDeg, whose straight paths C -> G and O -> P are clear of
/// every other ball's centre by two radii, and whose cue clears at one of
/// lowest_clear_elevation_deg()'s elevations, ranked by score, sent at the
/// pocket's centre (GhostBallAim::pocket_centre, the textbook rule). None
/// when no pocket qualifies or the cue ball is not on the table.
std::optional<GhostBallShot> ghost_ball_shot(const Scenario& table, int cue_ball, const std::vector<int>& targets,
                                             double speed = kGhostBallSpeed);

/// The pots sent to the middle of the pockets' windows
/// (GhostBallAim::window_middle), the largest aim tolerance first
/// (ghost_ball_pots()'s order), the first whose cue clears: the likeliest
/// ghost-ball pot, which the safety search's screen reads.
std::optional<GhostBallShot> likeliest_ghost_ball_shot(const Scenario& table, int cue_ball,
                                                       const std::vector<int>& targets,
                                                       double speed = kGhostBallSpeed);

/// The table with the cue ball (id `cue_ball`) placed at `spot`, at rest
/// and first in the ball order: its own parameters when it is on the table,
/// else a ball named "cue". Where an agent places the cue ball in hand.
Scenario with_cue_ball_at(const Scenario& table, int cue_ball, Vec2 spot);

/// The ghost-ball agent's rule for the cue ball in hand: a straight-in on
/// one of `targets`, the cue ball `back` behind the ghost ball on the line
/// from the pocket through the ball (C = O - (2R + back) u), for every
/// target and pocket whose spot is a free spot (is_free_spot(), the other
/// balls but the cue ball) inside `region` and whose paths C -> O and O -> P
/// are clear of the other balls by two radii; the nearest pocket (largest
/// 1 / |OP|, the first of equal ones) wins. None when no spot qualifies.
std::optional<Vec2> ghost_ball_in_hand_spot(const Scenario& table, int cue_ball, const std::vector<int>& targets,
                                            const PlacementRegion& region, double back = kGhostBallInHandBack);

/// ghost_ball_action() for given legal actions (ghost_ball_action(state, seed) passes
/// legal_actions(state); a caller or a test may give its own, e.g. a call
/// or a nomination the state's rules do not ask for yet).
Action ghost_ball_action(const GameState& state, const LegalActions& legal, std::uint64_t seed);

// ------------------------------------------------------------------ the game ball by a combination (game_ball_combination.cpp)

/// The ball whose legal pot wins the rack: 9-ball's 9, 10-ball's 10 (WPA
/// Rules of Play, sections 2 and 9, opening paragraphs); none in the other
/// games.
std::optional<int> game_ball(const GameState& state);

/// The strongest agent's chance of potting a ball on a run-out, measured:
/// 9,567 of the 10,293 shots it played on 1,620 run-out racks
/// (docs/planner-benchmark.md, "The game ball by a combination").
inline constexpr double kRunOutShotChance = 0.93;
/// The chance of running out from a pot of chance `shot` whose leave's
/// value is `next` (the next shots' chances, Leave::next_success_probability),
/// with `shots_after` more pots to make after those, each at
/// kRunOutShotChance: shot x next x kRunOutShotChance^shots_after.
double run_out_chance(double shot, double next, int shots_after);

/// The largest cut of the ball on on the game ball that an in-hand
/// combination spot is offered for, degrees.
inline constexpr double kMaxInHandCombinationCutDeg = 45.0;
/// The in-hand spots whose combination is planned in full.
inline constexpr std::size_t kCombinationInHandSpots = 2;

/// The cue ball's spots in hand for a combination of `target` through
/// `ball_on`: for each pocket, the ball on sent straight at the target's
/// ghost ball (the target's centre less two radii towards the pocket's
/// centre) with the cue ball `back` behind the ball on's own ghost ball on
/// that line (no cut on the ball on), where the ball on's cut on the target
/// is at most kMaxInHandCombinationCutDeg, the spot is a free spot inside
/// `region`, and the three straight paths are clear of the other balls by
/// two radii; the easiest first (the cosine of that cut over the two
/// balls' paths). Empty when none qualifies.
std::vector<Vec2> combination_in_hand_spots(const Scenario& table, int cue_ball, int ball_on, int target,
                                            const PlacementRegion& region, double back = kGhostBallInHandBack);

/// A combination on the game ball planned for the player to act.
struct GameBallCombination {
  PlannedShot shot;           ///< plan_shot()'s, its success probability on fresh draws
  std::optional<Vec2> place;  ///< in hand: the cue ball's spot
};

/// The game ball by a combination through the ball on (9-ball, 10-ball,
/// the game ball on the table and not itself the ball on): plan_shot() of
/// the game ball with PlanRequest::ball_on the ball on, kinds
/// {combination}, a call shot where the rules ask for a call, and `q`'s
/// noise, seed and budget; from where the cue ball lies, or in hand from
/// the first kCombinationInHandSpots of combination_in_hand_spots(), the
/// likeliest kept. None in another game or state, or when nothing is
/// feasible. `simulations` gains the engine runs spent.
std::optional<GameBallCombination> plan_game_ball_combination(const GameState& state, const LegalActions& legal,
                                                              PlanRequest q, long long& simulations);

// ------------------------------------------------------------------ the planner agent (planner_agent.cpp)

/// What the planner agent chose, and why (the benchmark reads it).
struct PlannerChoice {
  enum class Kind : char {
    decision,   ///< a decision (action.decision)
    break_shot, ///< break_action()
    pot,        ///< a planned pot of options.kinds (planned: the plan)
    fallback,   ///< a planned pot of options.fallback_kinds (a kick by default)
    safety,     ///< nothing pots: safe_hit(), announced as a push-out when one is allowed;
                ///< the safety planner's: plan_safety()'s strike (success_probability: its value)
  };
  Action action;
  Kind kind = Kind::safety;
  /// The plan's success probability and, with position play, its leave's
  /// next-shot probability (Leave::next_success_probability, 0 when the
  /// next shot is infeasible); -1 when not planned.
  double success_probability = -1.0;
  double next_success_probability = -1.0;
  /// Engine runs spent (a plan that found nothing counted at its budget).
  long long simulations = 0;
  /// One line: the shot planned ("in hand at (x, y): direct 1 into ..."),
  /// or why nothing potted.
  std::string detail;
  /// The options weighed, the chosen first (the pot's alternatives, with
  /// position play their leaves' next-shot estimates; a safety's candidates).
  std::vector<ConsideredOption> considered;
};

/// The next shots' legal targets after a shot that pots `target`, as
/// PositionRequest::next_targets (position_play.hpp), from the state's
/// rules: 9-ball and 10-ball, each other object ball in id order, one at a
/// time (the lowest is next, and where it drops too, the next lowest); 8-ball,
/// the shooter's group (open table: the group of `target`) then the 8;
/// snooker, after a red the colours on the table, after a colour while reds
/// remain the reds, in the clearance the colours after `target` in order.
/// Only balls on the table other than the cue ball(s); empty sets dropped.
std::vector<std::vector<int>> next_targets(const GameState& state, int target);

/// The noise the planner agents plan under (AgentOptions::noise): the
/// options', else the game's, else tournament_noise() when the game has none.
CueStrikeNoise planning_noise(const AgentOptions& options, const GameState& state);

/// The planner agent's choice (planner_action() is its action): the break;
/// a decision by decision_by_policy() with the table good when the best
/// pot planned from it (plan_shot, options.simulations, the cue ball placed
/// by ghost_ball_in_hand_spot() when in hand) has success probability >=
/// kPlannerGoodTable; else a pot of the shot_targets(): with the cue ball in
/// hand, plan_ball_in_hand() in the legal region (its next-shot plans
/// options.position_simulations runs, kInHandNextSimulations when 0); else
/// with position play (position_simulations > 0) plan_shot_for_position()
/// over next_targets(); else plan_shot(); options.kinds, then
/// options.fallback_kinds; with none feasible, safe_hit() (from
/// ghost_ball_in_hand_spot()'s spot, or a seeded random free spot, when in
/// hand), a push-out when one may be announced. The call is the planned
/// target and pocket (the safety: its ball and nearest pocket), and where
/// the rules ask for one every plan is a call shot (PlanRequest::call_shot:
/// a pot counts only in the shot's own pocket, as the rules score it); the
/// nomination, the planned target. Every plan is seeded with `seed` itself
/// (so a caller's seeds reproduce plan_shot's), the decision's evaluation
/// with stream_seed(seed, 1), a random spot with stream_seed(seed, 2).
inline constexpr double kPlannerGoodTable = 0.5;
inline constexpr int kInHandNextSimulations = 1000;
PlannerChoice planner_choice(const AgentOptions& options, const GameState& state, std::uint64_t seed);
/// The same for given legal actions (as ghost_ball_action()'s overload).
PlannerChoice planner_choice(const AgentOptions& options, const GameState& state, const LegalActions& legal,
                             std::uint64_t seed);

// ------------------------------------------------------------------ safety play (safety.cpp)
//
// A safety (the players' word; WPA 6.3's legal shot that does not try to
// pot): a strike that contacts a ball on first and then sends a ball to a
// rail or into a pocket, chosen to leave the opponent the worst chance.
//
// The opponent's chance is estimated twice. First by a quick screen, no
// engine run: pot_chance(), the best ghost-ball pot of the balls on from the
// table (with ball in hand, from ghost_ball_in_hand_spot()), turned into a
// probability by the ghost-ball aim tolerance (ghost_ball_pot_chance(),
// planning/ghost_ball.hpp: erf(2R w score / (sigma sqrt 2)) under Gaussian
// aim noise sigma, w the pocket's window for the target's direction,
// GhostBallShot::aim_tolerance = 2R w score). Direct pots
// only: a leave that gives a bank counts as safe. Then, for the few
// finalists, by the planner's own quick search: planned_chance(), plan_shot
// (direct and bank, kSafetyReplySimulations runs, the same noise) from the
// table the safety leaves, the cue ball in hand placed as the planner
// agent's decisions place it (ghost_ball_in_hand_spot()), or the ghost-ball
// estimate when that is larger.


/// The chance that the player to act in `state` pots a ball on from the
/// table (decisions due are taken as if the player shoots from the table as
/// it stands; the cue ball in hand placed by ghost_ball_in_hand_spot()),
/// under the aim noise of `noise` (header comment). 0 when no clear direct
/// pot exists; 1 when the noise's aim sigma is 0 and one exists.
double pot_chance(const GameState& state, const CueStrikeNoise& noise);

/// The same chance as the planner would plan it: plan_shot()'s success
/// probability for the shot_targets() of the player to act (kinds direct and
/// bank, kSafetyReplySimulations runs, `noise`, `seed`), from the table as
/// it stands (decisions due taken as play), the cue ball in hand at
/// ghost_ball_in_hand_spot() (no spot: where it lies; 0 when it is off the
/// table), 0 when no ball is on or nothing is feasible; or pot_chance() when
/// that is larger: so small a budget runs out before some direct pots the
/// full planner finds (after the plain hit on test_safety's first hidden
/// layout, a near straight-in: none found at 500 or 1,000 runs, 0.986 at
/// 2,000), as the ghost-ball estimate misses banks. Adds its engine runs to
/// `simulations` (the budget when nothing is feasible). Deterministic for a
/// seed.
inline constexpr int kSafetyReplySimulations = kMinPlanSimulations;
double planned_chance(const GameState& state, const CueStrikeNoise& noise, std::uint64_t seed,
                      long long& simulations);

/// The shooter's value after a shot that led to `next` (`shooter` is the
/// player who played it): 1 or 0 when the game is over with a winner (1/2
/// truncated); else q = pot_chance(next) for the player to act, or, when a
/// decision is due, max(q, 1 - q) (they play or pass, whichever is better
/// for them); that, when the shooter acts next, else 1 minus it.
double value_after_shot(const GameState& next, int shooter, const CueStrikeNoise& noise);
/// The same with q = planned_chance(next, noise, seed, simulations).
double planned_value_after_shot(const GameState& next, int shooter, const CueStrikeNoise& noise, std::uint64_t seed,
                                long long& simulations);

/// What a whole safety search found.
struct SafetyPlan {
  Action action;                ///< legal: no foul noise-free (a push-out: announced)
  /// The mean of planned_value_after_shot() over the chosen strike's
  /// kSafetyReplyOutcomes outcomes (the noise-free one, then the first
  /// noisy repeats'): 1 - the opponent's planned chance when the opponent
  /// shoots next (with ball in hand after a foul), the shooter's own when
  /// the shot keeps the table, after a push-out 1 - max(q, 1 - q).
  double value = 0.0;
  /// The screen's: the mean of value_after_shot() over kSafetyRepeats noisy
  /// repeats, and the same noise-free.
  double screen_value = 0.0;
  double noise_free_value = 0.0;
  int candidates = 0;           ///< strikes proposed
  int legal = 0;                ///< of them, legal noise-free
  int screened = 0;             ///< of them, played out under noise
  int replies = 0;              ///< reply plans (planned_chance) made
  long long simulations = 0;    ///< engine runs (one per play(), and the reply plans')
  std::string detail;           ///< the strike and its estimates, one line
};

/// Strikes proposed: for each of the kSafetyTargets nearest balls on, the
/// cue ball aimed to hit it at each of kSafetyCuts (the contact's offset
/// across the line of centres, ball diameters: 0 full ball, +-1 the
/// thinnest) and kSafetySpeeds, centre ball, the lowest clear elevation;
/// and safe_hit(). A push-out variant of each when one may be announced.
inline constexpr int kSafetyTargets = 3;
inline constexpr std::array<double, 7> kSafetyCuts{0.0, 0.4, -0.4, 0.75, -0.75, 0.95, -0.95};
inline constexpr std::array<double, 4> kSafetySpeeds{0.8, 1.5, 2.5, 4.0};
/// The best noise-free candidates played out under noise, and how often each.
inline constexpr int kSafetyScreened = 10;
inline constexpr int kSafetyRepeats = 8;
/// The best of those by the screen scored by the planned reply, and on how
/// many outcomes each (the noise-free one and kSafetyReplyOutcomes - 1
/// noisy repeats).
inline constexpr int kSafetyFinalists = 3;
inline constexpr int kSafetyReplyOutcomes = 3;

/// The safety search (safety.cpp), a driver over named steps: propose the
/// strikes; play each once noise-free through play() (the rules judge it)
/// and drop those that foul; rank the legal ones by their noise-free value
/// (value_after_shot()); play the kSafetyScreened best kSafetyRepeats times
/// each under `noise` (the game's noise model, common draws: repeat r of
/// every candidate is played with stream_seed(seed, r)); score the
/// kSafetyFinalists best mean values again by planned_value_after_shot() on
/// their kSafetyReplyOutcomes outcomes (outcome j's reply planned with
/// stream_seed(seed, kSafetyRepeats + j) for every finalist); choose the
/// best of those (the first of equal ones). `place`: the cue ball's spot
/// when in hand (required then). None when no candidate is legal.
std::optional<SafetyPlan> plan_safety(const GameState& state, const LegalActions& legal, std::optional<Vec2> place,
                                      const CueStrikeNoise& noise, std::uint64_t seed);

/// The safety planner's choice (safety_planner_action() is its action):
///   - the break, three-cushion: the planner's;
///   - a shot: the planner's pot (planner_choice) when it succeeds at least
///     kSafetyThreshold; else plan_safety() (from the planner's spot when
///     in hand, seeded stream_seed(seed, 3)), and the pot unless the
///     safety's value exceeds its success probability by more than
///     kSafetyMargin (a pot keeps the table with probability p, a safety
///     wins it back with about its value); else the safety (Kind::safety,
///     its value in success_probability);
///   - a decision: decision_by_policy() with the table good when the
///     player's best from it, the larger of the planner's pot (as the
///     planner decides) and the value of plan_safety() from it (searched
///     when that pot is below 1/2 and the cue ball is not in hand), is at
///     least 1/2: the opponent would face the same table, so the player
///     plays what favours the shooter and passes what does not.
/// Deterministic for a seed.
inline constexpr double kSafetyThreshold = 0.5;
inline constexpr double kSafetyMargin = 0.0;
PlannerChoice safety_planner_choice(const AgentOptions& options, const GameState& state, std::uint64_t seed);

}  // namespace cueball
