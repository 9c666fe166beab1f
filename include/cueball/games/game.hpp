// Games: the rules of 9-ball, 8-ball, 10-ball, snooker and three-cushion as
// pure functions over plain values, judged from the shot's own events
// (ShotFacts, simulation/shot_facts.hpp).
//
//   GameState s = new_game(default_config(GameKind::nine_ball), seed);
//   while (!s.over) {
//     const LegalActions legal = legal_actions(s);
//     Action a = ...;                       // an agent (agents/) or a user
//     GameStep step = play(s, a, shot_seed); // the shot, its facts, the ruling
//     s = step.next;
//   }
//
// A GameState is a value: copying it is a snapshot, and io/game_json.hpp
// writes and reads it bit for bit. play() never changes its input; it is
// deterministic for a seed (the execution noise of GameConfig::noise is
// drawn from it) and bounded: a game ends after GameConfig::max_shots shots
// or when a shot reaches the simulator's event limit, as `truncated` with
// the reason (GameState::end_reason), never by hanging.
//
// The rule books: the WPA Rules of Play (World Pool-Billiard Association;
// its sections: 1 General Rules, 2 Nine Ball, 3 Eight Ball, 6 Fouls, 8
// Definitions, 9 Ten Ball, so "WPA 2.4" is the 9-ball push-out and "WPA
// 6.3" the no-rail-after-contact foul), the WPBSA Official Rules of
// Snooker (2019; "WPBSA 3.12" is section 3, rule 12) and the UMB World Rules
// of Carom (three-cushion). Each rule is cited beside the code that judges
// it, in games/<game>.cpp; where the engine chose one of the variants in use,
// GameConfig says so and documents the default.
//
// Players are 0 and 1; player 0 breaks (or, in three-cushion, opens) unless
// a decision hands the break over. Ball ids follow rack.hpp: pool 0 = cue
// ball, 1..15 the numbered balls; snooker 0 = cue ball, 1..15 reds, 16
// yellow, 17 green, 18 brown, 19 blue, 20 pink, 21 black; three-cushion 0 =
// white (player 0's cue ball), 1 = yellow (player 1's), 2 = red.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cueball/physics/cue_strike.hpp"
#include "cueball/simulation/batch.hpp"
#include "cueball/simulation/scenario.hpp"
#include "cueball/simulation/shot_facts.hpp"
#include "cueball/table/placement.hpp"
#include "cueball/table/rack.hpp"

namespace cueball {

enum class GameKind : char { nine_ball, eight_ball, ten_ball, snooker, three_cushion };
inline constexpr std::array<GameKind, 5> kGameKinds{GameKind::nine_ball, GameKind::eight_ball, GameKind::ten_ball,
                                                    GameKind::snooker, GameKind::three_cushion};

/// "nine_ball", "eight_ball", "ten_ball", "snooker", "three_cushion".
const char* to_string(GameKind kind);
std::optional<GameKind> game_kind_from_string(std::string_view name);
/// The names, for messages: "nine_ball, eight_ball, ten_ball, snooker, three_cushion".
std::string game_kind_names();

/// The pool games' default rack gap scale, m (docs/break.md).
inline constexpr double kDefaultRackGapSigma = 2.5e-5;

/// How a game is played: the discipline, the table, and the variants the
/// rule books leave open (each documented with its default).
struct GameConfig {
  GameKind kind = GameKind::nine_ball;
  /// The table preset (table/table.hpp): pool_9ft for the pool games,
  /// snooker_12ft for snooker, carom_10ft for three-cushion.
  std::string table = "pool_9ft";
  /// The rack's gaps (rack.hpp), seeded by new_game's seed. The pool games
  /// default to gap_sigma = kDefaultRackGapSigma: balls made to 2 1/4 in ±
  /// 0.005 in (WPA Equipment Specifications) never close every contact of
  /// a rack; gaps this small are crossed inside the break's impact, as in a
  /// real rack (simulation/contact_cluster.hpp, docs/break.md); 0: a
  /// perfectly frozen lattice.
  RackOptions rack;
  /// Execution noise added to every strike (none by default; the
  /// computational-pool tournaments' level: tournament_noise(), planning).
  CueStrikeNoise noise;
  /// Shots (decisions included) after which the game ends as truncated.
  int max_shots = 1000;
  /// Three consecutive fouls lose the game (WPA 2.8, 9-ball; 10-ball likewise);
  /// 0 turns the rule off. 8-ball has no such rule and ignores it.
  int fouls_to_lose = 3;

