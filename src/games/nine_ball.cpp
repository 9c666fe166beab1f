// 9-ball (WPA Rules of Play, section 2 "Nine Ball", with the General Rules
// of section 1 and the Fouls of section 6). Balls 1-9; the lowest on the
// table is the ball on; the player who legally pockets the 9 wins (WPA
// section 2, its opening paragraph).
//
// Variants (GameConfig): the 9 on a legal break wins (WPA 2.5; false:
// respotted and the breaker continues), the push-out (WPA 2.4) on or off,
// three consecutive fouls lose (WPA 2.8; fouls_to_lose, 0 off). The warning
// WPA 2.8 asks the referee to give after a second foul is implied: the
// state's fouls_in_a_row shows it to both players.
#include <algorithm>

#include "games/rules.hpp"

namespace cueball {

namespace {

constexpr int kNine = 9;

bool contains(const std::vector<int>& v, int id) { return std::find(v.begin(), v.end(), id) != v.end(); }


// After a foul or a push-out, a pocketed 9 comes back (WPA 2.6).
void respot_nine(GameState& next, Ruling& ruling, const std::vector<int>& pocketed) {
  if (!contains(pocketed, kNine)) return;
  if (respot_on_long_string(next.table, kNine, 0)) ruling.respotted.push_back(kNine);
}

// A foul (WPA 6; 2.7): ball in hand anywhere for the opponent, a pocketed 9
// respotted, and the third foul in a row loses (WPA 2.8).
void foul(GameState& next, Ruling& ruling, Foul f, int shooter, const std::vector<int>& pocketed, std::string reason) {
  pool_foul(next, ruling, f, shooter, PlacementRegion::Kind::anywhere, std::move(reason));
  respot_nine(next, ruling, pocketed);
  const int limit = next.config.fouls_to_lose;
  if (limit > 0 && of(next.fouls_in_a_row, shooter) >= limit)
    win_rack(next, ruling, opponent(shooter), "WPA 2.8: " + std::to_string(limit) + " consecutive fouls lose the game");
}

void set_on(GameState& next) {
  const int lowest = lowest_object_ball(next.table);
  next.on = lowest < 0 ? std::vector<int>{} : std::vector<int>{lowest};
}

// Break shot (WPA 2.3): the lowest ball first, then a ball pocketed or at
// least four object balls driven to a rail, else a foul.
Judgement judge_break(const ShotContext& shot, Judgement j, const std::vector<int>& pocketed) {
  GameState& next = j.next;
  Ruling& ruling = j.ruling;
  const int shooter = shot.shooter;
  std::string reason;
  std::optional<Foul> f = pool_standard_foul(shot, shot.before.on, false, reason);
  if (!f && pocketed.empty() && object_balls_to_rail(shot.facts, shot.cue_ball) < 4) {
    f = Foul::illegal_break;
    reason = "WPA 2.3: no ball pocketed and fewer than four object balls driven to a rail";
  }
  if (f) {
    foul(next, ruling, *f, shooter, pocketed, reason);
    return j;
  }
  of(next.fouls_in_a_row, shooter) = 0;
  if (contains(pocketed, kNine)) {
    if (next.config.nine_on_break_wins) {
      win_rack(next, ruling, shooter, "WPA 2.5: the 9 pocketed on a legal break wins");
      return j;
    }
    respot_nine(next, ruling, pocketed);  // the variant: respotted, and the breaker continues
  }
  next.push_out_available = next.config.push_out;  // WPA 2.4: the shot after a legal break
  if (pocketed.empty()) {
    next.to_shoot = opponent(shooter);
    ruling.turn_over = true;
    ruling.reason = "legal break, nothing pocketed: the opponent shoots (may push out, WPA 2.4)";
  } else {
    ruling.reason = "legal break with a ball pocketed: the breaker continues (WPA 2.5)";
  }
  return j;
}

// Push-out (WPA 2.4): 6.2 and 6.3 suspended; the other player then chooses
// who shoots next. A pocketed 9 is respotted (WPA 2.6), other balls stay down.
Judgement judge_push_out(const ShotContext& shot, Judgement j, const std::vector<int>& pocketed) {
  GameState& next = j.next;
  Ruling& ruling = j.ruling;
  const int shooter = shot.shooter;
  std::string reason;
  const std::optional<Foul> f = pool_standard_foul(shot, {}, false, reason);
  if (f == Foul::miscue || f == Foul::scratch) {
    foul(next, ruling, *f, shooter, pocketed, reason);
    return j;
  }
  of(next.fouls_in_a_row, shooter) = 0;
  respot_nine(next, ruling, pocketed);
  next.phase = GamePhase::decision;
  next.to_shoot = opponent(shooter);
  next.decisions = {Decision::play, Decision::pass};
  ruling.turn_over = true;
  ruling.reason = "WPA 2.4: push-out; the opponent plays from here or passes it back";
  return j;
}

}  // namespace

GameState nine_ball_new_game(GameState base) {
  base.table.balls = balls_at_rest(rack_nine_ball(base.table.table, base.config.rack));
  base.phase = GamePhase::break_shot;
  PlacementRegion kitchen;
  kitchen.kind = PlacementRegion::Kind::behind_head_string;  // WPA 2.3(a)
  base.ball_in_hand = kitchen;
  set_on(base);
  return base;
}

LegalActions nine_ball_legal_actions(const GameState& state) {
  LegalActions a = base_legal_actions(state);
  if (!a.shoot) return a;
  a.push_out = state.push_out_available && state.phase == GamePhase::play;
  return a;
}

Judgement nine_ball_judge_shot(const ShotContext& shot) {
  Judgement j{{}, shot.before};
  GameState& next = j.next;
  next.table = table_after_shot(shot);
  next.phase = GamePhase::play;
  next.ball_in_hand.reset();
  next.decisions.clear();
  next.push_out_available = false;
  for (const Pot& p : shot.facts.pots) j.ruling.pocketed.push_back(p.ball);
  const std::vector<int> pocketed = object_balls_pocketed(shot.facts, shot.cue_ball);
  const int shooter = shot.shooter;

  if (shot.before.phase == GamePhase::break_shot) {
    j = judge_break(shot, std::move(j), pocketed);
  } else if (shot.action.push_out) {
    j = judge_push_out(shot, std::move(j), pocketed);
  } else {
    std::string reason;
    const std::optional<Foul> f = pool_standard_foul(shot, shot.before.on, true, reason);
    if (f) {
      foul(next, j.ruling, *f, shooter, pocketed, reason);
    } else {
      of(next.fouls_in_a_row, shooter) = 0;
      if (contains(pocketed, kNine)) {
        win_rack(next, j.ruling, shooter, "WPA 2, 2.5: the 9 pocketed on a legal shot wins");
      } else if (!pocketed.empty()) {
        j.ruling.reason = "legal shot with a ball pocketed: the shooter continues (WPA 2.5)";
      } else {
        next.to_shoot = opponent(shooter);
        j.ruling.turn_over = true;
        j.ruling.reason = "legal shot, nothing pocketed: the turn passes (WPA 2.5)";
      }
    }
  }
  if (!j.next.over) set_on(j.next);
  return j;
}

Judgement nine_ball_decide(const GameState& state, Decision decision) {
  return play_or_pass(state, decision, "WPA 2.4");
}

}  // namespace cueball
