// The interface every discipline's rules implement (games/<game>.cpp), and
// the helpers they share. game.cpp chooses the discipline by GameKind with a
// switch and does what is common to all: validating the action, placing and
// striking the cue ball with the config's noise, simulating, reading the
// facts, and the bound on shots.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cueball/games/game.hpp"

namespace cueball {

/// One shot, as the rules see it.
struct ShotContext {
  const GameState& before;   ///< the state it was played from
  const Action& action;
  int shooter = 0;
  int cue_ball = 0;
  const Scenario& shot;      ///< the balls as struck (the cue ball placed)
  const SimulationResult& result;
  const ShotFacts& facts;
  const std::vector<BallAfterShot>& after;  ///< every ball's end, in shot.balls' order
  bool miscue = false;       ///< the noisy strike was beyond the miscue limit: nothing moved
};

/// A ruling and the state it leads to.
struct Judgement {
  Ruling ruling;
  GameState next;
};

// Each discipline: the opening position (balls and who may place the cue
// ball), what the player to act may do, a shot's judgement, a decision's.
GameState nine_ball_new_game(GameState base);
LegalActions nine_ball_legal_actions(const GameState& state);
Judgement nine_ball_judge_shot(const ShotContext& shot);
Judgement nine_ball_decide(const GameState& state, Decision decision);

GameState eight_ball_new_game(GameState base);
LegalActions eight_ball_legal_actions(const GameState& state);
Judgement eight_ball_judge_shot(const ShotContext& shot);
Judgement eight_ball_decide(const GameState& state, Decision decision);

GameState ten_ball_new_game(GameState base);
LegalActions ten_ball_legal_actions(const GameState& state);
Judgement ten_ball_judge_shot(const ShotContext& shot);
Judgement ten_ball_decide(const GameState& state, Decision decision);

GameState snooker_new_game(GameState base);
LegalActions snooker_legal_actions(const GameState& state);
Judgement snooker_judge_shot(const ShotContext& shot);
Judgement snooker_decide(const GameState& state, Decision decision);

GameState three_cushion_new_game(GameState base);
LegalActions three_cushion_legal_actions(const GameState& state);
Judgement three_cushion_judge_shot(const ShotContext& shot);
Judgement three_cushion_decide(const GameState& state, Decision decision);

// ------------------------------------------------------------ shared helpers (game.cpp)

inline int opponent(int player) { return 1 - player; }

/// A player's entry of a two-player array (scores, fouls, groups).
template <class T>
T& of(std::array<T, 2>& a, int player) {
  return a[static_cast<std::size_t>(player)];
}
template <class T>
const T& of(const std::array<T, 2>& a, int player) {
  return a[static_cast<std::size_t>(player)];
}

/// The balls of a rack as SimulationBalls at rest.
std::vector<SimulationBall> balls_at_rest(const std::vector<PlacedBall>& placed);

/// Adds a ball at rest (or moves it there when it is already on the table).
void put_ball(Scenario& table, int id, Vec2 position);

/// True when ball `id` is on the table.
bool on_table(const Scenario& table, int id);

/// The table the shot left: the shot's balls at rest, the pocketed ones
/// removed (table_after, scenario.hpp).
Scenario table_after_shot(const ShotContext& shot);

/// What every discipline's legal actions start from: the player to act and
/// the cue ball; in phase decision, shoot false and the open decisions;
/// else the balls on, the ball-in-hand region and the kitchen rule as the
/// state has them.
LegalActions base_legal_actions(const GameState& state);

/// The game ends: `winner` wins (scores[winner] += points_for_win when given).
void end_game(GameState& next, Ruling& ruling, int winner, std::string reason);

// ------------------------------------------------------------ pool helpers (pool_rules.cpp)

/// The lowest-numbered object ball on the table (ids 1..15), or -1.
int lowest_object_ball(const Scenario& table);

/// 9-ball's and 10-ball's play-or-pass decision (after a push-out, WPA 2.4,
/// 9.4; after a wrongful pot, 9.7): `pass` hands the shot to the other
/// player, `play` keeps it with the player deciding; `reason` is the rule
/// cited, completed with what the decision did.
Judgement play_or_pass(const GameState& state, Decision decision, const std::string& rule);

// 9-ball and 10-ball, the rotation games: the ball on is the lowest, the
// game ball (the 9, the 10) comes back after a foul or a push-out.

/// on = {the lowest object ball}, or none when the table is empty.
void set_on_lowest(GameState& next);

/// A foul of a rotation game (WPA 2.7, 9.10): ball in hand anywhere for the
/// opponent, the game ball respotted when pocketed (WPA 2.6, 9.9), and the
/// config's consecutive fouls lose (WPA 2.8, 9.11; `rule` and `what` name
/// them in the reason: "<rule>: 3 consecutive fouls lose the <what>").
void rotation_foul(GameState& next, Ruling& ruling, Foul foul, int shooter, const std::vector<int>& pocketed,
                   int game_ball, const std::string& rule, const std::string& what, std::string reason);

/// The push-out of a rotation game (WPA 2.4, 9.4): wrong ball first and no
/// rail suspended, a scratch still a foul, the game ball respotted, then the
/// opponent plays from there or passes it back. `rule` is cited in the reason.
Judgement judge_push_out(const ShotContext& shot, Judgement j, const std::vector<int>& pocketed, int game_ball,
                         const std::string& rule, const std::string& three_foul_rule, const std::string& what);

/// The incoming player chooses who shoots next: phase decision, {play, pass}.
void offer_play_or_pass(GameState& next, Ruling& ruling, int shooter);

/// The pool games: `winner` wins the rack (scores[winner] += 1, end_game).
void win_rack(GameState& next, Ruling& ruling, int winner, std::string reason);

/// Pool: a ball pocketed, or the cue ball or an object ball touching a
/// cushion or a jaw after the first contact (WPA 6.3; a pocket's jaw is the
/// cushion's nose turned into the pocket, so a ball that hits it has
/// touched the rail).
bool rail_after_contact(const ShotFacts& facts);

/// Distinct object balls (not `cue_ball`) that touched a cushion or a jaw
/// during the shot (the break's "driven to a rail", WPA 2.3, 3.5).
int object_balls_to_rail(const ShotFacts& facts, int cue_ball);

/// Object balls pocketed, in order (not the cue ball).
std::vector<int> object_balls_pocketed(const ShotFacts& facts, int cue_ball);

/// Spots ball `id` on the long string (WPA 1.4, spot_on_long_string) in
/// `table`; the cue ball, when on the table, stays clear of it. False when
/// no spot is free (never on a real table).
bool respot_on_long_string(Scenario& table, int id, int cue_ball);

/// The foul's common consequences in the pool games: the turn passes, the
/// incoming player has ball in hand in `region` (WPA 1.5, 6), the
/// offender's consecutive fouls count up.
void pool_foul(GameState& next, Ruling& ruling, Foul foul, int shooter, PlacementRegion::Kind region,
               std::string reason);

/// The first foul among the standard ones of a pool shot (WPA 6.1-6.3):
/// a miscue, the cue ball pocketed, no contact, a first contact not in
/// `on` (a simultaneous contact with a ball on counts as on), no rail after
/// contact (checked when `rail_required`). None: a legal shot so far.
std::optional<Foul> pool_standard_foul(const ShotContext& shot, const std::vector<int>& on, bool rail_required,
                                       std::string& reason);

/// The kitchen rule (WPA 1.5 and 6.11, "Bad Play from Behind the Head
/// String"): with the cue ball in hand behind the head string, true when its
/// first contact is a ball whose centre lay behind the head string (x <
/// head_string_x) at the start of the shot and the cue ball had not crossed
/// the head string out of the kitchen before that contact.
bool cue_ball_not_out_of_kitchen(const ShotContext& shot);

/// When `id` is among `pocketed`, spots it on the long string (WPA 1.4) in
/// `next.table`, clear of the cue ball (id 0), and adds it to
/// ruling.respotted.
void respot_if_pocketed(GameState& next, Ruling& ruling, const std::vector<int>& pocketed, int id);

/// A placement region of `kind` (no rectangle bounds).
PlacementRegion region_of(PlacementRegion::Kind kind);

}  // namespace cueball
