// The random agent: any legal action, drawn uniformly (agent.hpp). A
// baseline, and the rules' stress test: it reaches fouls, decisions and
// placements a sensible player never would.
//
// Draws, in this order, from RandomStream(splitmix64(seed)): a decision
// uniformly among the open ones; else the cue speed uniform on [0.3, 8]
// m/s, the aim uniform on [-180, 180) degrees, elevation 0 with
// probability 0.8 and else uniform on [0, 30] degrees, the tip offsets
// uniform on the disc of radius 0.4 ball radii (inside the miscue limit);
// the cue ball's spot when in hand (always when it is off the table, else
// with probability 1/2) uniform over the region's free spots; a push-out
// with probability 0.3 when allowed; a called ball uniformly among the
// callable ones and a pocket uniformly; a nomination uniformly among the
// nominable balls.
#include <cmath>
#include <numbers>

#include "cueball/agents/agent.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/core/random.hpp"

namespace cueball {

namespace {

template <class T>
T pick(const std::vector<T>& v, RandomStream& rng) {
  return v[static_cast<std::size_t>(rng.integer(0, static_cast<int>(v.size()) - 1))];
}

// Tries for a free spot in the region before giving up (a region full of
// balls: never on a real table).
constexpr int kPlacementAttempts = 10000;

}  // namespace

Action random_action(const GameState& state, std::uint64_t seed) {
  const LegalActions legal = legal_actions(state);
  RandomStream rng(splitmix64(seed));
  Action a;
  if (!legal.shoot) {
    if (legal.decisions.empty()) throw InvalidArgument("state", "no action is open (the game is over)");
    a.decision = pick(legal.decisions, rng);
    return a;
  }
  a.strike.speed = rng.uniform(0.3, 8.0);
  a.strike.aim_deg = rng.uniform(-180.0, 180.0);
  a.strike.elevation_deg = rng.chance(0.8) ? 0.0 : rng.uniform(0.0, 30.0);
  const double r = 0.4 * std::sqrt(rng.unit()), phi = rng.uniform(0.0, 2.0 * std::numbers::pi);
  a.strike.side = r * std::cos(phi);
  a.strike.height = r * std::sin(phi);
  if (legal.ball_in_hand) {
    const bool off_table = find_ball(state.table.balls, legal.cue_ball) == nullptr;
    if (off_table || rng.chance(0.5)) {
      std::vector<Vec2> others;
      for (const SimulationBall& b : state.table.balls)
        if (b.id != legal.cue_ball) others.push_back(b.state.position);
      const Table& t = state.table.table;
      a.place = random_free_spot(t, others, t.ball.radius, rng, kPlacementAttempts, *legal.ball_in_hand);
      if (!a.place && off_table) throw InvalidArgument("state", "no free spot for the cue ball in its region");
    }
  }
  a.push_out = legal.push_out && rng.chance(0.3);
  if (legal.call_required && !legal.callable.empty()) {
    a.called_ball = pick(legal.callable, rng);
    a.called_pocket = rng.integer(0, static_cast<int>(state.table.table.pockets.size()) - 1);
  }
  if (legal.nominate_required && !legal.nominable.empty()) a.nominate = pick(legal.nominable, rng);
  return a;
}

}  // namespace cueball
