// What the pool games (9-ball, 8-ball, 10-ball) share: the standard fouls
// of WPA section 6, the rail after contact, the break's balls to a rail,
// spotting on the long string, ball in hand after a foul, the kitchen rule
// (the cue ball in hand behind the head string must leave it first).
#include <algorithm>
#include <set>

#include "games/rules.hpp"

namespace cueball {

int lowest_object_ball(const Scenario& table) {
  int lowest = -1;
  for (const SimulationBall& b : table.balls)
    if (b.id >= 1 && b.id <= 15 && (lowest < 0 || b.id < lowest)) lowest = b.id;
  return lowest;
}

Judgement play_or_pass(const GameState& state, Decision decision, const std::string& rule) {
  Judgement j{{}, state};
  j.next.phase = GamePhase::play;
  j.next.decisions.clear();
  if (decision == Decision::pass) {
    j.next.to_shoot = opponent(state.to_shoot);
    j.ruling.turn_over = true;
    j.ruling.reason = rule + ": passed back; the other player shoots from here";
  } else {
    j.ruling.reason = rule + ": the table is accepted; the player deciding shoots from here";
  }
  return j;
}

void win_rack(GameState& next, Ruling& ruling, int winner, std::string reason) {
  of(next.scores, winner) += 1;
  end_game(next, ruling, winner, std::move(reason));
}

bool rail_after_contact(const ShotFacts& facts) {
  if (facts.first_contact < 0) return false;
  for (const Pot& p : facts.pots)
    if (p.ball != facts.cue_ball) return true;  // WPA 6.3: "a ball must be pocketed"
  if (!facts.balls_to_cushion_after_first_contact().empty()) return true;
  for (const JawHit& j : facts.jaws)
    if (j.time >= facts.first_contact_time) return true;
  return false;
}

int object_balls_to_rail(const ShotFacts& facts, int cue_ball) {
  std::set<int> balls;
  for (const CushionHit& c : facts.cushions)
    if (c.ball != cue_ball) balls.insert(c.ball);
  for (const JawHit& j : facts.jaws)
    if (j.ball != cue_ball) balls.insert(j.ball);
  return static_cast<int>(balls.size());
}

std::vector<int> object_balls_pocketed(const ShotFacts& facts, int cue_ball) {
  std::vector<int> out;
  for (const Pot& p : facts.pots)
    if (p.ball != cue_ball) out.push_back(p.ball);
  return out;
}

bool respot_on_long_string(Scenario& table, int id, int cue_ball) {
  std::vector<Vec2> others;
  std::optional<Vec2> cue;
  for (const SimulationBall& b : table.balls) {
    if (b.id == id) continue;
    if (b.id == cue_ball)
      cue = b.state.position;
    else
      others.push_back(b.state.position);
  }
  const std::optional<Vec2> spot = spot_on_long_string(table.table, others, cue, table.table.ball.radius);
  if (!spot) return false;
  put_ball(table, id, *spot);
  return true;
}

void pool_foul(GameState& next, Ruling& ruling, Foul foul, int shooter, PlacementRegion::Kind region,
               std::string reason) {
  ruling.foul = foul;
  ruling.turn_over = true;
  ruling.reason = std::move(reason);
  of(next.fouls_in_a_row, shooter) += 1;
  next.to_shoot = opponent(shooter);
  next.phase = GamePhase::play;
  PlacementRegion r;
  r.kind = region;
  next.ball_in_hand = r;  // WPA 1.5: the incoming player has the cue ball in hand
}

std::optional<Foul> pool_standard_foul(const ShotContext& shot, const std::vector<int>& on, bool rail_required,
                                       std::string& reason) {
  const ShotFacts& f = shot.facts;
  if (shot.miscue) {
    reason = "miscue: the noisy strike was beyond the miscue limit (judged a foul)";
    return Foul::miscue;
  }
  if (f.pocketed(shot.cue_ball)) {
    reason = "WPA 6.1: the cue ball was pocketed";
    return Foul::scratch;
  }
  if (f.first_contact < 0) {
    reason = "WPA 6.2: the cue ball touched no ball";
    return Foul::no_contact;
  }
  const bool first_on = std::find(on.begin(), on.end(), f.first_contact) != on.end();
  const bool simultaneous_on = f.first_contact_simultaneous >= 0 &&
                               std::find(on.begin(), on.end(), f.first_contact_simultaneous) != on.end();
  if (!first_on && !simultaneous_on) {
    reason = "WPA 6.2: the cue ball first touched the " + std::to_string(f.first_contact) + ", not a ball on";
    return Foul::wrong_ball_first;
  }
  if (rail_required && !rail_after_contact(f)) {
    reason = "WPA 6.3: no ball was pocketed and no ball touched a rail after the contact";
    return Foul::no_rail_after_contact;
  }
  return std::nullopt;
}

bool cue_ball_not_out_of_kitchen(const ShotContext& shot) {
  const ShotFacts& f = shot.facts;
  if (f.first_contact < 0) return false;
  const SimulationBall* first = find_ball(shot.shot.balls, f.first_contact);
  if (first == nullptr) return false;
  const double string_x = head_string_x(shot.shot.table);
  if (!(first->state.position.x < string_x)) return false;  // WPA 1.5: a ball on the string or past it may be played
  for (const HeadStringCrossing& c : f.head_string_crossings)
    if (c.ball == shot.cue_ball && !c.toward_head && c.time <= f.first_contact_time) return false;
  return true;
}

void respot_if_pocketed(GameState& next, Ruling& ruling, const std::vector<int>& pocketed, int id) {
  if (std::find(pocketed.begin(), pocketed.end(), id) == pocketed.end()) return;
  if (respot_on_long_string(next.table, id, 0)) ruling.respotted.push_back(id);
}

PlacementRegion region_of(PlacementRegion::Kind kind) {
  PlacementRegion r;
  r.kind = kind;
  return r;
}

// ------------------------------------------------------------------ the rotation games

void set_on_lowest(GameState& next) {
  const int lowest = lowest_object_ball(next.table);
  next.on = lowest < 0 ? std::vector<int>{} : std::vector<int>{lowest};
}

void rotation_foul(GameState& next, Ruling& ruling, Foul foul, int shooter, const std::vector<int>& pocketed,
                   int game_ball, const std::string& rule, const std::string& what, std::string reason) {
  pool_foul(next, ruling, foul, shooter, PlacementRegion::Kind::anywhere, std::move(reason));
  respot_if_pocketed(next, ruling, pocketed, game_ball);
  const int limit = next.config.fouls_to_lose;
  if (limit > 0 && of(next.fouls_in_a_row, shooter) >= limit)
    win_rack(next, ruling, opponent(shooter),
             rule + ": " + std::to_string(limit) + " consecutive fouls lose the " + what);
}

void offer_play_or_pass(GameState& next, Ruling& ruling, int shooter) {
  next.phase = GamePhase::decision;
  next.to_shoot = opponent(shooter);
  next.decisions = {Decision::play, Decision::pass};
  ruling.turn_over = true;
}

Judgement judge_push_out(const ShotContext& shot, Judgement j, const std::vector<int>& pocketed, int game_ball,
                         const std::string& rule, const std::string& three_foul_rule, const std::string& what) {
  const int shooter = shot.shooter;
  std::string reason;
  const std::optional<Foul> f = pool_standard_foul(shot, {}, false, reason);
  if (f == Foul::miscue || f == Foul::scratch) {
    rotation_foul(j.next, j.ruling, *f, shooter, pocketed, game_ball, three_foul_rule, what, reason);
    return j;
  }
  of(j.next.fouls_in_a_row, shooter) = 0;
  respot_if_pocketed(j.next, j.ruling, pocketed, game_ball);
  offer_play_or_pass(j.next, j.ruling, shooter);
  j.ruling.reason = rule + ": push-out; the opponent plays from here or passes it back";
  return j;
}

}  // namespace cueball
