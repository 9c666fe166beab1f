// What a shot did: one record computed once from a simulation's result and
// read by everything that asks (the planner's success test, ShotOutcome,
// position play, the benchmark, the game rules).
//
// The facts are the simulator's own events, sorted into what the rule books
// ask about (WPA Rules of Play, WPBSA Rules of Snooker, UMB World Rules of
// Carom): which ball the cue ball hit first, every ball-ball contact in
// order, the pots in order with their pocket and time, the cushion contacts of
// every ball before and after that first contact, the cue ball's cushions
// before each of its ball contacts (three-cushion), jaw contacts, head-string
// crossings and the balls frozen at the start. Nothing here judges: a rule
// reads the facts and decides (games/).
//
// Conventions. Balls are named by id; cushions, jaws and pockets by their
// index in the Table (cushion_name(), jaw_name() and pockets[k].name give
// the names; the result JSON writes both). Times are seconds from the cue
// strike. Lists are in the order the simulator resolved the events, which is
// time order (simulator.hpp, "Determinism").
//
// Simultaneous first contacts. When the cue ball meets two balls at one
// instant (within kSimultaneousContactTime), the simulator resolves them one
// after the other in index order; which one is "first" is then an artefact
// of that order, so `first_contact_simultaneous` names the other one and a
// rule decides (WPA 6.2 "wrong ball first" asks which ball was struck first;
// a simultaneous hit of a legal ball and another is commonly judged legal).
#pragma once

#include <limits>
#include <vector>

#include "cueball/core/parameters.hpp"
#include "cueball/simulation/simulator.hpp"
#include "cueball/table/table.hpp"

namespace cueball {

/// Two contacts of the cue ball closer in time than this are simultaneous, s.
inline constexpr double kSimultaneousContactTime = 1e-9;
/// A ball at most this far from touching another ball or a cushion at the
/// start counts as frozen to it, m: a gap no referee can see (the simulator's
/// own contact tolerance, kContactTolerance, is 1e-9 m).
inline constexpr double kFrozenGap = 1e-6;

/// A ball-ball contact: `ball` and `other` as in the simulator's event.
struct BallContact {
  double time = 0.0;
  int ball = -1;
  int other = -1;
};

/// A ball captured by a pocket.
struct Pot {
  double time = 0.0;
  int ball = -1;
  int pocket = -1;  ///< index into Table::pockets
};

/// A ball's contact with a straight cushion (a ball_cushion event).
struct CushionHit {
  double time = 0.0;
  int ball = -1;
  int cushion = -1;                   ///< index into Table::cushions
  bool after_first_contact = false;   ///< after the cue ball's first contact with a ball
};

/// A ball's contact with a pocket jaw (a ball_jaw event). Kept apart from
/// the cushion contacts; whether it is a "rail" is the rule's to say (the
/// pool games count it as one: games/pool_rules.cpp).
struct JawHit {
  double time = 0.0;
  int ball = -1;
  int jaw = -1;  ///< index into Table::jaws
};

/// The cue ball's contact with ball `ball` (its k-th ball contact) and how
/// many cushions it had met before it (three-cushion: at least three before
/// the second object ball: the three-cushion point of the UMB World Rules of
/// Carom).
struct CueCushionsBeforeContact {
  double time = 0.0;
  int ball = -1;
  int cushions = 0;
};

/// A ball's centre crossing the head string (x = length / 4, rack.hpp).
struct HeadStringCrossing {
  double time = 0.0;
  int ball = -1;
  bool toward_head = false;  ///< crossed into the head side (x < length / 4)
};

/// Two balls touching at the start (WPA 6.7: shooting into a frozen ball counts as contacting it).
struct FrozenBalls {
  int ball = -1;
  int other = -1;
};

/// A ball touching a cushion at the start (the frozen-to-a-rail rules, e.g.
/// WPA 14.1 continuous 6.7.2, snooker and carom variants).
struct FrozenToCushion {
  int ball = -1;
  int cushion = -1;
};

struct ShotFacts {
  int cue_ball = -1;
  /// Id of the first ball the cue ball touches; -1 when it touches none.
  int first_contact = -1;
  double first_contact_time = std::numeric_limits<double>::quiet_NaN();
  /// Id of another ball the cue ball touched within kSimultaneousContactTime
  /// of the first contact; -1 when none (header comment).
  int first_contact_simultaneous = -1;
  std::vector<BallContact> contacts;   ///< every ball-ball contact, in order
  std::vector<Pot> pots;               ///< in order
  std::vector<CushionHit> cushions;    ///< every ball_cushion contact, in order
  std::vector<CueCushionsBeforeContact> cue_cushions_before_contact;  ///< one per cue-ball contact, in order
  std::vector<JawHit> jaws;            ///< in order
  std::vector<HeadStringCrossing> head_string_crossings;  ///< in time order
  std::vector<FrozenBalls> frozen_balls;          ///< pairs touching at the start, ball < other by input order
  std::vector<FrozenToCushion> frozen_to_cushion; ///< at the start

  /// True when ball `id` was pocketed.
  bool pocketed(int id) const;
  /// The pocket ball `id` dropped into, -1 when it was not pocketed.
  int pocket_of(int id) const;
  /// Cushion contacts of ball `id`: all, or only those after the first contact.
  int cushion_count(int id) const;
  int cushion_count_after_first_contact(int id) const;
  /// Distinct balls (the cue ball included) that met a cushion after the
  /// first contact (WPA 6.3: "any ball ... contacts a rail").
  std::vector<int> balls_to_cushion_after_first_contact() const;
  /// The distinct balls the cue ball touched, in the order first touched.
  std::vector<int> balls_touched_by_cue() const;
};

/// The facts of a simulated shot. The start of the shot is read from the
/// result (each trajectory's first segment); `parameters` are the shot's
/// (the head-string crossings follow the exact paths between events).
/// `cue_ball` is the id of the struck ball (no ball of that id: no contacts
/// are the cue ball's, first_contact -1).
ShotFacts shot_facts(const Table& table, const Parameters& parameters, const SimulationResult& result, int cue_ball);

/// The facts that follow from the events alone: everything but
/// head_string_crossings, frozen_balls and frozen_to_cushion (left empty).
/// What batches use (outcome_from_result, batch.hpp).
ShotFacts shot_facts(const SimulationResult& result, int cue_ball);

/// shot_facts(result, cue_ball) into `facts`, reusing its lists' storage: no
/// allocation once they have grown (a batch's worker keeps one).
void shot_facts_into(const SimulationResult& result, int cue_ball, ShotFacts& facts);

}  // namespace cueball
