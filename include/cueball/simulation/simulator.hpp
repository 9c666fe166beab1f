// An exact, event-driven simulation of a shot on a table.
//
// Between events every ball follows the closed-form motion of
// cloth_motion.hpp; events are found by polynomial root finding
// (contact_prediction.hpp) and resolved by the physics kernels:
//   motion transitions     cloth_motion.hpp (sliding -> rolling -> spinning -> rest, spin stop)
//   ball - ball            ball_collision_model.hpp (by name; an impulse with restitution and ball-ball friction by default)
//   ball - cushion, jaw    cushion_model.hpp (by name; Mathavan 2010 solved exactly by default), in the frame of
//                          the cushion's nose line or of the jaw's normal at the contact
//   ball - pocket          capture by the pocket's circle (table.hpp)
// The simulation advances from event to event, never by time steps; the
// trajectory of every ball is exact between events and can be evaluated at
// any time from the result.
//
// Determinism and bounds. Events are ordered by time, then by kind, then by
// the balls' and cushions' indices, so equal input gives bit-identical
// output. Predictions are cached per ball and per pair and recomputed exactly
// for the balls whose state an event changed (equipment-and-pitfalls.md,
// item 7). Touching balls (resting_contact.hpp): a pair touching and closing,
// or pressed together by its acceleration, is a contact at that instant
// (contact_prediction.hpp); contacts closing at 1 cm/s or faster are impacts:
// a pair touching nothing else by the ball-ball model, and a pair touching
// others (a frozen rack, a Newton's cradle; balls apart by less than the
// impact's compression count as touching) with every contact of that
// cluster at once (contact_cluster.hpp), whatever the balls' order; slower
// or pressed ones are resting contacts, resolved
// by impulses that leave nothing closing or pressing and only remove energy
// (a slow group of touching balls moves on as one), so no cascade of
// contacts at one instant goes on. A ball not pocketed stays inside the
// closed playing area (inside_playing_area, table.hpp) at every event, and
// no centre gets closer than the contact distance by more than 1e-9 m
// (stress/ checks both). A run stops with SimulationError after
// `max_events` events, never hangs.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "cueball/models/ball_collision/coulomb_impulse.hpp"
#include "cueball/models/ball_collision/model.hpp"
#include "cueball/models/cushion/model.hpp"
#include "cueball/physics/cloth_motion.hpp"
#include "cueball/models/cushion/impact.hpp"
#include "cueball/core/parameters.hpp"
#include "cueball/table/table.hpp"

namespace cueball {

/// A ball placed on the table at the start of a simulation.
struct SimulationBall {
  int id = 0;
  std::string name;
  BallState state;
};

struct SimulationSettings {
  /// Ball and cloth: the pool preset by default, as the default table, rack
  /// and scenario, the CLI and the Python module (README "Units and defaults").
  Parameters parameters = pool_parameters();
  /// The cushion model and its constants (cushion_model.hpp): by default
  /// Mathavan 2010 solved exactly, with the authors' fit e_e = 0.98, mu_w =
  /// 0.14. The exact solver agrees with the Euler scheme they fitted with to
  /// 1e-3 m/s, so their constants hold for it too (test_cushion_impact).
  CushionSettings cushion;
  /// The ball-ball model (ball_collision_model.hpp) and its constants.
  BallCollisionModel ball_collision_model = BallCollisionModel::coulomb_impulse;
  BallCollisionParameters ball_collision = ball_collision_alciatore();
  int max_events = 100000;                  ///< SimulationError beyond this
  friend bool operator==(const SimulationSettings&, const SimulationSettings&) = default;
};

enum class EventType {
  cue_strike,     ///< the shot starts (t = 0)
  slide_to_roll,  ///< slip reaches zero
  roll_to_spin,   ///< stops translating but still turning about the vertical
  roll_to_rest,   ///< stops translating, nothing turning
  spin_stop,      ///< vertical spin reaches zero
  ball_ball,
  ball_cushion,
  ball_jaw,
  ball_pocket,
};

const char* to_string(EventType t);

struct Event {
  double time = 0.0;
  EventType type = EventType::cue_strike;
  int ball = -1;   ///< id of the (first) ball
  int other = -1;  ///< ball_ball: the other ball's id; cushion/jaw/pocket: its index in the table; else -1
};

/// One piece of a ball's trajectory: from `start_time` it moves in closed form
/// from `state` until the next segment starts.
struct TrajectorySegment {
  double start_time = 0.0;
  BallState state;
};

struct BallTrajectory {
  int id = 0;
  std::string name;
  std::vector<TrajectorySegment> segments;  ///< ordered by start_time; the first at t = 0
  bool pocketed = false;
  int pocket = -1;            ///< index into Table::pockets when pocketed
  double pocket_time = 0.0;
  BallState final_state;      ///< at the end (for a pocketed ball: where it was captured, at rest)
};

struct SimulationResult {
  std::vector<Event> events;         ///< in the order resolved
  std::vector<BallTrajectory> balls; ///< in the input order
  double end_time = 0.0;             ///< every ball is at rest or pocketed

  /// The state of ball `index` (input order) at time t >= 0, evaluated from
  /// its exact trajectory.
  BallState state_at(std::size_t index, double t, const Parameters& p) const;
};

/// A ball failed to stay in a physical state, or the event limit was reached.
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The ball with id `id`, or nullptr.
const SimulationBall* find_ball(const std::vector<SimulationBall>& balls, int id);
/// Index in `balls` of the ball with id `id`; balls.size() when none has it.
std::size_t index_of(const std::vector<SimulationBall>& balls, int id);

/// Throws InvalidArgument for bad input: parameters out of range, duplicate
/// ids, a ball off the table or overlapping a cushion, two balls overlapping
/// (by more than 1e-9 m), non-finite or implausible velocities and spins.
/// The table and the settings are checked once per thread while they stay
/// the same: a call with a table and settings equal (==) to those of the
/// thread's last call that passed checks only the balls (a loop of
/// simulate() calls on one scenario pays for its table once).
void validate_simulation_input(const Table& table, const std::vector<SimulationBall>& balls,
                               const SimulationSettings& settings);

/// Simulates until every ball is at rest or pocketed. The balls' states at
/// t = 0 are taken as given (apply the cue strike first: cue_strike.hpp).
/// What the simulation derives from the table and the settings alone (the
/// cushions' and jaws' impact models and contact lines, the pockets grouped
/// with their jaws) is kept per thread while they stay equal (==) to the
/// last simulation's, here and in simulate_unchecked(): a loop over one
/// table pays for it once (about 2 us a shot on a pool table). The result
/// never depends on the simulations before it.
SimulationResult simulate(const Table& table, const std::vector<SimulationBall>& balls,
                          const SimulationSettings& settings);

/// simulate() without validate_simulation_input(), for inner loops whose
/// table, balls and settings already passed it (a batch re-striking one
/// validated scenario). Invalid input here is undefined behaviour.
SimulationResult simulate_unchecked(const Table& table, const std::vector<SimulationBall>& balls,
                                    const SimulationSettings& settings);

}  // namespace cueball
