// Snooker (WPBSA Official Rules of Snooker, section 3 "The Game", with the
// definitions of section 2). Ball ids (rack.hpp): 0 the cue ball, 1..15 the
// reds (1..reds in the short games), 16 yellow, 17 green, 18 brown, 19 blue,
// 20 pink, 21 black. Values (WPBSA 3.1): a red 1, the colours 2..7.
//
// The ball on, as GameState keeps it:
//   * reds:                 on = the reds on the table, colour_on = 0;
//   * a colour after a red: on = the colours on the table, colour_on = 0, and
//                           the stroke must nominate one of them (Action::nominate,
//                           WPBSA 3.3);
//   * the clearance:        on = {colour_on}, the lowest colour left (WPBSA 3.3).
// In a decision after a foul (phase decision), `on` keeps the foul stroke's
// balls on (what `restore` gives back); play and pass put the next player
// on the reds, or on the lowest colour when none is left.
//
// Choices the engine makes where the rule book leaves a judgement to the
// referee (documented here and in GameConfig):
//   * The miss (WPBSA 3.14; config.miss_rule): a foul in which the cue ball
//     fails to first hit a ball on (no contact, or the wrong ball first) is a
//     miss unless the striker was snookered before the stroke (no ball on
//     with both extreme edges clear, the section 2 definition, computed by
//     table/line_of_sight.hpp) — the practice of top-level referees, who
//     call nearly every such failure. A miscue is never a miss. The third
//     miss in a row with a full-ball view of a ball on (every straight
//     stroke to it clear; misses_in_a_row counts them, and a restore keeps
//     the count) loses the frame.
//   * Free ball (WPBSA 3.12): after a foul that leaves the cue ball on the
//     table snookered (as above, for the balls the next player is on). The
//     rule's condition that the free ball must not snooker the opponent is
//     not judged. After `restore` no free ball is awarded.
//   * Foul::wrong_pocket here means "a ball not on was potted" (WPBSA 3.11):
//     a colour while on a red, another colour than the one on, a red while on
//     a colour.
//   * A respotted black (WPBSA 3.4) goes to the player the coin toss gives:
//     the engine's coin is the state's shot count, even -> player 0, odd ->
//     player 1 (deterministic, so a game replays bit for bit).
//   * With only the black left and the scores more than 7 apart, nothing can
//     change the result (a foul on the black gives at most 7 and ends the
//     frame): the frame ends there, as the trailing player would concede.
//   * Colours spotted "as near as possible" are put kSpottingGap clear of the
//     ball they would touch (a spot is occupied when a ball there would touch
//     another, section 2).
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "cueball/table/line_of_sight.hpp"
#include "games/rules.hpp"