  // ---- 9-ball
  /// The 9 pocketed on a legal break wins (WPA 2.5, the default); false: it is respotted.
  bool nine_on_break_wins = true;
  /// A push-out may be played on the shot after the break (WPA 2.4; 10-ball likewise).
  bool push_out = true;

  // ---- 8-ball (and 10-ball): every shot after the break is a called shot,
  // a ball and a pocket (WPA 1.6, 3, 9): the rule books let an "obvious"
  // shot go uncalled, which an engine cannot judge, so it always asks.
  /// Where the cue ball is placed after a scratch on the break (WPA 3.3(g)
  /// gives ball in hand behind the head string; many leagues anywhere).
  PlacementRegion::Kind break_scratch_region = PlacementRegion::Kind::behind_head_string;

  // ---- snooker
  /// Reds in the rack: 6, 10 or 15.
  int reds = 15;
  /// The miss rule (WPBSA 3.14): the next player may have the balls
  /// replaced and the offender play again.
  bool miss_rule = true;

  // ---- three-cushion
  /// Points to win the game (a race; UMB: 40 in most events, 50 in some).
  int race_to = 15;
};

/// The configuration a discipline is played with unless changed: the table,
/// and the variants' defaults above.
GameConfig default_config(GameKind kind);

/// Throws InvalidArgument naming the field (as the JSON writes it:
/// "max_shots", "reds", "race_to", "table", "rack.gap_sigma", "noise ...").
void validate(const GameConfig& config);

/// A decision a player may be asked to take instead of shooting.
enum class Decision : char {
  play,                   ///< take the table as it is and shoot (accept a push-out, an illegal break, a foul's table, ...)
  pass,                   ///< make the opponent shoot from here (pass back a push-out, have the offender play again)
  rerack_and_break,       ///< 8-ball illegal break: re-rack and break yourself (WPA 3.3(d))
  rerack_opponent_breaks, ///< 8-ball illegal break: re-rack and have the offender break again (WPA 3.3(d))
  respot_eight,           ///< 8-ball, the 8 on the break: spot the 8 and play on (WPA 3.3(e), (f))
  rerack,                 ///< 8-ball, the 8 on the break: re-rack and break again (WPA 3.3(e), (f))
  restore,                ///< snooker miss: replace the balls, the offender plays again (WPBSA 3.14)
};
const char* to_string(Decision d);
std::optional<Decision> decision_from_string(std::string_view name);
std::string decision_names();

/// Where a game stands between shots.
enum class GamePhase : char {
  break_shot,  ///< the opening shot (pool: the break; three-cushion: the opening shot)
  play,        ///< a shot to play
  decision,    ///< `to_shoot` must take one of `decisions`
  over,        ///< won, or truncated
};
const char* to_string(GamePhase p);

/// 8-ball groups.
enum class Group : char { none, solids, stripes };
const char* to_string(Group g);

/// The whole state of a game: a value (copy = snapshot; JSON: io/game_json.hpp).
struct GameState {
  GameConfig config;
  /// The table and the balls at rest (no "cue"): what the next shot is played on.
  Scenario table;
  GamePhase phase = GamePhase::break_shot;
  int to_shoot = 0;               ///< the player to act: shoot or decide
  int breaker = 0;                ///< who broke (or opened) this rack
  /// The cue ball is in hand: placed by the player anywhere in the region
  /// before the shot (Action::place). None: played from where it lies.
  std::optional<PlacementRegion> ball_in_hand;
  /// 8-ball after a scratch on the break (WPA 3.3(g) with WPA 1.5, 6.11): the
  /// cue ball must cross the head string before it touches a ball behind it.
  bool cue_must_leave_kitchen = false;
  /// Points: three-cushion and snooker scores; pool games 1 to the winner.
  std::array<int, 2> scores{};
  std::array<int, 2> fouls_in_a_row{};
  /// The balls "on": those the cue ball may contact first. Snooker after a
  /// red: the six colours until one is nominated (Action::nominate).
  std::vector<int> on;
  std::array<Group, 2> groups{Group::none, Group::none};  ///< 8-ball; none/none: open table
  std::vector<Decision> decisions;  ///< open when phase == decision
  bool push_out_available = false;  ///< 9-ball, 10-ball: this shot may be a push-out
  /// Snooker: the cue ball is snookered after a foul (free ball, WPBSA 3.12),
  /// so the player may nominate any ball as on.
  bool free_ball = false;
  /// Snooker: consecutive misses of the offender with a full-ball view (WPBSA 3.14(g)).
  int misses_in_a_row = 0;
  /// Snooker: the colour the player must play next in the clearance (WPBSA
  /// 3.4); while reds remain, unused.
  int colour_on = 0;
  /// Snooker miss: the balls before the foul, restored on `restore`.
  std::vector<SimulationBall> before_miss;
  int shots = 0;                    ///< shots and decisions played so far
  int inning_points = 0;            ///< three-cushion: points of the current inning (the run)
  bool over = false;
  std::optional<int> winner;        ///< 0 or 1; none for a truncated game
  bool truncated = false;
  std::string end_reason;           ///< why it ended, citing the rule, or the bound that truncated it

