// Checks of a simulated shot for the simulator's tests: how deep any ball
// went into another or into a cushion or jaw, and how much the balls'
// kinetic energy ever rose from one event to the next.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "cueball/simulation/simulator.hpp"
#include "cueball/table/table.hpp"

namespace cueball {

// The largest depth by which any two balls overlap, or a ball enters a
// cushion or a jaw, at every event and at `per_interval` points between
// consecutive events (the trajectories are exact there).
inline double deepest_penetration(const Table& table, const SimulationResult& r, const Parameters& p,
                           int per_interval = 40) {
  const double radius = p.ball.radius;
  double worst = 0.0;
  const auto check = [&](double t) {
    std::vector<Vec2> on;
    for (std::size_t i = 0; i < r.balls.size(); ++i) {
      if (r.balls[i].pocketed && t >= r.balls[i].pocket_time) continue;
      const Vec2 c = r.state_at(i, t, p).position;
      for (const Vec2& o : on) worst = std::max(worst, 2 * radius - norm(c - o));
      on.push_back(c);
      for (const CushionSegment& seg : table.cushions) {
        const Vec2 along = seg.end - seg.start;
        const double foot = dot(c - seg.start, along) / dot(along, along);
        if (foot < 0 || foot > 1) continue;
        const double depth = dot(c - seg.start, inward_normal(seg));
        if (depth < -radius) continue;  // behind the nose line: a pocket's throat
        worst = std::max(worst, cushion_contact_distance(seg.contact_height, radius) - depth);
      }
      for (const JawArc& jaw : table.jaws) worst = std::max(worst, jaw_contact_distance(jaw, radius) - norm(c - jaw.centre));
    }
  };
  for (std::size_t k = 0; k < r.events.size(); ++k) {
    const double t0 = r.events[k].time;
    const double t1 = k + 1 < r.events.size() ? r.events[k + 1].time : r.end_time;
    for (int q = 0; q <= per_interval; ++q) check(t0 + (t1 - t0) * q / per_interval);
  }
  check(r.end_time + 1.0);
  return worst;
}

inline double energy_rise(const SimulationResult& r, const Parameters& p) {
  double previous = std::numeric_limits<double>::infinity(), rise = 0.0;
  for (const Event& e : r.events) {
    double total = 0.0;
    for (std::size_t i = 0; i < r.balls.size(); ++i)
      if (!(r.balls[i].pocketed && e.time >= r.balls[i].pocket_time)) total += kinetic_energy(r.state_at(i, e.time, p), p.ball);
    rise = std::max(rise, total - previous);
    previous = total;
  }
  return rise;
}

}  // namespace cueball