namespace cueball {

namespace {

constexpr int kYellow = 16;
constexpr int kBlack = 21;
// How far a colour spotted next to a ball is kept from it, m (section 2:
// a ball on a spot must not touch another).
constexpr double kSpottingGap = 1e-4;
// Two balls closer than 2R + this touch (a spot is occupied), m.
constexpr double kTouching = 1e-6;

bool is_red(int id) { return id >= 1 && id <= 15; }
bool is_colour(int id) { return id >= kYellow && id <= kBlack; }
// WPBSA 3.1: a red 1, yellow 2, green 3, brown 4, blue 5, pink 6, black 7.
int value(int id) { return is_red(id) ? 1 : is_colour(id) ? id - 14 : 0; }

std::string ball_name(int id) {
  static const char* const kColours[] = {"yellow", "green", "brown", "blue", "pink", "black"};
  if (id == 0) return "cue";
  if (is_red(id)) return "red" + std::to_string(id);
  if (is_colour(id)) return kColours[id - kYellow];
  return std::to_string(id);
}

bool contains(const std::vector<int>& v, int id) { return std::find(v.begin(), v.end(), id) != v.end(); }

std::vector<int> balls_where(const Scenario& table, bool (*pred)(int)) {
  std::vector<int> out;
  for (const SimulationBall& b : table.balls)
    if (pred(b.id)) out.push_back(b.id);
  std::sort(out.begin(), out.end());
  return out;
}
std::vector<int> reds_on_table(const Scenario& table) { return balls_where(table, is_red); }
std::vector<int> colours_on_table(const Scenario& table) { return balls_where(table, is_colour); }

PlacementRegion the_d() {
  PlacementRegion d;
  d.kind = PlacementRegion::Kind::inside_d;  // WPBSA 3.5, play from in-hand
  return d;
}

// The next player's ball on (after a turn ends or a foul): the reds while
// any is left, else the lowest colour (WPBSA 3.3).
void on_for_next_player(GameState& s) {
  const std::vector<int> reds = reds_on_table(s.table);
  if (!reds.empty()) {
    s.on = reds;
    s.colour_on = 0;
    return;
  }
  const std::vector<int> colours = colours_on_table(s.table);
  s.colour_on = colours.empty() ? 0 : colours.front();
  s.on = colours.empty() ? std::vector<int>{} : std::vector<int>{colours.front()};
}

// After a red is potted: a colour, to be nominated (WPBSA 3.3).
void on_a_colour(GameState& s) {
  s.on = colours_on_table(s.table);
  s.colour_on = 0;
}

bool on_colour_after_red(const GameState& s) { return s.colour_on == 0 && !s.on.empty() && is_colour(s.on.front()); }

// ------------------------------------------------------------------ line of sight

struct View {
  bool snookered = true;  // no ball on with both extreme edges clear (section 2)
  bool full_ball = false; // some ball on fully in view (WPBSA 3.14)
};

View view_from(const Scenario& table, int cue_ball, const std::vector<int>& on) {
  View v;
  const SimulationBall* cue = find_ball(table.balls, cue_ball);
  if (!cue || on.empty()) return v;
  std::vector<Vec2> obstacles;
  for (const SimulationBall& b : table.balls)
    if (b.id != cue_ball && !contains(on, b.id)) obstacles.push_back(b.state.position);
  for (const int id : on) {
    const SimulationBall* target = find_ball(table.balls, id);
    if (!target) continue;
    const BallView bv = view_of_ball(cue->state.position, target->state.position, obstacles, table.table.ball.radius);
    if (bv.both_edges()) v.snookered = false;
    if (bv.full) v.full_ball = true;
  }
  return v;
}

// ------------------------------------------------------------------ spotting colours (WPBSA 3.7)

Vec2 own_spot(const SnookerSpots& s, int id) {
  switch (id) {
    case 16: return s.yellow;
    case 17: return s.green;
    case 18: return s.brown;
    case 19: return s.blue;
    case 20: return s.pink;
    default: return s.black;
  }
}

// A ball of `id` may stand at p: on the bed, clear of the pockets and
// touching no other ball (section 2, "occupied").
bool free_for(const Scenario& table, int id, Vec2 p, double extra_gap) {
  const double R = table.table.ball.radius;
  std::vector<Vec2> others;
  for (const SimulationBall& b : table.balls) {
    if (b.id == id) continue;
    if (norm(b.state.position - p) < 2.0 * R + extra_gap) return false;
    others.push_back(b.state.position);
  }
  return is_free_spot(table.table, others, p, R);
}

// As near as possible to the own spot on the line from it to the top
// cushion (x growing), else towards the bottom cushion: the candidates are
// the spot and every place where the ball would just clear a ball on the line.
std::optional<Vec2> near_own_spot(const Scenario& table, int id, Vec2 spot) {
  const double R = table.table.ball.radius;
  const double reach = 2.0 * R + kSpottingGap;
  std::vector<double> up, down;
  for (const SimulationBall& b : table.balls) {
    if (b.id == id) continue;
    const double dy = b.state.position.y - spot.y;
    if (std::abs(dy) >= reach) continue;
    const double dx = std::sqrt(reach * reach - dy * dy);
    for (const double x : {b.state.position.x - dx, b.state.position.x + dx}) (x >= spot.x ? up : down).push_back(x);
  }
  std::sort(up.begin(), up.end());
  std::sort(down.begin(), down.end(), [](double a, double b) { return a > b; });
  for (const std::vector<double>* side : {&up, &down})
    for (const double x : *side) {
      const Vec2 p{x, spot.y};
      if (free_for(table, id, p, kSpottingGap * 0.5)) return p;
    }
  return std::nullopt;
}

void place_colour(Scenario& table, int id, Vec2 p) {
  put_ball(table, id, p);
  table.balls[index_of(table.balls, id)].name = ball_name(id);
}

// WPBSA 3.7: each colour on its own spot; when that is occupied, on the
// highest-value spot available; when all are, as near as possible to its
// own spot towards the top cushion. Own spots first, then the rest, the
// highest value first.
void respot_colours(Scenario& table, std::vector<int> colours, Ruling& ruling) {
  const SnookerSpots spots = snooker_spots(table.table);
  std::sort(colours.begin(), colours.end(), [](int a, int b) { return a > b; });
  std::vector<int> waiting;
  for (const int id : colours) {
    if (free_for(table, id, own_spot(spots, id), kTouching))
      place_colour(table, id, own_spot(spots, id));
    else
      waiting.push_back(id);
  }
  for (const int id : waiting) {
    std::optional<Vec2> p;
    for (int spot = kBlack; spot >= kYellow && !p; --spot)
      if (free_for(table, id, own_spot(spots, spot), kTouching)) p = own_spot(spots, spot);
    if (!p) p = near_own_spot(table, id, own_spot(spots, id));
    if (p) place_colour(table, id, *p);
  }
  for (const int id : colours)
    if (on_table(table, id)) ruling.respotted.push_back(id);
}

// ------------------------------------------------------------------ end of the frame (WPBSA 3.4)

// The frame ends on the scores; equal scores: the black is respotted, the
// cue ball in hand in the D for the player the coin gives (header comment).
void end_frame(GameState& next, Ruling& ruling, std::string why) {
  const int a = next.scores[0], b = next.scores[1];
  if (a != b) {
    end_game(next, ruling, a > b ? 0 : 1, std::move(why));
    return;
  }
  const bool black_down = !on_table(next.table, kBlack);
  next.table.balls.clear();
  place_colour(next.table, kBlack, snooker_spots(next.table.table).black);
  if (black_down) ruling.respotted.push_back(kBlack);
  next.phase = GamePhase::play;
  next.decisions.clear();
  next.ball_in_hand = the_d();
  next.free_ball = false;
  next.before_miss.clear();
  next.misses_in_a_row = 0;
  next.on = {kBlack};
  next.colour_on = kBlack;
  next.to_shoot = next.shots % 2 == 0 ? 0 : 1;
  if (!ruling.reason.empty()) ruling.reason += "; ";
  ruling.reason += std::move(why) + "; scores level: WPBSA 3.4, the black is respotted and player " +
                   std::to_string(next.to_shoot) + " (the coin: the shot count's parity) plays from in hand in the D";
}

bool only_black(const Scenario& table) {
  for (const SimulationBall& b : table.balls)
    if (b.id != 0 && b.id != kBlack) return false;
  return on_table(table, kBlack);
}

// ------------------------------------------------------------------ judging a stroke

// One stroke as the rules read it, filled by the steps of snooker_judge_shot.
struct Stroke {
  const ShotContext& shot;
  Judgement j;
  int shooter = 0;
  // What the striker was on.
  std::vector<int> on;             // the balls the cue ball may hit first
  std::vector<int> scoring;        // the balls whose pot scores
  std::optional<int> free_ball;    // the nominated free ball
  int on_value = 1;                // the value of the ball on
  // What happened.
  std::vector<int> potted;         // object balls, in order
  std::vector<int> contacted;      // the first contact and a simultaneous one
  bool hit_on = false;
  std::optional<Foul> foul;
  std::string reason;
  int penalty = 0;
};

// The value a ball "concerned" in a foul has: a free ball counts as the ball on (WPBSA 3.12).
int concerned_value(const Stroke& s, int id) { return s.free_ball && id == *s.free_ball ? s.on_value : value(id); }

// Step 1: what the striker was on (WPBSA 3.3; the free ball, 3.12).
void read_ball_on(Stroke& s) {
  const GameState& before = s.shot.before;
  const std::optional<int> nominated = s.shot.action.nominate;
  if (on_colour_after_red(before)) {
    const int c = nominated.value_or(before.on.front());
    s.on = {c};
    s.scoring = {c};
    s.on_value = value(c);
    return;
  }
  s.on = before.on;
  s.scoring = before.on;
  s.on_value = before.colour_on != 0 ? value(before.colour_on) : 1;
  if (before.free_ball && nominated) {
    s.free_ball = *nominated;
    s.on.push_back(*nominated);
    s.scoring.push_back(*nominated);
  }
}

// Step 2: the facts the rules read.
void read_facts(Stroke& s) {
  const ShotFacts& f = s.shot.facts;
  for (const Pot& p : f.pots) s.j.ruling.pocketed.push_back(p.ball);
  s.potted = object_balls_pocketed(f, s.shot.cue_ball);
  if (f.first_contact >= 0) s.contacted.push_back(f.first_contact);
  if (f.first_contact_simultaneous >= 0) s.contacted.push_back(f.first_contact_simultaneous);
  // WPBSA 3.6: two balls may be hit at once only when both are on (two
  // reds, or the free ball and the ball on); a free ball must be among them.
  s.hit_on = !s.contacted.empty();
  for (const int id : s.contacted) s.hit_on = s.hit_on && contains(s.on, id);
  if (s.free_ball) s.hit_on = s.hit_on && contains(s.contacted, *s.free_ball);
}

// Step 3: the foul, if any (WPBSA 3.11), and its value: 4, or the ball on,
// or the highest ball concerned (hit first, hit with it, potted).
void find_foul(Stroke& s) {
  const ShotFacts& f = s.shot.facts;
  std::vector<int> wrong;
  for (const int id : s.potted)
    if (!contains(s.scoring, id)) wrong.push_back(id);
  if (s.shot.miscue) {
    s.foul = Foul::miscue;
    s.reason = "miscue: the noisy strike was beyond the miscue limit (judged a foul)";
  } else if (f.pocketed(s.shot.cue_ball)) {
    s.foul = Foul::scratch;
    s.reason = "WPBSA 3.11: the cue ball was potted (in-off)";
  } else if (f.first_contact < 0) {
    s.foul = Foul::no_contact;
    s.reason = "WPBSA 3.11: the cue ball hit no ball";
  } else if (!s.hit_on) {
    s.foul = Foul::wrong_ball_first;
    s.reason = "WPBSA 3.11: the cue ball first hit " + ball_name(f.first_contact) +
               (f.first_contact_simultaneous >= 0 ? " and " + ball_name(f.first_contact_simultaneous) : "") +
               ", not the ball on" + (s.free_ball ? " (the free ball " + ball_name(*s.free_ball) + ")" : "");
  } else if (!wrong.empty()) {
    s.foul = Foul::wrong_pocket;
    s.reason = "WPBSA 3.11: a ball not on was potted (" + ball_name(wrong.front()) + ")";
  }
  if (!s.foul) return;
  s.penalty = std::max(4, s.on_value);
  for (const int id : s.contacted) s.penalty = std::max(s.penalty, concerned_value(s, id));
  for (const int id : s.potted) s.penalty = std::max(s.penalty, concerned_value(s, id));
}

// Step 4a: a foul. The points go to the opponent (WPBSA 3.11); colours potted
// are respotted, reds stay down; in-off: the cue ball in hand in the D
// (3.5); the next player plays or has the offender play again, or after a
// miss has the balls replaced (3.14); free ball when snookered (3.12).
void apply_foul(Stroke& s) {
  GameState& next = s.j.next;
  Ruling& ruling = s.j.ruling;
  const GameState& before = s.shot.before;
  const int other = opponent(s.shooter);
  ruling.foul = s.foul;
  ruling.reason = s.reason + "; " + std::to_string(s.penalty) + " points to player " + std::to_string(other);
  of(ruling.points, other) += s.penalty;
  of(next.scores, other) += s.penalty;
  ruling.turn_over = true;
  std::vector<int> colours;
  for (const int id : s.potted)
    if (is_colour(id)) colours.push_back(id);
  respot_colours(next.table, colours, ruling);
  if (s.shot.facts.pocketed(s.shot.cue_ball)) next.ball_in_hand = the_d();

  // WPBSA 3.4: with only the black left, a foul ends the frame.
  if (only_black(before.table)) {
    end_frame(next, ruling, "WPBSA 3.4: a foul with only the black left ends the frame");
    return;
  }

  // WPBSA 3.14: the miss, by the criterion of the header comment.
  const bool missed = next.config.miss_rule && *s.foul != Foul::miscue && !s.hit_on;
  std::vector<int> could_be_on = before.on;
  if (s.free_ball) could_be_on.push_back(*s.free_ball);
  const View seen = view_from(s.shot.shot, s.shot.cue_ball, could_be_on);
  const bool miss = missed && !seen.snookered;
  ruling.miss = miss;
  next.misses_in_a_row = miss && seen.full_ball ? before.misses_in_a_row + 1 : 0;
  if (miss && seen.full_ball && next.misses_in_a_row >= 3) {
    end_game(next, ruling, other,
             "WPBSA 3.14: a third miss in a row with a full-ball view of the ball on loses the frame");
    return;
  }
  if (miss) {
    ruling.reason += "; a miss (WPBSA 3.14): the striker was not snookered";
    next.before_miss = s.shot.shot.balls;  // as struck: the cue ball where it was played from
  } else {
    next.before_miss.clear();
  }

  // The next player's ball on decides the free ball (the cue ball must be on the table).
  GameState incoming = next;
  on_for_next_player(incoming);
  next.free_ball = !next.ball_in_hand && view_from(next.table, s.shot.cue_ball, incoming.on).snookered &&
                   !incoming.on.empty();
  if (next.free_ball) ruling.reason += "; the cue ball is snookered: free ball (WPBSA 3.12)";
  next.phase = GamePhase::decision;
  next.to_shoot = other;
  next.decisions = {Decision::play, Decision::pass};
  if (miss) next.decisions.push_back(Decision::restore);
  next.on = before.on;  // the foul stroke's balls on, for `restore`
  next.colour_on = before.colour_on;
}

// Step 4b: a fair stroke: the pots score (WPBSA 3.3), potted colours are
// respotted while they were not the clearance's ball on (3.7), and the
// striker plays on after a score.
void apply_fair_stroke(Stroke& s) {
  GameState& next = s.j.next;
  Ruling& ruling = s.j.ruling;
  const GameState& before = s.shot.before;
  next.misses_in_a_row = 0;
  next.before_miss.clear();
  int points = 0;
  std::vector<int> respot;
  const bool clearance = before.colour_on != 0 && reds_on_table(before.table).empty();
  if (clearance) {
    // The ball on, or else the free ball standing for it (WPBSA 3.12): scored once.
    if (contains(s.potted, before.colour_on) || (s.free_ball && contains(s.potted, *s.free_ball)))
      points = value(before.colour_on);
    if (s.free_ball && contains(s.potted, *s.free_ball)) respot.push_back(*s.free_ball);
  } else {
    for (const int id : s.potted) {
      points += s.free_ball && id == *s.free_ball ? s.on_value : value(id);
      if (is_colour(id)) respot.push_back(id);
    }
  }
  respot_colours(next.table, respot, ruling);
  of(ruling.points, s.shooter) += points;
  of(next.scores, s.shooter) += points;
  if (points == 0) {
    next.to_shoot = opponent(s.shooter);
    ruling.turn_over = true;
    on_for_next_player(next);
    ruling.reason = "fair stroke, nothing potted: the turn passes (WPBSA 3.3)";
  } else if (!clearance && !on_colour_after_red(before)) {
    on_a_colour(next);
    ruling.reason = "a red potted (" + std::to_string(points) + "): the striker is on a colour, to nominate (WPBSA 3.3)";
  } else {
    on_for_next_player(next);
    if (clearance && on_table(next.table, before.colour_on)) {
      // Only the free ball went down: still on the same colour.
      next.on = {before.colour_on};
      next.colour_on = before.colour_on;
    }
    ruling.reason = "a colour potted (" + std::to_string(points) + "): the striker plays on (WPBSA 3.3)";
  }
  if (object_balls(next).empty()) end_frame(next, ruling, "WPBSA 3.4: the last ball (the black) is potted");
}

// Step 5: with only the black left and the scores more than 7 apart, the
// frame is decided (header comment).
void close_decided_frame(Stroke& s) {
  GameState& next = s.j.next;
  if (next.over || !only_black(next.table)) return;
  if (std::abs(next.scores[0] - next.scores[1]) <= value(kBlack)) return;
  end_game(next, s.j.ruling, next.scores[0] > next.scores[1] ? 0 : 1,
           "only the black is left and the scores are more than 7 apart: the frame is decided (conceded)");
}

}  // namespace

GameState snooker_new_game(GameState base) {
  base.table.balls = balls_at_rest(rack_snooker_with_reds(base.table.table, base.config.reds, base.config.rack));
  base.phase = GamePhase::break_shot;
  base.ball_in_hand = the_d();  // WPBSA 3.3(a): the first stroke from in hand
  on_for_next_player(base);
  return base;
}

LegalActions snooker_legal_actions(const GameState& state) {
  LegalActions a;
  a.player = state.to_shoot;
  a.cue_ball = 0;
  a.shoot = state.phase != GamePhase::decision;
  if (!a.shoot) {
    a.decisions = state.decisions;
    return a;
  }
  a.on = state.on;
  a.ball_in_hand = state.ball_in_hand;
  if (on_colour_after_red(state)) {
    a.nominate_required = true;  // WPBSA 3.3: the colour is nominated
    a.nominable = state.on;
  } else if (state.free_ball) {
    a.free_ball = true;  // WPBSA 3.12: any ball may be nominated as the ball on
    for (const int id : object_balls(state))
      if (!contains(state.on, id)) a.nominable.push_back(id);
    std::sort(a.nominable.begin(), a.nominable.end());
  }
  return a;
}

Judgement snooker_judge_shot(const ShotContext& shot) {
  Stroke s{shot, Judgement{{}, shot.before}, shot.shooter, {}, {}, {}, 1, {}, {}, false, {}, {}, 0};
  GameState& next = s.j.next;
  next.table = table_after_shot(shot);
  next.phase = GamePhase::play;
  next.ball_in_hand.reset();
  next.decisions.clear();
  next.free_ball = false;
  read_ball_on(s);
  read_facts(s);
  find_foul(s);
  if (s.foul)
    apply_foul(s);
  else
    apply_fair_stroke(s);
  close_decided_frame(s);
  if (!s.j.next.over) s.j.ruling.turn_over = s.j.next.to_shoot != shot.shooter || s.j.next.phase == GamePhase::decision;
  return std::move(s.j);
}

Judgement snooker_decide(const GameState& state, Decision decision) {
  Judgement j{{}, state};
  GameState& next = j.next;
  const int offender = opponent(state.to_shoot);
  next.phase = GamePhase::play;
  next.decisions.clear();
  switch (decision) {
    case Decision::play:
      on_for_next_player(next);
      next.misses_in_a_row = 0;
      next.before_miss.clear();
      j.ruling.reason = std::string("WPBSA 3.11: the next player plays the table as it is") +
                        (next.free_ball ? ", with a free ball (WPBSA 3.12)" : "");
      break;
    case Decision::pass:
      next.to_shoot = offender;
      on_for_next_player(next);
      next.free_ball = false;
      next.misses_in_a_row = 0;
      next.before_miss.clear();
      j.ruling.turn_over = true;
      j.ruling.reason = "WPBSA 3.11: the offender is asked to play again, from where the balls lie";
      break;
    default: {  // restore (only open after a miss)
      next.table.balls = state.before_miss;
      next.before_miss.clear();
      next.ball_in_hand.reset();
      next.free_ball = false;
      next.to_shoot = offender;
      // The foul stroke's ball on comes back with the balls (kept in `on`).
      next.on.clear();
      for (const int id : state.on)
        if (on_table(next.table, id)) next.on.push_back(id);
      next.colour_on = reds_on_table(next.table).empty() && next.on.size() == 1 ? next.on.front() : 0;
      j.ruling.turn_over = true;
      j.ruling.reason = "WPBSA 3.14: the balls are replaced and the offender plays the stroke again";
      break;
    }
  }
  return j;
}

}  // namespace cueball
