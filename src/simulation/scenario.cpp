// Running a scenario: the strike resolved and applied, the shot simulated
// (its JSON: io/scenario_json.hpp, io/result_json.hpp).
#include "cueball/simulation/scenario.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "cueball/table/cue_obstruction.hpp"

namespace cueball {

CueStrike resolved_strike(const Scenario& s, const CueStrike& strike) {
  CueStrike out = strike;
  if (s.cue && s.cue->target) {
    const SimulationBall* from = find_ball(s.balls, s.cue->ball);
    const SimulationBall* to = find_ball(s.balls, *s.cue->target);
    if (from && to) {
      const Vec2 d = to->state.position - from->state.position;
      out.aim = std::atan2(d.y, d.x) + (strike.aim - s.cue->strike.aim);  // noise on the aim survives
    }
  }
  return out;
}

std::vector<SimulationBall> balls_after_strike(const Scenario& s, const std::optional<CueStrike>& strike) {
  std::vector<SimulationBall> balls = s.balls;
  if (!s.cue) return balls;
  const CueStrike chosen = resolved_strike(s, strike ? *strike : s.cue->strike);
  for (SimulationBall& b : balls) {
    if (b.id == s.cue->ball) b.state = strike_ball(chosen, b.state.position, s.settings.parameters.ball, s.cue_parameters);
  }
  return balls;
}

SimulationResult run_scenario(const Scenario& s) {
  SimulationResult r = simulate(s.table, balls_after_strike(s), s.settings);
  if (s.cue) r.events.insert(r.events.begin(), Event{0.0, EventType::cue_strike, s.cue->ball, -1});
  return r;
}

bool cue_strike_obstructed(const Scenario& s) {
  if (!s.cue || !find_ball(s.balls, s.cue->ball)) return false;
  const SimulationBall* cue = find_ball(s.balls, s.cue->ball);
  std::vector<Vec2> others;
  for (const SimulationBall& b : s.balls)
    if (&b != cue) others.push_back(b.state.position);
  return cue_obstructed(s.table, cue->state.position, others, resolved_strike(s, s.cue->strike),
                        s.settings.parameters.ball.radius);
}

std::vector<BallAfterShot> balls_after_shot(const SimulationResult& r) {
  std::vector<BallAfterShot> out;
  out.reserve(r.balls.size());
  for (const BallTrajectory& b : r.balls) out.push_back({b.id, b.final_state.position, b.pocketed, b.pocketed ? b.pocket : -1});
  return out;
}

Scenario table_after(const Scenario& before, const std::vector<BallAfterShot>& after) {
  Scenario left = before;
  left.cue.reset();
  left.balls.clear();
  for (const SimulationBall& b : before.balls) {
    const auto it = std::find_if(after.begin(), after.end(), [&](const BallAfterShot& a) { return a.id == b.id; });
    if (it == after.end() || it->pocketed) continue;
    SimulationBall at_rest = b;
    at_rest.state = BallState{};
    at_rest.state.position = it->position;
    left.balls.push_back(std::move(at_rest));
  }
  return left;
}

Scenario table_after(const Scenario& before, const SimulationResult& r) { return table_after(before, balls_after_shot(r)); }

}  // namespace cueball
