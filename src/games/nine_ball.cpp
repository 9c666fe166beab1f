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
    rotation_foul(next, ruling, *f, shooter, pocketed, kNine, "WPA 2.8", "game", reason);
    return j;
  }
  of(next.fouls_in_a_row, shooter) = 0;
  if (contains(pocketed, kNine)) {
    if (next.config.nine_on_break_wins) {
      win_rack(next, ruling, shooter, "WPA 2.5: the 9 pocketed on a legal break wins");
      return j;
    }
    respot_if_pocketed(next, ruling, pocketed, kNine);  // the variant: respotted, and the breaker continues
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


}  // namespace

GameState nine_ball_new_game(GameState base) {
  base.table.balls = balls_at_rest(rack_nine_ball(base.table.table, base.config.rack));
  base.phase = GamePhase::break_shot;
  PlacementRegion kitchen;
  kitchen.kind = PlacementRegion::Kind::behind_head_string;  // WPA 2.3(a)
  base.ball_in_hand = kitchen;
  set_on_lowest(base);
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
    j = judge_push_out(shot, std::move(j), pocketed, kNine, "WPA 2.4", "WPA 2.8", "game");
  } else {
    std::string reason;
    const std::optional<Foul> f = pool_standard_foul(shot, shot.before.on, true, reason);
    if (f) {
      rotation_foul(next, j.ruling, *f, shooter, pocketed, kNine, "WPA 2.8", "game", reason);
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
  if (!j.next.over) set_on_lowest(j.next);
  return j;
}

Judgement nine_ball_decide(const GameState& state, Decision decision) {
  return play_or_pass(state, decision, "WPA 2.4");
}

}  // namespace cueball
