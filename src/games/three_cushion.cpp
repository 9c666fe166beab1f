// Three-cushion (UMB World Rules of Carom, the edition of 1 January 1989
// with its later sports-rule changes; "UMB Art. 83" is its article 83,
// "Three cushions"). Three balls on a pocketless table: ids 0 white
// (player 0's cue ball), 1 yellow (player 1's), 2 red. Each player strikes
// his own cue ball; the two others are his object balls.
//
// A point (Art. 24, the cannon, with Art. 83 for three-cushion): the cue
// ball touches both object balls and has made at least three cushion
// contacts before it touches the second one (contacts with one cushion count
// each time; ShotFacts::cue_cushions_before_contact counts them). A point
// continues the inning; a shot without a point, or a foul, ends it and the
// opponent plays the balls where they lie (Art. 25, 41). The first player to
// config.race_to points wins (Art. 29).
//
// Choices where the rule books leave one, or where the engine cannot follow
// them:
//   - The opening (Art. 23): red on the top (foot) spot, the opponent's ball
//     (yellow) on the head spot, the opener's (white) on the head string
//     kStartingOffset to the RIGHT of the head spot seen from the head end
//     (y = W/2 - 0.182 m; UMB lets the opener choose the right or the left
//     one of the two starting spots of Art. 13). Player 0 opens: the lag
//     (Art. 22) is not played. The opening shot must hit the red first; a
//     simultaneous hit of the red and the yellow is accepted (no referee can
//     tell them apart).
//   - Frozen balls (Art. 27 lets the player play away from a ball his cue ball
//     touches, or have the balls spotted): the engine plays them away, with
//     no decision to take. A contact with a ball the cue ball was frozen to
//     at the start, made at the strike itself (before any cushion, within
//     kSimultaneousContactTime of the strike), is not counted: the cue ball
//     still has to touch that ball again for it to count. The spotting
//     option is not offered.
//   - A shot that touches no ball scores no point and ends the inning; it is
//     not named a foul (three-cushion has no penalty points and the
//     consequence is the same).
//   - A ball off the table (Art. 28, a foul) cannot happen today: the engine
//     has no airborne phase and the carom table no pockets. The rule is judged
//     all the same for a table that takes a ball off its bed (a custom table
//     with pockets): a foul (Foul::ball_off_table), no point, the inning
//     ends, and the ball is spotted on its opening spot (red the top spot, a
//     cue ball the head spot), or on the first free one of the top, head and
//     centre spots when that is taken (the engine's reading of Art. 28).
//   - Playing with the wrong cue ball (Foul::bad_cue_ball) cannot happen:
//     play() strikes the state's cue ball.
//   - A miscued noisy strike is a foul (Foul::miscue; Art. 41).
//   - No equalizing inning: the race ends when a player reaches race_to (UMB
//     knock-out matches are played without one since the 2019 sports rules).
//   - config.fouls_to_lose does not apply (three-cushion has no such rule);
//     fouls_in_a_row is counted all the same.
#include <algorithm>
#include <array>

#include "cueball/core/errors.hpp"
#include "cueball/table/placement.hpp"
#include "games/rules.hpp"

