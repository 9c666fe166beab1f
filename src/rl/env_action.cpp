// The learner's action (rl/environment.hpp): its scales, decoding it into a
// game Action (illegal parts named, never thrown), the action masks, and
// its mirror image.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/enum_names.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/rl/environment.hpp"
#include "cueball/table/placement.hpp"

namespace cueball {

namespace {

constexpr double kDegPerRad = 180.0 / 3.14159265358979323846;

constexpr std::array<ActionForm, 2> kActionForms{ActionForm::raw, ActionForm::target};
constexpr std::array<BreakPolicy, 2> kBreakPolicies{BreakPolicy::recommended, BreakPolicy::agent};

// A component in [-1, 1]: clipped, NaN read as 0.
double unit(double v) { return std::isnan(v) ? 0.0 : std::clamp(v, -1.0, 1.0); }

// [-1, 1] -> [lo, hi].
double span(double v, double lo, double hi) { return lo + 0.5 * (unit(v) + 1.0) * (hi - lo); }

bool contains(const std::vector<int>& v, int id) { return std::find(v.begin(), v.end(), id) != v.end(); }

std::string list(const std::vector<int>& v) {
  std::string s;
  for (const int id : v) s += (s.empty() ? "" : ", ") + std::to_string(id);
  return s.empty() ? "none" : s;
}

const SimulationBall* ball_with_id(const Scenario& table, int id) {
  for (const SimulationBall& b : table.balls)
    if (b.id == id) return &b;
  return nullptr;
}

// The balls the discrete `ball` may name (action_masks' ball mask).
const std::vector<int>& selectable_balls(const LegalActions& legal) {
  if (legal.nominate_required) return legal.nominable;
  if (legal.call_required && !legal.callable.empty()) return legal.callable;
  return legal.on;
}

// The strike's tip offsets: the square [-1, 1]^2 onto the disc of radius
// kMiscueOffsetFraction along rays from the centre.
void tip_offsets(double s, double h, double& side, double& height) {
  const double r = std::hypot(s, h);
  if (r == 0.0) {
    side = height = 0.0;
    return;
  }
  // A hair inside the limit, so that rounding never puts the rim beyond it.
  const double k = kMiscueOffsetFraction * (1.0 - 1e-12) * std::max(std::abs(s), std::abs(h)) / r;
  side = s * k;
  height = h * k;
}

// The ghost-ball aim from the cue ball at `cue` to pot the ball at `object`
// into `pocket`, degrees.
double ghost_ball_aim_deg(Vec2 cue, Vec2 object, Vec2 pocket, double radius) {
  Vec2 u{pocket.x - object.x, pocket.y - object.y};
  const double n = std::hypot(u.x, u.y);
  if (n > 0.0) u = {u.x / n, u.y / n};
  const Vec2 ghost{object.x - 2.0 * radius * u.x, object.y - 2.0 * radius * u.y};
  return std::atan2(ghost.y - cue.y, ghost.x - cue.x) * kDegPerRad;
}

// Step 1 of decode_action: a decision, when one is due or asked for.
bool decode_decision(const LegalActions& legal, const EnvAction& a, DecodedAction& out) {
  if (legal.shoot) {
    if (a.decision != 0) out.illegal = "decision: a shot is due, not a decision (choose 0)";
    return false;
  }
  const int d = a.decision - 1;
  for (const Decision open : legal.decisions)
    if (static_cast<int>(open) == d) {
      out.action.decision = open;
      return true;
    }
  out.action.decision = legal.decisions.front();
  out.illegal = "decision: " + std::to_string(a.decision) + " is not open; took " +
                std::string(to_string(legal.decisions.front()));
  return true;
}

// Step 2: the strike, raw or relative to the target's ghost-ball aim.
void decode_strike(const EnvOptions& options, const GameState& state, const LegalActions& legal, const EnvAction& a,
                   DecodedAction& out) {
  ShotAction& s = out.action.strike;
  s.speed = span(a.strike[0], kEnvMinSpeed, options.max_speed);
  s.elevation_deg = span(a.strike[2], 0.0, kEnvMaxElevationDeg);
  tip_offsets(unit(a.strike[3]), unit(a.strike[4]), s.side, s.height);
  if (options.form == ActionForm::raw) {
    s.aim_deg = unit(a.strike[1]) * 180.0;
    return;
  }
  const Scenario& t = state.table;
  const int pockets = static_cast<int>(t.table.pockets.size());
  const SimulationBall* cue = ball_with_id(t, legal.cue_ball);
  const SimulationBall* object = ball_with_id(t, a.ball);
  Vec2 from = cue ? cue->state.position : Vec2{};
  if (out.action.place) from = *out.action.place;
  if (!object || a.ball == legal.cue_ball || a.pocket < 0 || a.pocket >= pockets || (!cue && !out.action.place)) {
    if (out.illegal.empty())
      out.illegal = "ball: " + std::to_string(a.ball) + " and pocket " + std::to_string(a.pocket) +
                    " are not a target on the table (pockets 0.." + std::to_string(pockets - 1) + ")";
    s.aim_deg = unit(a.strike[1]) * kEnvMaxCutOffsetDeg;
    return;
  }
  const double aim = ghost_ball_aim_deg(from, object->state.position, t.table.pockets[static_cast<std::size_t>(a.pocket)].centre,
                                        t.table.ball.radius);
  s.aim_deg = aim + unit(a.strike[1]) * kEnvMaxCutOffsetDeg;
}

// Step 3: the cue ball's spot when in hand.
void decode_place(const GameState& state, const LegalActions& legal, const EnvAction& a, DecodedAction& out) {
  if (!legal.ball_in_hand) return;
  const Table& t = state.table.table;
  const PlacementRegion box = bounding_rectangle(t, *legal.ball_in_hand);
  const double r = t.ball.radius;  // a centre closer to the box's edge than that touches the cushion
  const Vec2 p{span(a.place[0], box.x_min + r, box.x_max - r), span(a.place[1], box.y_min + r, box.y_max - r)};
  out.action.place = p;
  std::vector<Vec2> others;
  for (const SimulationBall& b : state.table.balls)
    if (b.id != legal.cue_ball) others.push_back(b.state.position);
  if (!in_region(t, *legal.ball_in_hand, p) || !is_free_spot(t, others, p, t.ball.radius))
    out.illegal = "place: the spot is outside the region " + std::string(to_string(legal.ball_in_hand->kind)) +
                  " or not free";
}

// Step 4: the call, the nomination and the push-out.
void decode_call(const GameState& state, const LegalActions& legal, const EnvAction& a, DecodedAction& out) {
  const int pockets = static_cast<int>(state.table.table.pockets.size());
  if (legal.call_required) {
    out.action.called_ball = a.ball;
    out.action.called_pocket = a.pocket;
    if (!contains(legal.callable, a.ball) && out.illegal.empty())
      out.illegal = "ball: " + std::to_string(a.ball) + " may not be called; allowed: " + list(legal.callable);
    else if ((a.pocket < 0 || a.pocket >= pockets) && out.illegal.empty())
      out.illegal = "pocket: " + std::to_string(a.pocket) + " is out of range [0, " + std::to_string(pockets - 1) + "]";
  }
  if (legal.nominate_required) {
    out.action.nominate = a.ball;
    if (!contains(legal.nominable, a.ball) && out.illegal.empty())
      out.illegal = "ball: " + std::to_string(a.ball) + " may not be nominated; allowed: " + list(legal.nominable);
  }
  if (a.push_out != 0) {
    out.action.push_out = true;
    if (!legal.push_out && out.illegal.empty()) out.illegal = "push_out: a push-out is not available";
  }
}

}  // namespace

const char* to_string(ActionForm form) { return form == ActionForm::raw ? "raw" : "target"; }
std::optional<ActionForm> action_form_from_string(std::string_view name) { return value_named(kActionForms, name); }
const char* to_string(BreakPolicy p) { return p == BreakPolicy::recommended ? "recommended" : "agent"; }
std::optional<BreakPolicy> break_policy_from_string(std::string_view name) {
  return value_named(kBreakPolicies, name);
}

DecodedAction decode_action(const EnvOptions& options, const GameState& state, const EnvAction& a) {
  DecodedAction out;
  if (state.over) {
    out.illegal = "the game is over";
    return out;
  }
  const LegalActions legal = legal_actions(state);
  if (decode_decision(legal, a, out)) return out;
  decode_place(state, legal, a, out);
  decode_strike(options, state, legal, a, out);
  decode_call(state, legal, a, out);
  return out;
}

ActionMasks action_masks(const GameState& state) {
  ActionMasks m;
  m.ball.assign(static_cast<std::size_t>(env_ball_count(state.config.kind)), 0);
  m.pocket.assign(state.table.table.pockets.size(), 0);
  if (state.over) return m;
  const LegalActions legal = legal_actions(state);
  if (!legal.shoot) {
    for (const Decision d : legal.decisions) m.decision[static_cast<std::size_t>(static_cast<int>(d) + 1)] = 1;
    return m;
  }
  m.decision[0] = 1;
  m.push_out[0] = 1;
  m.push_out[1] = legal.push_out ? 1 : 0;
  for (const int id : selectable_balls(legal))
    if (id >= 0 && static_cast<std::size_t>(id) < m.ball.size() && ball_with_id(state.table, id))
      m.ball[static_cast<std::size_t>(id)] = 1;
  std::fill(m.pocket.begin(), m.pocket.end(), std::uint8_t{1});
  return m;
}

EnvAction mirror_action(const Table& table, const EnvAction& a) {
  EnvAction m = a;
  m.strike[1] = -a.strike[1];
  m.strike[3] = -a.strike[3];
  m.place[1] = -a.place[1];
  if (a.pocket >= 0 && static_cast<std::size_t>(a.pocket) < table.pockets.size()) {
    const Vec2 c = table.pockets[static_cast<std::size_t>(a.pocket)].centre;
    const Vec2 image{c.x, table.width - c.y};
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < table.pockets.size(); ++i) {
      const double d = std::hypot(table.pockets[i].centre.x - image.x, table.pockets[i].centre.y - image.y);
      if (d < best) {
        best = d;
        m.pocket = static_cast<int>(i);
      }
    }
  }
  return m;
}

}  // namespace cueball
