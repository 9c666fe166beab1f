// What a shot did, read off the simulator's events and trajectories
// (shot_facts.hpp). One pass over the events sorts them into the facts; the
// head-string crossings follow each trajectory segment's exact path
// (contact_prediction.hpp quadratic_path); the frozen balls compare the
// start positions.
#include "cueball/simulation/shot_facts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cueball/physics/contact_prediction.hpp"
#include "cueball/table/placement.hpp"

namespace cueball {

namespace {

// The event pass: everything that follows from the events in order.
void read_events(const SimulationResult& r, ShotFacts& f) {
  int cue_cushions = 0;
  bool contacted = false;
  for (const Event& e : r.events) {
    switch (e.type) {
      case EventType::ball_ball: {
        f.contacts.push_back({e.time, e.ball, e.other});
        if (e.ball != f.cue_ball && e.other != f.cue_ball) break;
        const int hit = e.ball == f.cue_ball ? e.other : e.ball;
        f.cue_cushions_before_contact.push_back({e.time, hit, cue_cushions});
        if (!contacted) {
          contacted = true;
          f.first_contact = hit;
          f.first_contact_time = e.time;
        } else if (f.first_contact_simultaneous < 0 && hit != f.first_contact &&
                   e.time - f.first_contact_time <= kSimultaneousContactTime) {
          f.first_contact_simultaneous = hit;
        }
        break;
      }
      case EventType::ball_cushion:
        f.cushions.push_back({e.time, e.ball, e.other, contacted});
        if (e.ball == f.cue_ball) ++cue_cushions;
        break;
      case EventType::ball_jaw: f.jaws.push_back({e.time, e.ball, e.other}); break;
      case EventType::ball_pocket: f.pots.push_back({e.time, e.ball, e.other}); break;
      default: break;
    }
  }
}

// Appends the times in (a, b] at which x(t) - line changes side on one
// trajectory piece, given that it is monotone on [a, b]. Bisection to the
// last bit: crossings are few, and the answer must not depend on a
// quadratic formula's cancellation.
void crossing_between(const QuadraticPath& q, double line, double a, double b, double t0, int id,
                      std::vector<HeadStringCrossing>& out) {
  const auto x = [&](double t) { return q.position.x + t * q.velocity.x + 0.5 * t * t * q.acceleration.x; };
  const bool head_a = x(a) < line, head_b = x(b) < line;
  if (head_a == head_b) return;
  double lo = a, hi = b;
  for (int k = 0; k < 200 && lo < hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    ((x(mid) < line) == head_a ? lo : hi) = mid;
  }
  out.push_back({t0 + hi, id, head_b});
}

// The head-string crossings of one ball, in time order.
void head_string_crossings(const BallTrajectory& b, double end_time, double line, const Parameters& p,
                           std::vector<HeadStringCrossing>& out) {
  for (std::size_t k = 0; k < b.segments.size(); ++k) {
    const TrajectorySegment& seg = b.segments[k];
    const double until = k + 1 < b.segments.size() ? b.segments[k + 1].start_time
                         : b.pocketed              ? b.pocket_time
                                                   : end_time;
    const double span = until - seg.start_time;
    if (!(span > 0.0)) continue;
    const QuadraticPath q = quadratic_path(seg.state, p);
    // x(t) is monotone on each side of its extremum -v_x / a_x.
    double turn = q.acceleration.x != 0.0 ? -q.velocity.x / q.acceleration.x : -1.0;
    if (!(turn > 0.0 && turn < span)) turn = span;
    crossing_between(q, line, 0.0, turn, seg.start_time, b.id, out);
    if (turn < span) crossing_between(q, line, turn, span, seg.start_time, b.id, out);
  }
}

// Balls touching other balls or cushions at the start.
void frozen_at_start(const Table& table, const Parameters& p, const SimulationResult& r, ShotFacts& f) {
  const double radius = p.ball.radius;
  for (std::size_t i = 0; i < r.balls.size(); ++i) {
    const Vec2 pi = r.balls[i].segments.front().state.position;
    for (std::size_t j = i + 1; j < r.balls.size(); ++j) {
      const Vec2 pj = r.balls[j].segments.front().state.position;
      if (norm(pj - pi) <= 2.0 * radius + kFrozenGap) f.frozen_balls.push_back({r.balls[i].id, r.balls[j].id});
    }
    for (std::size_t c = 0; c < table.cushions.size(); ++c) {
      const CushionSegment& s = table.cushions[c];
      if (distance_to_segment(s, pi) <= cushion_contact_distance(s.contact_height, radius) + kFrozenGap)
        f.frozen_to_cushion.push_back({r.balls[i].id, static_cast<int>(c)});
    }
  }
}

}  // namespace

void shot_facts_into(const SimulationResult& result, int cue_ball, ShotFacts& f) {
  f.cue_ball = cue_ball;
  f.first_contact = -1;
  f.first_contact_time = std::numeric_limits<double>::quiet_NaN();
  f.first_contact_simultaneous = -1;
  f.contacts.clear();
  f.pots.clear();
  f.cushions.clear();
  f.cue_cushions_before_contact.clear();
  f.jaws.clear();
  f.head_string_crossings.clear();
  f.frozen_balls.clear();
  f.frozen_to_cushion.clear();
  read_events(result, f);
}

ShotFacts shot_facts(const SimulationResult& result, int cue_ball) {
  ShotFacts f;
  shot_facts_into(result, cue_ball, f);
  return f;
}

ShotFacts shot_facts(const Table& table, const Parameters& parameters, const SimulationResult& result, int cue_ball) {
  ShotFacts f = shot_facts(result, cue_ball);
  const double line = head_string_x(table);
  for (const BallTrajectory& b : result.balls)
    if (!b.segments.empty()) head_string_crossings(b, result.end_time, line, parameters, f.head_string_crossings);
  std::stable_sort(f.head_string_crossings.begin(), f.head_string_crossings.end(),
                   [](const HeadStringCrossing& a, const HeadStringCrossing& b) { return a.time < b.time; });
  if (std::all_of(result.balls.begin(), result.balls.end(), [](const BallTrajectory& b) { return !b.segments.empty(); }))
    frozen_at_start(table, parameters, result, f);
  return f;
}

bool ShotFacts::pocketed(int id) const { return pocket_of(id) >= 0; }

int ShotFacts::pocket_of(int id) const {
  for (const Pot& p : pots)
    if (p.ball == id) return p.pocket;
  return -1;
}

int ShotFacts::cushion_count(int id) const {
  return static_cast<int>(std::count_if(cushions.begin(), cushions.end(), [&](const CushionHit& c) { return c.ball == id; }));
}

int ShotFacts::cushion_count_after_first_contact(int id) const {
  return static_cast<int>(std::count_if(cushions.begin(), cushions.end(),
                                        [&](const CushionHit& c) { return c.ball == id && c.after_first_contact; }));
}

std::vector<int> ShotFacts::balls_to_cushion_after_first_contact() const {
  std::vector<int> out;
  for (const CushionHit& c : cushions)
    if (c.after_first_contact && std::find(out.begin(), out.end(), c.ball) == out.end()) out.push_back(c.ball);
  return out;
}

std::vector<int> ShotFacts::balls_touched_by_cue() const {
  std::vector<int> out;
  for (const CueCushionsBeforeContact& c : cue_cushions_before_contact)
    if (std::find(out.begin(), out.end(), c.ball) == out.end()) out.push_back(c.ball);
  return out;
}

}  // namespace cueball