  /// The cue ball the player to act strikes: 0 in the pool games and
  /// snooker; in three-cushion 0 (white) for player 0 and 1 (yellow) for player 1.
  int cue_ball() const;
};

bool operator==(const GameState& a, const GameState& b);

/// What a player does: a shot (the strike, and where the rules ask it, a
/// placement, a call, a nomination, a push-out) or a decision.
struct Action {
  std::optional<Decision> decision;  ///< a decision instead of a shot
  ShotAction strike;                 ///< speed m/s, aim_deg, elevation_deg, side, height (ball radii)
  std::optional<int> aim_at;         ///< aim at this ball's centre instead of strike.aim_deg
  std::optional<Vec2> place;         ///< the cue ball's spot when in hand (required then)
  std::optional<int> called_ball;    ///< 10-ball, 8-ball: the called ball
  std::optional<int> called_pocket;  ///< index into table.pockets
  bool push_out = false;             ///< 9-ball, 10-ball: announce a push-out (WPA 2.4)
  /// Snooker: the colour nominated after a red (WPBSA 3.4(b)) or the free
  /// ball (WPBSA 3.12).
  std::optional<int> nominate;
};

/// What the player to act may do now.
struct LegalActions {
  int player = 0;
  int cue_ball = 0;
  bool shoot = true;                       ///< a shot is allowed (false: a decision is due)
  std::vector<int> on;                     ///< balls the cue ball may contact first
  std::optional<PlacementRegion> ball_in_hand;  ///< place the cue ball in this region first
  bool cue_must_leave_kitchen = false;
  bool call_required = false;              ///< call a ball and a pocket (called_ball, called_pocket)
  std::vector<int> callable;               ///< the balls that may be called
  bool push_out = false;                   ///< a push-out may be announced
  bool nominate_required = false;          ///< snooker: nominate a colour (or the free ball)
  std::vector<int> nominable;              ///< the balls that may be nominated
  bool free_ball = false;
  std::vector<Decision> decisions;         ///< when shoot is false, or alongside (none today)
};

/// Fouls, named as the rule books name them.
enum class Foul : char {
  scratch,                ///< cue ball pocketed (WPA 6.1; snooker's "in-off", a foul of WPBSA section 3)
  wrong_ball_first,       ///< the first ball contacted is not on (WPA 6.2; WPBSA 3.12(a)(ii))
  no_contact,             ///< the cue ball touched no ball (WPA 6.2; WPBSA 3.12; UMB)
  no_rail_after_contact,  ///< no ball to a rail or pocketed after the contact (WPA 6.3)
  illegal_break,          ///< WPA 2.3, 3.3, 9.3: nothing potted and fewer than four object balls to a rail
  ball_off_table,         ///< WPA 6.5; not reachable today (no airborne phase)
  wrong_pocket,           ///< a ball not on potted, or in another pocket than called (snooker: a ball not on potted; 8-ball: the 8 in another pocket than called, WPA 3.8)
  cue_ball_not_out_of_kitchen,  ///< in hand behind the head string, it touched a ball behind it first (WPA 1.5, 6.11)
  bad_cue_ball,           ///< three-cushion: struck the opponent's cue ball (UMB)
  miscue,                 ///< the noisy strike went beyond the miscue limit: judged as a foul (the engine cannot play it)
};
const char* to_string(Foul f);

/// The judgement of one shot or decision.
struct Ruling {
  std::optional<Foul> foul;
  std::array<int, 2> points{};     ///< points each player scored by it (snooker, three-cushion; pool: 0)
  bool turn_over = false;          ///< the other player acts next
  bool game_over = false;
  std::optional<int> winner;
  std::vector<int> pocketed;       ///< object balls pocketed, in order (the cue ball too)
  std::vector<int> respotted;      ///< balls put back on the table, in order
  bool push_out = false;           ///< the shot was an announced push-out
  bool miss = false;               ///< snooker: the foul was called a miss (WPBSA 3.14)
  bool truncated = false;          ///< the game was cut short by a bound (end_reason says which)
  std::string reason;              ///< one line, citing the rule
};

/// One play(): the shot (empty for a decision), its facts, the ruling and the next state.
struct GameStep {
  Action action;                   ///< as given
  std::optional<CueStrike> played; ///< the strike actually played (after noise), radians and metres
  Scenario shot;                   ///< the scenario shot: the balls before it (the cue ball placed) and the played strike
  SimulationResult result;         ///< empty for a decision
  ShotFacts facts;
  Ruling ruling;
  GameState next;
};

/// A game ready to break: the discipline's rack on its table, seeded by
/// `seed` when config.rack.gap_sigma > 0 (its own seed then is ignored), the
/// breaker's cue ball in hand in the kitchen or the D (three-cushion: the
/// UMB opening position). Validates the config.
GameState new_game(const GameConfig& config, std::uint64_t seed = 0);

/// What the player to act may do (an over game: nothing, shoot false).
LegalActions legal_actions(const GameState& state);

/// Throws InvalidArgument naming the field ("place", "called_ball",
/// "called_pocket", "nominate", "decision", "push_out", "speed", ...) when
/// `action` is not legal in `state`: a decision that is not open, a shot
/// when a decision is due, a placement outside the region or on a ball, a
/// missing or needless call, a push-out that is not available, a strike
/// out of range, a game that is over.
void validate_action(const GameState& state, const Action& action);

/// Plays `action` in `state`: places the cue ball, strikes it (with the
/// config's noise drawn from `seed`), simulates, reads the facts and judges
/// them by the discipline's rules. Throws InvalidArgument as
/// validate_action(). A shot that reaches the event limit ends the game as
/// truncated (Ruling::truncated; never throws for it).
GameStep play(const GameState& state, const Action& action, std::uint64_t seed = 0);

/// A stroke that moved nothing, judged as the discipline judges a miscue
/// (Foul::miscue: the pool games' ball in hand for the opponent, snooker's
/// foul points, three-cushion's end of the inning): what an illegal action
/// of a learner costs (rl/environment.hpp). `why` is put before the
/// ruling's reason. With the cue ball in hand it is placed at `place` when
/// that is a legal spot, else left where it lies, else (off the table) at a
/// free spot of the region drawn from `seed`. A call or nomination the
/// rules ask for is filled in (the first allowed ball, pocket 0): a foul
/// stroke pots nothing. Throws InvalidArgument("action") when the game is
/// over or a decision is due.
GameStep play_foul_stroke(const GameState& state, std::optional<Vec2> place, std::uint64_t seed,
                          const std::string& why);

/// The balls on the table in `state` that are not the cue ball(s).
std::vector<int> object_balls(const GameState& state);

}  // namespace cueball
