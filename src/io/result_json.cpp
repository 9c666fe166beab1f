// The simulation result as JSON (io/result_json.hpp): what the CLI's
// simulate --json prints and Python's Result.to_json gives.
#include "cueball/io/result_json.hpp"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "cueball/core/errors.hpp"
#include "cueball/io/table_json.hpp"
#include "cueball/simulation/shot_facts.hpp"
#include "core/angles.hpp"
#include "io/json_output.hpp"

namespace cueball {

namespace {

using Json = nlohmann::json;

}  // namespace

std::string result_to_json(const Scenario& s, const SimulationResult& r, double sample_rate, int indent) {
  const Parameters& p = s.settings.parameters;
  if (!(std::isfinite(sample_rate) && sample_rate >= 0.0))
    throw InvalidArgument("sample_rate", sample_rate, "[0, infinity)", "sampling rate, Hz (0: none)");
  if (sample_rate > 0.0) {
    // Counted in floating point before anything is allocated.
    const double times = std::floor(r.end_time * sample_rate) + 1.0;
    const double states = times * static_cast<double>(r.balls.size());
    if (!(states <= kMaxSamples)) {
      const double most = std::floor(kMaxSamples / static_cast<double>(std::max<std::size_t>(r.balls.size(), 1)));
      throw InvalidArgument("sample_rate", "sample_rate = " + format_number(sample_rate) + " Hz over the shot's " +
                                               format_number(r.end_time) + " s and " + std::to_string(r.balls.size()) +
                                               " balls gives " + format_number(states) + " sampled states; allowed: at most " +
                                               format_number(kMaxSamples) + " (here a rate up to " +
                                               format_number(std::floor(most / std::max(r.end_time, 1e-9))) + " Hz)");
    }
  }
  Json out;
  out["table"] = Json::parse(table_to_json(s.table));
  out["parameters"] = io::parameters_json(p);
  out["parameters"]["cushion_model"] = to_string(s.settings.cushion.model);
  out["parameters"]["ball_collision_model"] = to_string(s.settings.ball_collision_model);
  out["parameters"]["cushion_restitution"] = s.settings.cushion.restitution;
  out["parameters"]["cushion_friction"] = s.settings.cushion.friction;
  if (s.cue) {
    const ShotStrike& c = *s.cue;
    const CueStrike k = resolved_strike(s, c.strike);
    const double radius = p.ball.radius;
    out["cue_strike"] = {{"given", io::cue_json(s)},
                         {"resolved",
                          {{"ball", c.ball},
                           {"target", c.target ? Json(*c.target) : Json(nullptr)},
                           {"speed", k.speed},
                           {"aim_deg", k.aim / kDegree},
                           {"elevation_deg", k.elevation / kDegree},
                           {"side", k.side_offset / radius},
                           {"height", k.height_offset / radius},
                           {"aim_rad", k.aim},
                           {"elevation_rad", k.elevation},
                           {"side_m", k.side_offset},
                           {"height_m", k.height_offset},
                           {"mass", s.cue_parameters.mass},
                           {"tip_restitution", s.cue_parameters.tip_restitution},
                           {"end_mass", s.cue_parameters.end_mass}}}};
  } else {
    out["cue_strike"] = nullptr;
  }
  out["cue_obstructed"] = cue_strike_obstructed(s);
  out["scenario"] = io::scenario_json(s);
  out["end_time"] = r.end_time;
  Json events = Json::array();
  for (const Event& e : r.events) {
    Json ev{{"time", e.time}, {"type", to_string(e.type)}, {"balls", Json::array({e.ball})}};
    switch (e.type) {
      case EventType::ball_ball: ev["balls"].push_back(e.other); break;
      case EventType::ball_cushion:
        ev["cushion"] = e.other;
        ev["cushion_name"] = cushion_name(s.table, static_cast<std::size_t>(e.other));
        break;
      case EventType::ball_jaw:
        ev["jaw"] = e.other;
        ev["jaw_name"] = jaw_name(s.table, static_cast<std::size_t>(e.other));
        break;
      case EventType::ball_pocket: ev["pocket"] = s.table.pockets[static_cast<std::size_t>(e.other)].name; break;
      default: break;
    }
    events.push_back(ev);
  }
  out["events"] = events;
  out["facts"] = io::shot_facts_json(s.table, shot_facts(s.table, p, r, s.cue ? s.cue->ball : -1));
  Json balls = Json::array();
  for (const BallTrajectory& b : r.balls) {
    Json jb = io::state_json(b.final_state);
    jb["id"] = b.id;
    jb["name"] = b.name;
    jb["pocketed"] = b.pocketed;
    jb["pocket"] = b.pocketed ? Json(s.table.pockets[static_cast<std::size_t>(b.pocket)].name) : Json(nullptr);
    jb["pocket_time"] = b.pocketed ? Json(b.pocket_time) : Json(nullptr);
    Json segments = Json::array();
    for (const TrajectorySegment& seg : b.segments) {
      Json js = io::state_json(seg.state);
      js["t"] = seg.start_time;
      js["phase"] = to_string(motion_phase(seg.state, p));
      segments.push_back(js);
    }
    jb["segments"] = segments;
    balls.push_back(jb);
  }
  out["balls"] = balls;
  if (sample_rate > 0.0) {
    const auto count = static_cast<std::size_t>(std::floor(r.end_time * sample_rate)) + 1;
    Json times = Json::array();
    for (std::size_t k = 0; k < count; ++k) times.push_back(static_cast<double>(k) / sample_rate);
    Json per_ball = Json::array();
    for (std::size_t i = 0; i < r.balls.size(); ++i) {
      Json pos = Json::array(), vel = Json::array(), spin = Json::array();
      for (std::size_t k = 0; k < count; ++k) {
        const BallState st = r.state_at(i, static_cast<double>(k) / sample_rate, p);
        pos.push_back(io::vec(st.position));
        vel.push_back(io::vec(st.velocity));
        spin.push_back(io::vec(st.angular_velocity));
      }
      per_ball.push_back({{"id", r.balls[i].id}, {"position", pos}, {"velocity", vel}, {"angular_velocity", spin}});
    }
    out["samples"] = {{"rate_hz", sample_rate}, {"times", times}, {"balls", per_ball}};
  }
  return out.dump(indent);
}

}  // namespace cueball
