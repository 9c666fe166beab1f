// 8-ball (WPA Rules of Play, section 3 "Eight Ball", with the General Rules
// of section 1 and the Fouls of section 6). Balls 1-15: the solids 1-7, the
// stripes 9-15 and the 8; the player who pockets his group and then legally
// pockets the 8 in the called pocket wins (WPA 3, opening paragraph).
//
// The numbers cited are those of the WPA Rules of Play of 2008 and later:
// 3.3 Break Shot (its items (a)-(g)), 3.4 Open Table / Choosing Groups, 3.5
// Continuing Play, 3.6 Standard Fouls, 3.8 Losing the Rack; 1.4 Spotting
// Balls, 1.5 Cue Ball in Hand, 1.6 Standard Call Shot; 6.1-6.3 the standard
// fouls, 6.11 Bad Play from Behind the Head String.
//
// Choices (documented in game.hpp's GameConfig and here):
// - Every shot after the break is a called shot: a ball and a pocket
//   (WPA 3 "Shots are called", 1.6). The rule book lets "obvious" shots go
//   uncalled; an engine cannot tell obvious from not, so it always asks.
//   There is no separate safety call: a shot whose called ball does not drop
//   in the called pocket simply ends the turn.
// - The balls that may be called are the balls on: on an open table any
//   ball but the 8, with groups set the shooter's group, the 8 once that
//   group is off the table (also on an open table with no solid or stripe
//   left).
// - After a scratch on the break the cue ball is in hand in
//   config.break_scratch_region (behind the head string by default, WPA
//   3.3(g)); behind the head string, the kitchen rule applies to that shot
//   (WPA 1.5, 6.11).
// - A re-rack (WPA 3.3(d), (e), (f)) is a new rack from the config; with
//   random gaps (rack.gap_sigma > 0), seeded by stream_seed(rack.seed,
//   shots) so that each re-rack differs and a replay gives the same one.
//   Decision::rerack after the 8 on the break: the player deciding breaks
//   (the breaker in 3.3(e), the incoming player in 3.3(f)).
// - An illegal break that also scratches: the incoming player's options
//   are those of 3.3(d); accepting the table, he has the cue ball in hand
//   as after a scratch on the break.
// - No three-foul rule in 8-ball (it is 9-ball's and 10-ball's, WPA 2.8,
//   9.11): config.fouls_to_lose is ignored; fouls_in_a_row still counts.
#include <algorithm>

#include "cueball/core/random.hpp"
#include "games/rules.hpp"

