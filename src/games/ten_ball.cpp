// 10-ball (WPA Rules of Play, section 9 "Ten Ball", with the General Rules
// of section 1 and the Fouls of section 6). Balls 1-10, played in rotation:
// the lowest on the table must be hit first; every shot after the break is
// called (a ball and a pocket); the player who legally pockets the called
// 10 wins (WPA 9, opening paragraph).
//
// The numbers cited are those of the WPA ten-ball rules of 2009 and later:
// 9.2 Ten Ball Rack, 9.3 Legal Break Shot, 9.4 Push Out, 9.5 Call Shots and
// Pocketing Balls, 9.7 Wrongfully Pocketed Balls, 9.8 Continuing Play, 9.9
// Spotting Balls, 9.10 Standard Fouls, 9.11 Serious Fouls (three in a row).
//
// Choices (GameConfig and here):
// - The break must hit the 1 first, as every shot must hit the lowest ball
//   (WPA 9 opening paragraph, 6.2; 9-ball's break asks the same, WPA 2.3).
// - The 10 pocketed on the break is spotted and the breaker continues (WPA
//   9 opening paragraph); it never wins on the break.
// - Any ball on the table may be called (a combination or a carom on the
//   called ball is legal); the call is ignored on a push-out, which needs
//   none (WPA 9.4), but validate_action still asks for one on every shot
//   after the break so that the shot is always judged the same way.
// - The 10 legally called and pocketed wins whenever it drops (a
//   combination too); pocketed any other way it is spotted (WPA 9.9).
// - A pot that is not the called ball in the called pocket, without a foul
//   (WPA 9.7): the turn ends and the incoming player chooses to play the
//   table (Decision::play) or to have the shooter play again
//   (Decision::pass).
// - Three consecutive fouls lose (WPA 9.11; config.fouls_to_lose, 0 off);
//   the push-out is config.push_out as in 9-ball.
#include <algorithm>

#include "games/rules.hpp"

namespace cueball {

namespace {

constexpr int kTen = 10;

bool contains(const std::vector<int>& v, int id) { return std::find(v.begin(), v.end(), id) != v.end(); }

// Break shot (WPA 9.3): the 1 first, then a ball pocketed or at least four
// object balls driven to a rail, else a foul.
Judgement judge_break(const ShotContext& shot, Judgement j, const std::vector<int>& pocketed) {
  GameState& next = j.next;
  Ruling& ruling = j.ruling;
  const int shooter = shot.shooter;
  std::string reason;
  std::optional<Foul> f = pool_standard_foul(shot, shot.before.on, false, reason);
  if (!f && pocketed.empty() && object_balls_to_rail(shot.facts, shot.cue_ball) < 4) {
    f = Foul::illegal_break;
    reason = "WPA 9.3(b): no ball pocketed and fewer than four object balls driven to a rail";
  }
  if (f) {
    rotation_foul(next, ruling, *f, shooter, pocketed, kTen, "WPA 9.11", "rack", reason);
    return j;
  }
  of(next.fouls_in_a_row, shooter) = 0;
  respot_if_pocketed(next, ruling, pocketed, kTen);  // WPA 9: the 10 on the break is spotted
  next.push_out_available = next.config.push_out;    // WPA 9.4: the shot after a legal break
  if (pocketed.empty()) {
    next.to_shoot = opponent(shooter);
    ruling.turn_over = true;
    ruling.reason = "legal break, nothing pocketed: the opponent shoots (may push out, WPA 9.4)";
  } else {
    ruling.reason = "legal break with a ball pocketed: the breaker continues (WPA 9.8)";
    if (contains(pocketed, kTen)) ruling.reason += "; the 10 is spotted (WPA 9, 9.9)";
  }
  return j;
}

// A called shot (WPA 9.5, 9.7, 9.8).
Judgement judge_called_shot(const ShotContext& shot, Judgement j, const std::vector<int>& pocketed) {
  GameState& next = j.next;
  Ruling& ruling = j.ruling;
  const int shooter = shot.shooter;
  std::string reason;
  const std::optional<Foul> f = pool_standard_foul(shot, shot.before.on, true, reason);
  if (f) {
    rotation_foul(next, ruling, *f, shooter, pocketed, kTen, "WPA 9.11", "rack", reason);
    return j;
  }
  of(next.fouls_in_a_row, shooter) = 0;
  const int called = shot.action.called_ball.value_or(-1);
  const int dropped_in = shot.facts.pocket_of(called);
  const bool called_pot = called >= 0 && dropped_in >= 0 && dropped_in == shot.action.called_pocket.value_or(-1);
  if (called_pot && called == kTen) {
    win_rack(next, ruling, shooter, "WPA 9, 9.5: the 10 called and legally pocketed wins the rack");
    return j;
  }
  respot_if_pocketed(next, ruling, pocketed, kTen);  // WPA 9.9: a 10 not called, or not in its pocket
  if (called_pot) {
    ruling.reason = "WPA 9.8: the called ball pocketed in the called pocket: the shooter continues";
  } else if (!pocketed.empty()) {
    offer_play_or_pass(next, ruling, shooter);
    ruling.reason = dropped_in >= 0 ? "WPA 9.7: the called ball dropped in pocket " + std::to_string(dropped_in) +
                                          ", not the called one (no foul)"
                                    : std::string("WPA 9.7: a ball other than the called one was pocketed (no foul)");
    ruling.reason += "; the opponent plays the table or has the shooter play again";
  } else {
    next.to_shoot = opponent(shooter);
    ruling.turn_over = true;
    ruling.reason = "legal shot, nothing pocketed: the turn passes (WPA 9.8)";
  }
  return j;
}

}  // namespace

GameState ten_ball_new_game(GameState base) {
  base.table.balls = balls_at_rest(rack_ten_ball(base.table.table, base.config.rack));
  base.phase = GamePhase::break_shot;
  base.to_shoot = base.breaker;
  base.ball_in_hand = region_of(PlacementRegion::Kind::behind_head_string);  // WPA 9.3(a)
  set_on_lowest(base);
  return base;
}

LegalActions ten_ball_legal_actions(const GameState& state) {
  LegalActions a = base_legal_actions(state);
  if (!a.shoot) return a;
  a.push_out = state.push_out_available && state.phase == GamePhase::play;
  // WPA 9.5: every shot after the break is called; no call on the break.
  a.call_required = state.phase == GamePhase::play;
  if (a.call_required) a.callable = object_balls(state);
  return a;
}

Judgement ten_ball_judge_shot(const ShotContext& shot) {
  Judgement j{{}, shot.before};
  GameState& next = j.next;
  next.table = table_after_shot(shot);
  next.phase = GamePhase::play;
  next.ball_in_hand.reset();
  next.decisions.clear();
  next.push_out_available = false;
  for (const Pot& p : shot.facts.pots) j.ruling.pocketed.push_back(p.ball);
  const std::vector<int> pocketed = object_balls_pocketed(shot.facts, shot.cue_ball);
  if (shot.before.phase == GamePhase::break_shot)
    j = judge_break(shot, std::move(j), pocketed);
  else if (shot.action.push_out)
    j = judge_push_out(shot, std::move(j), pocketed, kTen, "WPA 9.4", "WPA 9.11", "rack");
  else
    j = judge_called_shot(shot, std::move(j), pocketed);
  if (!j.next.over) set_on_lowest(j.next);
  return j;
}

Judgement ten_ball_decide(const GameState& state, Decision decision) {
  return play_or_pass(state, decision, "WPA 9.4, 9.7");
}

}  // namespace cueball