namespace cueball {

namespace {

constexpr int kWhite = 0;
constexpr int kYellow = 1;
constexpr int kRed = 2;
/// The opener's cue ball from the head spot along the head string, m (the
/// starting spots of UMB Art. 13; 7 3/16 in in the US carom rules).
constexpr double kStartingOffset = 0.182;
/// Cushion contacts the cue ball needs before the second object ball (Art. 83).
constexpr int kCushionsForPoint = 3;

const char* ball_name(int id) {
  switch (id) {
    case kWhite: return "white";
    case kYellow: return "yellow";
    case kRed: return "red";
  }
  return "?";
}

// The spots of UMB Art. 13 on the engine's table: the top (foot) spot, the
// head spot and the centre spot, all on the long string.
Vec2 top_spot(const Table& t) { return foot_spot(t); }
Vec2 head_spot(const Table& t) { return {head_string_x(t), long_string_y(t)}; }
Vec2 centre_spot(const Table& t) { return {0.5 * t.length, long_string_y(t)}; }

void place(Scenario& table, int id, Vec2 p) {
  put_ball(table, id, p);
  table.balls[index_of(table.balls, id)].name = ball_name(id);
}

std::vector<int> object_balls_of(int cue_ball) {
  std::vector<int> out;
  for (const int id : {kWhite, kYellow, kRed})
    if (id != cue_ball) out.push_back(id);
  return out;
}

// What the cue ball did, as Art. 83 asks: the first and the second object
// ball it touched and the cushions it had met before the second.
struct Carom {
  int first = -1;
  int second = -1;
  int cushions_before_second = 0;
  bool point = false;
};

// A contact made at the strike with a ball the cue ball was frozen to (the
// engine's reading of Art. 27: it plays away from that ball).
bool frozen_push(const ShotFacts& facts, const CueCushionsBeforeContact& c) {
  if (c.cushions > 0 || c.time > kSimultaneousContactTime) return false;
  for (const FrozenBalls& f : facts.frozen_balls)
    if ((f.ball == facts.cue_ball && f.other == c.ball) || (f.other == facts.cue_ball && f.ball == c.ball)) return true;
  return false;
}

Carom read_carom(const ShotFacts& facts) {
  Carom k;
  for (const CueCushionsBeforeContact& c : facts.cue_cushions_before_contact) {
    if (frozen_push(facts, c)) continue;
    if (k.first < 0) {
      k.first = c.ball;
    } else if (c.ball != k.first) {
      k.second = c.ball;
      k.cushions_before_second = c.cushions;
      break;
    }
  }
  k.point = k.second >= 0 && k.cushions_before_second >= kCushionsForPoint;
  return k;
}

// Where a ball that left the table goes back (the engine's reading of UMB
// Art. 28): its opening spot, else the first free one of the three spots.
void spot_ball(GameState& next, Ruling& ruling, int id) {
  const Table& t = next.table.table;
  const double r = t.ball.radius;
  std::vector<Vec2> others;
  for (const SimulationBall& b : next.table.balls)
    if (b.id != id) others.push_back(b.state.position);
  const std::array<Vec2, 3> spots{id == kRed ? top_spot(t) : head_spot(t), id == kRed ? head_spot(t) : top_spot(t),
                                  centre_spot(t)};
  for (const Vec2 p : spots) {
    if (is_free_spot(t, others, p, r)) {
      place(next.table, id, p);
      ruling.respotted.push_back(id);
      return;
    }
  }
}

void end_inning(GameState& next, Ruling& ruling, int shooter, std::string reason) {
  next.to_shoot = opponent(shooter);
  next.inning_points = 0;
  ruling.turn_over = true;
  ruling.reason = std::move(reason);
}

void foul(GameState& next, Ruling& ruling, Foul f, int shooter, std::string reason) {
  ruling.foul = f;
  of(next.fouls_in_a_row, shooter) += 1;
  end_inning(next, ruling, shooter, std::move(reason));
}

void set_on(GameState& next) {
  next.on = object_balls_of(next.cue_ball());
}

// The balls that left the bed in the shot (captured by a pocket of a custom table).
std::vector<int> balls_off_table(const ShotContext& shot) {
  std::vector<int> out;
  for (const BallAfterShot& b : shot.after)
    if (b.pocketed) out.push_back(b.id);
  return out;
}

}  // namespace

GameState three_cushion_new_game(GameState base) {
  // UMB Art. 23: the starting position.
  const Table& t = base.table.table;
  base.table.balls.clear();
  place(base.table, kWhite, {head_string_x(t), long_string_y(t) - kStartingOffset});
  place(base.table, kYellow, head_spot(t));
  place(base.table, kRed, top_spot(t));
  base.phase = GamePhase::break_shot;
  base.to_shoot = 0;
  base.breaker = 0;
  base.ball_in_hand.reset();
  base.on = {kRed};  // Art. 23: the opening shot must hit the red first
  return base;
}

LegalActions three_cushion_legal_actions(const GameState& state) {
  return base_legal_actions(state);  // no decisions, no ball in hand, no calls
}

Judgement three_cushion_judge_shot(const ShotContext& shot) {
  Judgement j{{}, shot.before};
  GameState& next = j.next;
  Ruling& ruling = j.ruling;
  const int shooter = shot.shooter;
  next.table = table_after_shot(shot);
  next.phase = GamePhase::play;
  next.decisions.clear();
  const std::vector<int> off = balls_off_table(shot);
  ruling.pocketed = off;
  const Carom carom = read_carom(shot.facts);

  if (shot.miscue) {
    foul(next, ruling, Foul::miscue, shooter, "UMB Art. 41: miscue (the noisy strike was beyond the miscue limit)");
  } else if (!off.empty()) {
    foul(next, ruling, Foul::ball_off_table, shooter, "UMB Art. 28: a ball left the table; no point");
    for (const int id : off) spot_ball(next, ruling, id);
  } else if (shot.before.phase == GamePhase::break_shot && carom.first >= 0 && carom.first != kRed &&
             shot.facts.first_contact_simultaneous != kRed) {
    foul(next, ruling, Foul::wrong_ball_first, shooter,
         std::string("UMB Art. 23: the opening shot must hit the red first; it hit the ") + ball_name(carom.first));
  } else if (carom.point) {
    of(next.fouls_in_a_row, shooter) = 0;
    of(next.scores, shooter) += 1;
    of(ruling.points, shooter) = 1;
    next.inning_points += 1;
    ruling.reason = "UMB Art. 83: a point (" + std::to_string(carom.cushions_before_second) +
                    " cushions before the second ball); the inning goes on";
    if (of(next.scores, shooter) >= next.config.race_to)
      end_game(next, ruling, shooter, "UMB Art. 29: " + std::to_string(next.config.race_to) + " points reached");
  } else {
    of(next.fouls_in_a_row, shooter) = 0;
    std::string why;
    if (carom.first < 0)
      why = "no ball touched";
    else if (carom.second < 0)
      why = std::string("only the ") + ball_name(carom.first) + " touched";
    else
      why = std::to_string(carom.cushions_before_second) + " cushion" +
            (carom.cushions_before_second == 1 ? "" : "s") + " before the second ball";
    end_inning(next, ruling, shooter, "UMB Art. 83: no point (" + why + "); the inning ends");
  }
  if (!next.over) set_on(next);
  return j;
}

Judgement three_cushion_decide(const GameState& state, Decision decision) {
  // No decision is ever open (validate_action refuses one before this).
  throw InvalidArgument("decision", std::string(to_string(decision)) + " is not open in three_cushion (" +
                                        to_string(state.phase) + ")");
}

}  // namespace cueball