namespace cueball {

namespace {

constexpr int kEight = 8;

bool contains(const std::vector<int>& v, int id) { return std::find(v.begin(), v.end(), id) != v.end(); }

Group group_of(int id) {
  if (id >= 1 && id <= 7) return Group::solids;
  if (id >= 9 && id <= 15) return Group::stripes;
  return Group::none;
}

Group other_group(Group g) {
  if (g == Group::solids) return Group::stripes;
  if (g == Group::stripes) return Group::solids;
  return Group::none;
}

// The balls `player` may hit first and call: on the break any ball (WPA
// 3.3(b)); on an open table any ball but the 8 (WPA 3.4); with groups set
// his group, and the 8 once it is cleared (WPA 3.5).
std::vector<int> balls_on(const GameState& s, int player) {
  std::vector<int> out;
  const bool open = of(s.groups, player) == Group::none;
  for (const SimulationBall& b : s.table.balls) {
    if (b.id == 0) continue;
    if (s.phase == GamePhase::break_shot || (open ? b.id != kEight : group_of(b.id) == of(s.groups, player)))
      out.push_back(b.id);
  }
  if (out.empty() && on_table(s.table, kEight)) out.push_back(kEight);
  return out;
}

void set_on(GameState& s) { s.on = balls_on(s, s.to_shoot); }

// The cue ball in hand after a scratch on the break (WPA 3.3(f), (g)):
// the config's region, and the kitchen rule when it is the kitchen.
void in_hand_after_break_scratch(GameState& next) {
  next.ball_in_hand = region_of(next.config.break_scratch_region);
  next.cue_must_leave_kitchen = next.config.break_scratch_region == PlacementRegion::Kind::behind_head_string;
}

// A new rack (WPA 3.2) broken by `breaker`: the cue ball in hand behind the
// head string (WPA 3.3(a)), the table open.
GameState rack_up(GameState s, int breaker) {
  RackOptions options = s.config.rack;
  if (options.gap_sigma > 0.0 && s.shots > 0)
    options.seed = stream_seed(options.seed, static_cast<std::uint64_t>(s.shots));
  s.table.balls = balls_at_rest(rack_eight_ball(s.table.table, options));
  s.phase = GamePhase::break_shot;
  s.breaker = breaker;
  s.to_shoot = breaker;
  s.ball_in_hand = region_of(PlacementRegion::Kind::behind_head_string);
  s.cue_must_leave_kitchen = false;
  s.groups = {Group::none, Group::none};
  s.decisions.clear();
  set_on(s);
  return s;
}


// A decision for `player` to take before anyone shoots.
void ask(GameState& next, Ruling& ruling, int player, int shooter, std::vector<Decision> decisions) {
  next.phase = GamePhase::decision;
  next.to_shoot = player;
  next.decisions = std::move(decisions);
  ruling.turn_over = player != shooter;
}

// Break shot (WPA 3.3).
Judgement judge_break(const ShotContext& shot, Judgement j, const std::vector<int>& pocketed) {
  GameState& next = j.next;
  Ruling& ruling = j.ruling;
  const int shooter = shot.shooter;
  const bool scratch = shot.facts.pocketed(shot.cue_ball);
  const bool legal = !shot.miscue && (!pocketed.empty() || object_balls_to_rail(shot.facts, shot.cue_ball) >= 4);
  if (!legal) {
    // WPA 3.3(d): the incoming player accepts the table, re-racks and
    // breaks, or has the offender break again.
    ruling.foul = Foul::illegal_break;
    of(next.fouls_in_a_row, shooter) += 1;
    ask(next, ruling, opponent(shooter), shooter,
        {Decision::play, Decision::rerack_and_break, Decision::rerack_opponent_breaks});
    if (scratch) in_hand_after_break_scratch(next);
    ruling.reason = std::string("WPA 3.3(d): ") + (shot.miscue ? "a miscue, " : "") +
                    "no ball pocketed and fewer than four object balls driven to a rail" +
                    (scratch ? " (and the cue ball pocketed)" : "") +
                    "; the opponent accepts the table, re-racks and breaks, or has the breaker break again";
    return j;
  }
  if (contains(pocketed, kEight)) {
    if (!scratch) {
      // WPA 3.3(e): not a foul; the breaker spots the 8 or breaks again.
      of(next.fouls_in_a_row, shooter) = 0;
      ask(next, ruling, shooter, shooter, {Decision::respot_eight, Decision::rerack});
      ruling.reason = "WPA 3.3(e): the 8 pocketed on a legal break; the breaker spots it and continues, or re-racks";
    } else {
      // WPA 3.3(f): the 8 and the cue ball; the incoming player spots the 8
      // and has the cue ball in hand behind the head string, or re-racks.
      ruling.foul = Foul::scratch;
      of(next.fouls_in_a_row, shooter) += 1;
      ask(next, ruling, opponent(shooter), shooter, {Decision::respot_eight, Decision::rerack});
      in_hand_after_break_scratch(next);
      ruling.reason =
          "WPA 3.3(f): the 8 and the cue ball pocketed on the break; the opponent spots the 8 and takes the cue ball "
          "in hand, or re-racks and breaks";
    }
    return j;
  }
  if (scratch) {
    // WPA 3.3(g): a foul; the balls pocketed stay down, the table is open,
    // the cue ball in hand behind the head string.
    pool_foul(next, ruling, Foul::scratch, shooter, next.config.break_scratch_region,
              std::string("WPA 3.3(g): the cue ball pocketed on a legal break; the opponent has it in hand ") +
                  (next.config.break_scratch_region == PlacementRegion::Kind::behind_head_string
                       ? "behind the head string (and must leave it, WPA 6.11)"
                       : "anywhere (config.break_scratch_region)"));
    in_hand_after_break_scratch(next);
    return j;
  }
  of(next.fouls_in_a_row, shooter) = 0;
  if (pocketed.empty()) {
    next.to_shoot = opponent(shooter);
    ruling.turn_over = true;
    ruling.reason = "legal break, nothing pocketed: the opponent shoots; the table is open (WPA 3.3, 3.4)";
  } else {
    ruling.reason = "WPA 3.3(c): legal break with a ball pocketed: the breaker continues; the table is open";
  }
  return j;
}

// The shot's foul, if any: WPA 6.1-6.3 against the balls on, then the
// kitchen rule after a scratch on the break (WPA 6.11).
std::optional<Foul> shot_foul(const ShotContext& shot, std::string& reason) {
  std::optional<Foul> f = pool_standard_foul(shot, shot.before.on, true, reason);
  const bool kitchen_may_apply = !f || f == Foul::wrong_ball_first || f == Foul::no_rail_after_contact;
  if (shot.before.cue_must_leave_kitchen && kitchen_may_apply && cue_ball_not_out_of_kitchen(shot)) {
    f = Foul::cue_ball_not_out_of_kitchen;
    reason = "WPA 1.5, 6.11: from in hand behind the head string, the cue ball touched the " +
             std::to_string(shot.facts.first_contact) + " (behind the head string) before crossing it";
  }
  return f;
}

// The 8 went down on a shot after the break (WPA 3.8; 3, opening paragraph).
void judge_eight_down(const ShotContext& shot, Judgement& j, const std::optional<Foul>& f, const std::string& reason) {
  GameState& next = j.next;
  Ruling& ruling = j.ruling;
  const int shooter = shot.shooter;
  if (f) {
    ruling.foul = f;
    win_rack(next, ruling, opponent(shooter), "WPA 3.8(a): the 8 pocketed on a foul (" + reason + ") loses the rack");
    return;
  }
  if (shot.before.on != std::vector<int>{kEight}) {
    win_rack(next, ruling, opponent(shooter),
        "WPA 3.8(b), (e): the 8 pocketed before the shooter's group was off the table loses the rack");
    return;
  }
  const int pocket = shot.facts.pocket_of(kEight);
  if (shot.action.called_ball == kEight && shot.action.called_pocket == pocket) {
    of(next.fouls_in_a_row, shooter) = 0;
    win_rack(next, ruling, shooter, "WPA 3: the 8 legally pocketed in the called pocket wins the rack");
    return;
  }
  ruling.foul = Foul::wrong_pocket;
  win_rack(next, ruling, opponent(shooter),
      "WPA 3.8(d): the 8 dropped in pocket " + std::to_string(pocket) + ", not the called one, and loses the rack");
}

// A shot after the break (WPA 3.4-3.8).
Judgement judge_play(const ShotContext& shot, Judgement j, const std::vector<int>& pocketed) {
  GameState& next = j.next;
  Ruling& ruling = j.ruling;
  const int shooter = shot.shooter;
  std::string reason;
  const std::optional<Foul> f = shot_foul(shot, reason);
  if (contains(pocketed, kEight)) {
    judge_eight_down(shot, j, f, reason);
    return j;
  }
  if (f) {
    // WPA 3.6: ball in hand anywhere for the opponent; balls pocketed stay
    // down; a foul never sets the groups.
    pool_foul(next, ruling, *f, shooter, PlacementRegion::Kind::anywhere,
              reason + "; WPA 3.6: the opponent has the cue ball in hand");
    return j;
  }
  of(next.fouls_in_a_row, shooter) = 0;
  const int called = shot.action.called_ball.value_or(-1);
  const int called_pocket = shot.action.called_pocket.value_or(-1);
  const int dropped_in = shot.facts.pocket_of(called);
  if (called >= 0 && dropped_in >= 0 && dropped_in == called_pocket) {
    ruling.reason = "WPA 3.5: the called ball pocketed in the called pocket: the shooter continues";
    if (of(next.groups, shooter) == Group::none) {
      // WPA 3.4: a legally pocketed called ball chooses the groups.
      of(next.groups, shooter) = group_of(called);
      of(next.groups, opponent(shooter)) = other_group(group_of(called));
      ruling.reason += std::string("; WPA 3.4: the shooter takes the ") + to_string(group_of(called));
    }
    return j;
  }
  next.to_shoot = opponent(shooter);
  ruling.turn_over = true;
  if (dropped_in >= 0)
    ruling.reason = "WPA 1.6, 3.5: the called ball dropped in pocket " + std::to_string(dropped_in) +
                    ", not the called one: no foul, the turn ends (it stays down)";
  else if (!pocketed.empty())
    ruling.reason = "WPA 1.6, 3.5: the called ball was not pocketed: the turn ends (the balls pocketed stay down)";
  else
    ruling.reason = "legal shot, nothing pocketed: the turn passes (WPA 3.5)";
  return j;
}

}  // namespace

GameState eight_ball_new_game(GameState base) {
  const int breaker = base.breaker;
  return rack_up(std::move(base), breaker);
}

LegalActions eight_ball_legal_actions(const GameState& state) {
  LegalActions a = base_legal_actions(state);
  if (!a.shoot) return a;
  // WPA 3.3(b): no call on the break; every later shot is called (the file's header).
  a.call_required = state.phase == GamePhase::play;
  if (a.call_required) a.callable = state.on;
  return a;
}

Judgement eight_ball_judge_shot(const ShotContext& shot) {
  Judgement j{{}, shot.before};
  GameState& next = j.next;
  next.table = table_after_shot(shot);
  next.phase = GamePhase::play;
  next.ball_in_hand.reset();
  next.cue_must_leave_kitchen = false;
  next.decisions.clear();
  for (const Pot& p : shot.facts.pots) j.ruling.pocketed.push_back(p.ball);
  const std::vector<int> pocketed = object_balls_pocketed(shot.facts, shot.cue_ball);
  if (shot.before.phase == GamePhase::break_shot)
    j = judge_break(shot, std::move(j), pocketed);
  else
    j = judge_play(shot, std::move(j), pocketed);
  if (!j.next.over) set_on(j.next);
  return j;
}

Judgement eight_ball_decide(const GameState& state, Decision decision) {
  Judgement j{{}, state};
  GameState& next = j.next;
  Ruling& ruling = j.ruling;
  const int player = state.to_shoot;
  next.phase = GamePhase::play;
  next.decisions.clear();
  switch (decision) {
    case Decision::play:
      ruling.reason = "WPA 3.3(d)(1): the illegal break is accepted; the incoming player shoots from here";
      break;
    case Decision::rerack_and_break:
      next = rack_up(std::move(next), player);
      ruling.reason = "WPA 3.3(d)(2): re-racked; the incoming player breaks";
      break;
    case Decision::rerack_opponent_breaks:
      next = rack_up(std::move(next), opponent(player));
      ruling.turn_over = true;
      ruling.reason = "WPA 3.3(d)(3): re-racked; the offender breaks again";
      break;
    case Decision::respot_eight:
      if (respot_on_long_string(next.table, kEight, 0)) ruling.respotted.push_back(kEight);
      ruling.reason = "WPA 3.3(e)(1), (f)(1), 1.4: the 8 is spotted; the player deciding shoots";
      break;
    case Decision::rerack:
      next = rack_up(std::move(next), player);
      ruling.reason = "WPA 3.3(e)(2), (f)(2): re-racked; the player deciding breaks";
      break;
    case Decision::pass:
    case Decision::restore:
      break;  // never open in 8-ball (validate_action refuses it)
  }
  set_on(next);
  return j;
}

}  // namespace cueball
