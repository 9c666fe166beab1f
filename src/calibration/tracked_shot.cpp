#include "cueball/calibration/tracked_shot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "cueball/core/errors.hpp"

namespace cueball {

namespace {

std::string num(double v) { return format_number(v); }

void check_ball(const TrackedBall& b, const Table& table, const std::string& at) {
  if (b.t.empty()) throw InvalidArgument(at + ".t", at + ".t is empty (a ball needs at least one sample)");
  if (b.t.size() > kMaxTrackedSamples)
    throw InvalidArgument(at + ".t", at + ".t has " + std::to_string(b.t.size()) + " samples; allowed: at most " +
                                         std::to_string(kMaxTrackedSamples));
  if (b.x.size() != b.t.size() || b.y.size() != b.t.size()) {
    const std::string which = b.x.size() != b.t.size() ? ".x" : ".y";
    const std::size_t n = b.x.size() != b.t.size() ? b.x.size() : b.y.size();
    throw InvalidArgument(at + which, at + which + " has " + std::to_string(n) + " values; allowed: as many as " + at +
                                          ".t (" + std::to_string(b.t.size()) + ")");
  }
  const double margin = kMaxLayoutNudge;
  for (std::size_t i = 0; i < b.t.size(); ++i) {
    const std::string k = "[" + std::to_string(i) + "]";
    if (!std::isfinite(b.t[i]) || std::abs(b.t[i]) > kMaxRecordSeconds)
      throw InvalidArgument(at + ".t" + k, b.t[i], "[" + num(-kMaxRecordSeconds) + ", " + num(kMaxRecordSeconds) + "] s",
                            "sample time");
    if (i > 0 && !(b.t[i] > b.t[i - 1]))
      throw InvalidArgument(at + ".t" + k, at + ".t" + k + " = " + num(b.t[i]) + " is not after the previous sample " +
                                               num(b.t[i - 1]) + " (sample times must increase)");
    if (!std::isfinite(b.x[i]) || b.x[i] < -margin || b.x[i] > table.length + margin)
      throw InvalidArgument(at + ".x" + k, b.x[i], "[" + num(-margin) + ", " + num(table.length + margin) + "] m",
                            "position along the table");
    if (!std::isfinite(b.y[i]) || b.y[i] < -margin || b.y[i] > table.width + margin)
      throw InvalidArgument(at + ".y" + k, b.y[i], "[" + num(-margin) + ", " + num(table.width + margin) + "] m",
                            "position across the table");
  }
}

std::size_t first_moving_sample(const TrackedBall& b) {
  for (std::size_t i = 1; i < b.t.size(); ++i)
    if (std::hypot(b.x[i] - b.x[0], b.y[i] - b.y[0]) >= kMoveThreshold) return i;
  return b.t.size();
}

// The index of the last sample at or before record time t, or -1.
long last_at_or_before(const TrackedBall& b, double t) {
  const auto it = std::upper_bound(b.t.begin(), b.t.end(), t);
  return static_cast<long>(it - b.t.begin()) - 1;
}

// Steps of prepare_shot over one context.
struct Preparation {
  const TrackedShot& shot;
  const Table& table;
  const std::string& path;
  PreparedShot out;
  std::vector<const TrackedBall*> order;  // layout order
  double rest_time = 0.0;                 // record time of the cue ball's last sample at rest
};

void order_balls(Preparation& p) {
  for (const TrackedBall& b : p.shot.balls)
    if (b.name == p.shot.cue_ball) p.order.push_back(&b);
  for (const TrackedBall& b : p.shot.balls)
    if (b.name != p.shot.cue_ball) p.order.push_back(&b);
  for (const TrackedBall* b : p.order) p.out.names.push_back(b->name);
}

// The strike: after the cue ball's last sample at rest, before its first
// moving one; its first moving samples give the aim and speed estimates.
void estimate_strike(Preparation& p) {
  const TrackedBall& c = *p.order[0];
  const std::size_t k = first_moving_sample(c);
  p.rest_time = c.t[k - 1];
  const double dx = c.x[k] - c.x[0], dy = c.y[k] - c.y[0];
  p.out.aim_estimate_deg = std::atan2(dy, dx) * 180.0 / 3.14159265358979323846;
  // Speed over the first two moving samples when they are close in time,
  // else from the first one and the rest sample.
  double speed = 0.0;
  if (k + 1 < c.t.size() && c.t[k + 1] - c.t[k] < 0.1)
    speed = std::hypot(c.x[k + 1] - c.x[k], c.y[k + 1] - c.y[k]) / (c.t[k + 1] - c.t[k]);
  else
    speed = std::hypot(dx, dy) / std::max(c.t[k] - c.t[k - 1], 0.02);
  p.out.speed_estimate = std::clamp(speed, 0.05, 10.0);
  // Estimated strike: the first moving sample's distance travelled back at that speed.
  const double back = std::hypot(dx, dy) / p.out.speed_estimate;
  p.out.origin = std::max(c.t[k] - back, p.rest_time);
  p.out.strike_min = std::max(p.rest_time - p.out.origin, -0.05);
  p.out.strike_max = c.t[k] - p.out.origin - 1e-4;
  if (c.t[k] - c.t[0] > 0.5)
    p.out.notes.push_back("the record starts " + num(c.t[k] - c.t[0]) + " s before the cue ball moves; samples up to " +
                          num(p.rest_time) + " s are the layout");
}

void build_layout(Preparation& p) {
  const double R = p.table.ball.radius;
  for (std::size_t j = 0; j < p.order.size(); ++j) {
    const TrackedBall& b = *p.order[j];
    const long i = std::max(last_at_or_before(b, p.rest_time), 0L);
    SimulationBall s;
    s.id = static_cast<int>(j);
    s.name = b.name;
    s.state.position = {b.x[static_cast<std::size_t>(i)], b.y[static_cast<std::size_t>(i)]};
    p.out.layout.push_back(s);
  }
  // Onto the table (clear of the cushions), then apart from one another; a
  // few rounds since a push may move a ball back against a cushion.
  const double gap = 1e-6;
  std::vector<Vec2> given;
  for (const SimulationBall& s : p.out.layout) given.push_back(s.state.position);
  for (int round = 0; round < 8; ++round) {
    for (SimulationBall& s : p.out.layout) {
      s.state.position.x = std::clamp(s.state.position.x, R + gap, p.table.length - R - gap);
      s.state.position.y = std::clamp(s.state.position.y, R + gap, p.table.width - R - gap);
    }
    bool overlap = false;
    for (std::size_t a = 0; a < p.out.layout.size(); ++a)
      for (std::size_t b = a + 1; b < p.out.layout.size(); ++b) {
        Vec2& pa = p.out.layout[a].state.position;
        Vec2& pb = p.out.layout[b].state.position;
        const double dx = pb.x - pa.x, dy = pb.y - pa.y, d = std::hypot(dx, dy);
        if (d >= 2 * R + gap) continue;
        overlap = true;
        const double ux = d > 0 ? dx / d : 1.0, uy = d > 0 ? dy / d : 0.0;
        const double push = (2 * R + 2 * gap - d) / 2;
        pa.x -= ux * push, pa.y -= uy * push;
        pb.x += ux * push, pb.y += uy * push;
      }
    if (!overlap && round > 0) break;
  }
  for (std::size_t j = 0; j < p.out.layout.size(); ++j) {
    const Vec2 q = p.out.layout[j].state.position;
    const double moved = std::hypot(q.x - given[j].x, q.y - given[j].y);
    if (moved > kMaxLayoutNudge)
      throw InvalidArgument(p.path + ".balls." + p.out.names[j],
                            p.path + ".balls." + p.out.names[j] + " at the strike (" + num(given[j].x) + ", " +
                                num(given[j].y) + ") is " + num(moved) + " m from a legal place; allowed: at most " +
                                num(kMaxLayoutNudge) + " m (off the table or inside another ball)");
    if (moved > 1e-9)
      p.out.notes.push_back(p.out.names[j] + " moved " + num(moved * 1000) + " mm onto a legal place");
  }
}

void collect_samples(Preparation& p) {
  p.out.duration = 0.0;
  for (std::size_t j = 0; j < p.order.size(); ++j) {
    const TrackedBall& b = *p.order[j];
    int n = 0;
    // The position held since the last written sample: the layout's at the strike.
    const Vec2 start = p.out.layout[j].state.position;
    double held_t = 0.0, held_x = start.x, held_y = start.y;
    for (std::size_t i = 0; i < b.t.size(); ++i) {
      if (b.t[i] <= p.rest_time) continue;  // the layout, before the strike
      const double t = b.t[i] - p.out.origin;
      // Dead band: until this sample the ball stayed near the last one written.
      const bool resting = first_moving_sample(b) == b.t.size();
      for (double h = held_t + kHoldStep; resting && h < t - kHoldStep / 2; h += kHoldStep)
        p.out.samples.push_back({static_cast<int>(j), h, held_x, held_y, true});
      p.out.samples.push_back({static_cast<int>(j), t, b.x[i], b.y[i], false});
      held_t = t, held_x = b.x[i], held_y = b.y[i];
      p.out.duration = std::max(p.out.duration, t);
      ++n;
    }
    p.out.samples_per_ball.push_back(n);
    const std::size_t k = first_moving_sample(b);
    p.out.moved.push_back(k < b.t.size() ? 1 : 0);
    p.out.departure.push_back(k < b.t.size() ? b.t[k] - p.out.origin : std::numeric_limits<double>::infinity());
  }
}

// The first object ball to depart, if the record tells it from the next one.
void find_first_object_ball(Preparation& p) {
  const std::vector<double>& d = p.out.departure;
  int first = -1;
  for (std::size_t j = 1; j < d.size(); ++j)
    if (std::isfinite(d[j]) && (first < 0 || d[j] < d[static_cast<std::size_t>(first)])) first = static_cast<int>(j);
  if (first < 0) return;
  for (std::size_t j = 1; j < d.size(); ++j)
    if (static_cast<int>(j) != first && d[j] - d[static_cast<std::size_t>(first)] < kContactOrderGap) return;
  p.out.first_object_ball = first;
}

}  // namespace

void validate_tracked_shot(const TrackedShot& shot, const Table& table, const std::string& path) {
  if (shot.balls.empty()) throw InvalidArgument(path + ".balls", path + ".balls is empty (a shot needs its balls)");
  if (shot.balls.size() > kMaxTrackedBalls)
    throw InvalidArgument(path + ".balls", path + ".balls has " + std::to_string(shot.balls.size()) +
                                               " balls; allowed: at most " + std::to_string(kMaxTrackedBalls));
  std::set<std::string> names;
  for (const TrackedBall& b : shot.balls) {
    const std::string at = path + ".balls." + quote_input(b.name);
    if (b.name.empty()) throw InvalidArgument(path + ".balls", path + ".balls has a ball with an empty name");
    if (!names.insert(b.name).second) throw InvalidArgument(at, at + " is given twice");
    check_ball(b, table, path + ".balls." + b.name);
  }
  if (!names.count(shot.cue_ball))
    throw InvalidArgument(path + ".cue_ball", path + ".cue_ball = " + quote_input(shot.cue_ball) +
                                                  " is not one of the shot's balls");
  for (const TrackedBall& b : shot.balls)
    if (b.name == shot.cue_ball && first_moving_sample(b) == b.t.size())
      throw InvalidArgument(path + ".balls." + b.name,
                            path + ".balls." + b.name + " (the cue ball) never moves " + num(kMoveThreshold) +
                                " m from its first sample: nothing to fit");
}

PreparedShot prepare_shot(const TrackedShot& shot, const Table& table, const std::string& path) {
  Preparation p{shot, table, path, {}, {}, 0.0};
  p.out.id = shot.id;
  order_balls(p);
  estimate_strike(p);
  build_layout(p);
  collect_samples(p);
  find_first_object_ball(p);
  return p.out;
}

}  // namespace cueball
