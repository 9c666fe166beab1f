// The event-driven table simulator; see simulator.hpp for the method, the
// ordering of events and the policy for touching balls.
#include "cueball/simulation/simulator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <tuple>
#include <utility>

#include "cueball/core/errors.hpp"
#include "cueball/physics/contact_prediction.hpp"
#include "cueball/physics/resting_contact.hpp"
#include "cueball/simulation/contact_cluster.hpp"

namespace cueball {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Slow and pressed contacts (resting_contact.hpp) below this closing speed
// are parted by press_apart before any group is formed, m/s.
constexpr double kPressSpeed = 1e-9;

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

// A predicted event: ball index a, and b = the other ball's index (pairs) or
// the cushion / jaw / pocket index.
struct Candidate {
  double time = kInfinity;
  EventType type = EventType::cue_strike;
  int a = -1;
  int b = -1;
};

// Deterministic total order: time, then kind, then indices.
bool earlier(const Candidate& x, const Candidate& y) {
  if (x.time != y.time) return x.time < y.time;
  if (x.type != y.type) return x.type < y.type;
  if (x.a != y.a) return x.a < y.a;
  return x.b < y.b;
}

// An axis-aligned box bounding a path over an interval (or a cushion's
// reach): a few comparisons reject most candidate contacts before any
// polynomial is formed.
struct Box {
  Vec2 lo, hi;
};

// The box of a quadratic path over [0, horizon]: the box of its Bezier
// control points, which contain the path (convex hull property). A ball that
// is not translating has horizon +infinity and a zero path: its position.
Box path_box(const QuadraticPath& s, double horizon) {
  if (!std::isfinite(horizon)) {
    if (s.velocity == Vec2{} && s.acceleration == Vec2{}) return {s.position, s.position};
    constexpr double inf = std::numeric_limits<double>::infinity();
    return {{-inf, -inf}, {inf, inf}};
  }
  const Vec2 p1 = s.position + (0.5 * horizon) * s.velocity;
  const Vec2 p2 = s.position + horizon * s.velocity + (0.5 * horizon * horizon) * s.acceleration;
  return {{std::min({s.position.x, p1.x, p2.x}), std::min({s.position.y, p1.y, p2.y})},
          {std::max({s.position.x, p1.x, p2.x}), std::max({s.position.y, p1.y, p2.y})}};
}

// True when the boxes come within `gap` of each other.
bool boxes_within(const Box& a, const Box& b, double gap) {
  return a.lo.x - gap <= b.hi.x && b.lo.x - gap <= a.hi.x && a.lo.y - gap <= b.hi.y && b.lo.y - gap <= a.hi.y;
}

// Slack added to every box test so that rounding in the boxes can never
// reject a contact the polynomial would find (a contact is found to ~1e-15 m).
constexpr double kBoxSlack = 1e-9;

// Whether the segment from a to b meets the closed box (Liang-Barsky clipping).
bool segment_meets_box(Vec2 a, Vec2 b, const Box& box) {
  double t0 = 0.0, t1 = 1.0;
  const Vec2 d = b - a;
  const double p[4] = {-d.x, d.x, -d.y, d.y};
  const double q[4] = {a.x - box.lo.x, box.hi.x - a.x, a.y - box.lo.y, box.hi.y - a.y};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0.0) {
      if (q[k] < 0.0) return false;
    } else {
      const double t = q[k] / p[k];
      if (p[k] < 0.0) t0 = std::max(t0, t);
      else t1 = std::min(t1, t);
    }
  }
  return t0 <= t1;
}

// A box wholly inside the playing area (inside_playing_area, table.hpp),
// so that most positions are checked with four comparisons: the table's
// extent less 0.1 m on each side (clear of the pockets), kept only when
// its corners are inside and no edge of the boundary polygon (noses and the
// chords between them) meets it. Empty when that fails (an odd custom table).
Box box_inside_playing_area(const Table& table) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const Box empty{{kInf, kInf}, {-kInf, -kInf}};
  if (table.cushions.empty()) return empty;
  Box box{{kInf, kInf}, {-kInf, -kInf}};
  for (const CushionSegment& c : table.cushions)
    for (Vec2 q : {c.start, c.end}) {
      box.lo = {std::min(box.lo.x, q.x), std::min(box.lo.y, q.y)};
      box.hi = {std::max(box.hi.x, q.x), std::max(box.hi.y, q.y)};
    }
  box.lo = box.lo + Vec2{0.1, 0.1};
  box.hi = box.hi - Vec2{0.1, 0.1};
  if (!(box.lo.x < box.hi.x && box.lo.y < box.hi.y)) return empty;
  for (Vec2 corner : {box.lo, box.hi, Vec2{box.lo.x, box.hi.y}, Vec2{box.hi.x, box.lo.y}})
    if (!inside_playing_area(table, corner)) return empty;
  const std::size_t n = table.cushions.size();
  for (std::size_t i = 0; i < n; ++i) {
    const CushionSegment& c = table.cushions[i];
    if (segment_meets_box(c.start, c.end, box) || segment_meets_box(c.end, table.cushions[(i + 1) % n].start, box))
      return empty;
  }
  return box;
}

// A pocket and the jaws nearest to it (jaws far from every pocket form
// groups of their own), with a circle containing all their contact circles.
struct PocketGroup {
  int pocket = -1;
  std::vector<std::size_t> jaws;
  Vec2 centre;
  double radius = 0.0;
};

// What a simulation derives from the table and the settings alone: the
// ball-ball contact, each cushion's and jaw's impact model and contact
// line, the pockets grouped with their jaws, a box inside the playing area.
// Built once for a table and settings on each thread and kept while a
// thread's simulations use the same ones (table_contacts()), so that a loop
// of simulations on one table (a planner's trials, a batch's noisy shots, a
// user's loop) pays for it once: about 2 us of a pool table's simulation.
struct TableContacts {
  BallCollisionContact ball_contact;
  ClusterSettings cluster_settings;  // the ball-ball model's e, phenolic balls' K / m
  std::vector<CushionContact> cushion_models, jaw_models;
  std::vector<ContactLine> cushion_lines;
  std::vector<Box> cushion_boxes;  // where a ball centre can touch each cushion
  std::vector<double> jaw_distance;
  std::vector<PocketGroup> groups;
  Box inner_box;  // wholly inside the playing area (check_on_table's fast path)
};

void group_pockets_and_jaws(const Table& table, TableContacts& c) {
  for (std::size_t q = 0; q < table.pockets.size(); ++q)
    c.groups.push_back({static_cast<int>(q), {}, table.pockets[q].centre, table.pockets[q].radius});
  for (std::size_t j = 0; j < table.jaws.size(); ++j) {
    const Vec2 centre = table.jaws[j].centre;
    PocketGroup* nearest = nullptr;
    for (PocketGroup& g : c.groups)
      if (g.pocket >= 0 && (!nearest || norm(centre - g.centre) < norm(centre - nearest->centre))) nearest = &g;
    if (!nearest || norm(centre - nearest->centre) > 0.3) {
      c.groups.push_back({-1, {j}, centre, c.jaw_distance[j]});
      continue;
    }
    nearest->jaws.push_back(j);
    nearest->radius = std::max(nearest->radius, norm(centre - nearest->centre) + c.jaw_distance[j]);
  }
}

TableContacts make_table_contacts(const Table& table, const SimulationSettings& settings) {
  const Parameters& p = settings.parameters;
  TableContacts c;
  c.ball_contact = ball_collision_contact(p, settings.ball_collision_model, settings.ball_collision);
  c.cluster_settings.restitution = c.ball_contact.model == BallCollisionModel::mathavan_2014
                                       ? c.ball_contact.mathavan.restitution
                                       : c.ball_contact.coulomb.restitution;
  c.cluster_settings.stiffness = hertz_stiffness_per_mass(p.ball);
  // Contacts left slower than half the impacts' threshold are resting
  // contacts (resting_contact.hpp).
  c.cluster_settings.slow_speed = 0.5 * kPushSpeed;
  // A table has one contact height or a few: each model (and its
  // validation) is built once.
  std::vector<std::pair<double, CushionContact>> by_height;
  const auto model_for = [&](double contact_height) {
    for (const auto& [height, model] : by_height)
      if (height == contact_height) return model;
    by_height.emplace_back(contact_height, cushion_contact(p, settings.cushion, contact_height));
    return by_height.back().second;
  };
  for (const CushionSegment& s : table.cushions) {
    c.cushion_models.push_back(model_for(s.contact_height));
    c.cushion_lines.push_back(contact_line(s.start, s.end, cushion_contact_distance(s.contact_height, p.ball.radius)));
    // A ball centre touching this cushion lies within the contact distance
    // of the segment.
    const double d = c.cushion_lines.back().contact_distance + kBoxSlack;
    c.cushion_boxes.push_back({{std::min(s.start.x, s.end.x) - d, std::min(s.start.y, s.end.y) - d},
                               {std::max(s.start.x, s.end.x) + d, std::max(s.start.y, s.end.y) + d}});
  }
  for (const JawArc& j : table.jaws) {
    c.jaw_models.push_back(model_for(j.contact_height));
    c.jaw_distance.push_back(j.radius + cushion_contact_distance(j.contact_height, p.ball.radius));
  }
  group_pockets_and_jaws(table, c);
  c.inner_box = box_inside_playing_area(table);
  return c;
}

// The table contacts of this table and these settings: this thread's last
// ones when the table (its ball too) and the settings are the same (==,
// which no NaN passes), else built anew. Shared, so that a simulation keeps
// its own while another on the same thread replaces them.
std::shared_ptr<const TableContacts> table_contacts(const Table& table, const SimulationSettings& settings) {
  struct Last {
    Table table;
    SimulationSettings settings;
    std::shared_ptr<const TableContacts> contacts;
  };
  thread_local Last last;
  if (last.contacts && last.settings == settings && last.table == table && last.table.ball == table.ball)
    return last.contacts;
  auto contacts = std::make_shared<const TableContacts>(make_table_contacts(table, settings));  // may throw
  last = {table, settings, contacts};
  return contacts;
}

class Simulation {
 public:
  Simulation(const Table& table, const std::vector<SimulationBall>& balls, const SimulationSettings& settings)
      : table_(table),
        settings_(settings),
        p_(settings.parameters),
        n_(static_cast<int>(balls.size())),
        contacts_(table_contacts(table, settings)),
        ball_contact_(contacts_->ball_contact),
        cluster_settings_(contacts_->cluster_settings),
        cushion_models_(contacts_->cushion_models),
        jaw_models_(contacts_->jaw_models),
        cushion_lines_(contacts_->cushion_lines),
        cushion_boxes_(contacts_->cushion_boxes),
        jaw_distance_(contacts_->jaw_distance),
        groups_(contacts_->groups),
        inner_box_(contacts_->inner_box) {
    result_.balls.resize(balls.size());
    const auto n = balls.size();
    state_.resize(n);
    time_.assign(n, 0.0);
    phase_.resize(n);
    transition_.resize(n);
    path_.resize(n);
    path_end_.resize(n);
    path_box_.resize(n);
    transition_next_.resize(n);
    contact_ = 2.0 * p_.ball.radius;
    active_.assign(n, 1);
    ball_next_.resize(n);
    pair_next_.assign(n == 0 ? 0 : n * (n - 1) / 2, kInfinity);
    // Room for a typical shot's events and segments (a break has ~100
    // events, ~10 segments a ball): the vectors rarely grow.
    result_.events.reserve(16 * n);
    for (std::size_t i = 0; i < n; ++i) {
      result_.balls[i].segments.reserve(16);
      result_.balls[i].id = balls[i].id;
      result_.balls[i].name = balls[i].name;
      state_[i] = balls[i].state;
    }
    for (int i = 0; i < n_; ++i) begin_segment(i);
    for (int i = 0; i < n_; ++i) predict_ball(i);
    for (int i = 0; i < n_; ++i)
      for (int j = i + 1; j < n_; ++j) predict_pair(i, j);
  }

  SimulationResult run() {
    for (;;) {
      const Candidate next = earliest();
      if (!std::isfinite(next.time)) break;
      if (static_cast<int>(result_.events.size()) >= settings_.max_events) {
        std::string last;
        for (std::size_t k = result_.events.size() - std::min<std::size_t>(result_.events.size(), 6); k < result_.events.size(); ++k) {
          const Event& e = result_.events[k];
          last += std::string(last.empty() ? "" : ", ") + to_string(e.type) + " " + std::to_string(e.ball) +
                  (e.other >= 0 ? "/" + std::to_string(e.other) : "") + " at " + num(e.time);
        }
        throw SimulationError("event limit of " + std::to_string(settings_.max_events) + " reached at t = " +
                              num(now_) + " s (raise max_events, or report the shot: it may not end); last events: " + last);
      }
      now_ = next.time;
      resolve(next);
    }
    result_.end_time = now_;
    for (int i = 0; i < n_; ++i) {
      BallTrajectory& b = result_.balls[static_cast<std::size_t>(i)];
      if (!b.pocketed) b.final_state = state_at_now(i);
    }
    return std::move(result_);
  }

 private:
  std::size_t idx(int i) const { return static_cast<std::size_t>(i); }

  // Whether the path's hull over the horizon comes within `radius` of `centre`.
  static bool reaches_circle(const QuadraticPath& s, Vec2 centre, double radius, double horizon) {
    return predict_contact_possible({centre, {}, {}}, s, radius, horizon);
  }

  // The ball's state at now_ (no transition lies between its last update and now_).
  BallState state_at_now(int i) const {
    return evolve_in_phase(state_[idx(i)], phase_[idx(i)], now_ - time_[idx(i)], p_);
  }

  void begin_segment(int i) {
    const std::size_t k = idx(i);
    time_[k] = now_;
    phase_[k] = motion_phase(state_[k], p_);
    transition_[k] = next_transition(state_[k], p_);
    path_[k] = quadratic_path(state_[k], p_);
    path_end_[k] = now_ + phase_end_time(state_[k], p_);
    path_box_[k] = path_box(path_[k], path_end_[k] - now_);
    result_.balls[k].segments.push_back({now_, state_[k]});
  }

  // Ball i's next transition (sliding ends, rolling ends, vertical spin ends).
  void predict_transition(int i) {
    const std::size_t k = idx(i);
    Candidate best;
    const NextTransition& tr = transition_[k];
    if (active_[k]) {
      switch (tr.kind) {
        case Transition::sliding_ends: best = {time_[k] + tr.time, EventType::slide_to_roll, i, -1}; break;
        case Transition::rolling_ends: best = {time_[k] + tr.time, EventType::roll_to_rest, i, -1}; break;
        case Transition::vertical_spin_ends: best = {time_[k] + tr.time, EventType::spin_stop, i, -1}; break;
        case Transition::none: break;
      }
    }
    transition_next_[k] = best;
  }

  // Ball i's earliest contact with the table: a cushion, a jaw or a pocket,
  // within its current path (up to the end of sliding or rolling).
  void predict_ball(int i) {
    predict_transition(i);
    const std::size_t k = idx(i);
    Candidate best;
    if (!active_[k]) {
      ball_next_[k] = best;
      return;
    }
    const double horizon = path_end_[k] - now_;
    const QuadraticPath& s = path_[k];  // predict_ball runs right after begin_segment: time_[k] == now_
    if (phase_[k] == MotionPhase::sliding || phase_[k] == MotionPhase::rolling) {
      const auto consider = [&](std::optional<double> t, EventType type, std::size_t index) {
        if (!t) return;
        const Candidate c{now_ + *t, type, i, static_cast<int>(index)};
        if (earlier(c, best)) best = c;
      };
      const Box& reach = path_box_[k];
      for (std::size_t c = 0; c < cushion_lines_.size(); ++c) {
        if (!boxes_within(reach, cushion_boxes_[c], 0.0)) continue;
        consider(predict_line_contact(s, cushion_lines_[c], horizon), EventType::ball_cushion, c);
      }
      // Each pocket with its jaws sits inside one bounding circle: a path
      // whose hull misses that circle meets none of them.
      for (const PocketGroup& g : groups_) {
        if (!boxes_within(reach, {g.centre, g.centre}, g.radius + kBoxSlack)) continue;
        if (!reaches_circle(s, g.centre, g.radius, horizon)) continue;
        for (std::size_t j : g.jaws)
          consider(predict_circle_contact(s, table_.jaws[j].centre, jaw_distance_[j], horizon), EventType::ball_jaw, j);
        if (g.pocket >= 0) {
          const Pocket& q = table_.pockets[idx(g.pocket)];
          consider(predict_circle_contact(s, q.centre, q.radius, horizon), EventType::ball_pocket, idx(g.pocket));
        }
      }
    }
    ball_next_[k] = best;
  }

  // Pairs i < j row by row: (0,1) (0,2) ... (0,n-1) (1,2) ...
  std::size_t pair_index(int i, int j) const {
    return idx(i) * (2 * idx(n_) - idx(i) - 1) / 2 + idx(j - i - 1);
  }

  // The pair at index k of pair_index()'s order.
  std::pair<int, int> pair_at(std::size_t k) const {
    int i = 0;
    for (std::size_t row = idx(n_) - 1; k >= row; --row) {
      k -= row;
      ++i;
    }
    return {i, i + 1 + static_cast<int>(k)};
  }

  void predict_pair(int i, int j) { pair_next_[pair_index(i, j)] = pair_contact_time(i, j); }

  // The time of the pair's next contact, i < j (none: +infinity).
  double pair_contact_time(int i, int j) const {
    if (!active_[idx(i)] || !active_[idx(j)]) return kInfinity;
    const bool i_moves = phase_[idx(i)] == MotionPhase::sliding || phase_[idx(i)] == MotionPhase::rolling;
    const bool j_moves = phase_[idx(j)] == MotionPhase::sliding || phase_[idx(j)] == MotionPhase::rolling;
    if (!i_moves && !j_moves) return kInfinity;
    // Each box holds its ball's path until the path changes, which bounds
    // the pair's horizon: boxes apart by more than 2R rule contact out.
    if (!boxes_within(path_box_[idx(i)], path_box_[idx(j)], contact_ + kBoxSlack)) return kInfinity;
    const double horizon = std::min(path_end_[idx(i)], path_end_[idx(j)]) - now_;
    const auto t = predict_contact(advance(path_[idx(i)], now_ - time_[idx(i)]),
                                   advance(path_[idx(j)], now_ - time_[idx(j)]), contact_, horizon);
    return t ? now_ + *t : kInfinity;
  }

  // A pair's event is a ball_ball one of balls i < j, and the pairs are
  // kept in the order of their indices (pair_index), the order `earlier`
  // breaks ties by: the pairs' earliest event is the first pair at the
  // smallest time, found by a scan of their times alone, a few instructions
  // a pair (a break has ~100 events and 45 or 120 pairs).
  Candidate earliest() const {
    std::size_t first = pair_next_.size();
    double soonest = kInfinity;
    for (std::size_t k = 0; k < pair_next_.size(); ++k) {
      if (pair_next_[k] < soonest) {
        soonest = pair_next_[k];
        first = k;
      }
    }
    Candidate best;
    if (first < pair_next_.size()) {
      const auto [i, j] = pair_at(first);
      best = {soonest, EventType::ball_ball, i, j};
    }
    for (const Candidate& c : ball_next_)
      if (earlier(c, best)) best = c;
    for (const Candidate& c : transition_next_)
      if (earlier(c, best)) best = c;
    return best;
  }

  // New states for the balls in `changed` at now_: new segments, new predictions.
  void commit(std::initializer_list<int> changed) { commit(std::span<const int>(changed.begin(), changed.size())); }
  void commit(std::span<const int> changed) {
    for (int i : changed) {
      begin_segment(i);
      check_on_table(i);
    }
    for (int i : changed) predict_ball(i);
    for (auto i = changed.begin(); i != changed.end(); ++i)
      for (int j = 0; j < n_; ++j) {
        // A pair of two changed balls is predicted once, with the first.
        if (j != *i && std::find(changed.begin(), i, j) == i) predict_pair(std::min(*i, j), std::max(*i, j));
      }
  }

  void record(EventType type, int i, int other) {
    result_.events.push_back({now_, type, result_.balls[idx(i)].id, other});
  }

  void resolve(const Candidate& c) {
    const int i = c.a;
    const std::size_t k = idx(i);
    switch (c.type) {
      case EventType::spin_stop: {
        // The path does not change when the vertical spin stops: every
        // prediction stands; only the ball's own next transition is new.
        state_[k] = evolve_in_phase(state_[k], phase_[k], transition_[k].time, p_);
        record(EventType::spin_stop, i, -1);
        time_[k] = now_;
        phase_[k] = motion_phase(state_[k], p_);
        transition_[k] = next_transition(state_[k], p_);
        path_[k] = quadratic_path(state_[k], p_);
        result_.balls[k].segments.push_back({now_, state_[k]});
        predict_transition(i);
        break;
      }
      case EventType::slide_to_roll:
      case EventType::roll_to_rest:
      case EventType::roll_to_spin: {
        // Exactly the transition's own duration, so the state snaps onto the new phase.
        state_[k] = evolve_in_phase(state_[k], phase_[k], transition_[k].time, p_);
        EventType type = c.type;
        if (type == EventType::roll_to_rest && motion_phase(state_[k], p_) == MotionPhase::spinning)
          type = EventType::roll_to_spin;
        record(type, i, -1);
        commit({i});
        break;
      }
      case EventType::ball_ball:
        resolve_ball_contact(i, c.b);
        break;
      case EventType::ball_cushion: {
        const CushionSegment& seg = table_.cushions[idx(c.b)];
        const Vec2 e = (seg.end - seg.start) / norm(seg.end - seg.start);
        state_[k] = wall_impact(i, state_at_now(i), perp(e), cushion_models_[idx(c.b)]);
        record(EventType::ball_cushion, i, c.b);
        commit({i});
        break;
      }
      case EventType::ball_jaw: {
        const BallState s = state_at_now(i);
        const Vec2 d = s.position - table_.jaws[idx(c.b)].centre;
        state_[k] = wall_impact(i, s, d / norm(d), jaw_models_[idx(c.b)]);
        record(EventType::ball_jaw, i, c.b);
        commit({i});
        break;
      }
      case EventType::ball_pocket: {
        BallTrajectory& b = result_.balls[k];
        b.pocketed = true;
        b.pocket = c.b;
        b.pocket_time = now_;
        b.final_state = {state_at_now(i).position, {}, {}};
        active_[k] = 0;
        record(EventType::ball_pocket, i, c.b);
        predict_ball(i);
        for (int j = 0; j < n_; ++j)
          if (j != i) predict_pair(std::min(i, j), std::max(i, j));
        break;
      }
      case EventType::cue_strike:
        break;
    }
  }

  // Two balls touching now: an impact when they close at kPushSpeed or
  // faster, else a resting contact (resting_contact.hpp): press_apart for a
  // pair with no closing speed whose slip presses it together, a group
  // otherwise.
  void resolve_ball_contact(int i, int j) {
    BallState a = state_at_now(i), b = state_at_now(j);
    const double closing = -dot(b.velocity - a.velocity, unit(b.position - a.position));
    record(EventType::ball_ball, i, result_.balls[idx(j)].id);
    if (closing >= kPushSpeed) {
      if (touching_cluster(i, j, closing)) {
        resolve_cluster();
        return;
      }
      std::tie(a, b) = collide(a, b, p_.ball, ball_contact_);
    } else if (!(closing <= kPressSpeed && press_apart(a, b, p_.ball.radius))) {
      push_group(i, j);
      return;
    }
    state_[idx(i)] = a;
    state_[idx(j)] = b;
    commit({i, j});
  }

  static Vec2 unit(Vec2 d) { return d / norm(d); }

  // Whether the impact of balls i and j reaches a third ball: cluster_ then
  // holds every active ball touching them, directly or through others, or
  // apart by less than the compression of their impact (contact_cluster.hpp),
  // with their states now, and cluster_contacts_ every such pair among them
  // with its gap.
  bool touching_cluster(int i, int j, double closing) {
    cluster_.clear();
    cluster_contacts_.clear();
    in_cluster_.assign(idx(n_), 0);
    const double reach = std::max(hertz_compression(closing, cluster_settings_.stiffness), kContactTolerance);
    const auto join = [&](int k, const BallState& s) {
      in_cluster_[idx(k)] = 1;
      cluster_.push_back({k, s});
    };
    join(i, state_at_now(i));
    join(j, state_at_now(j));
    for (std::size_t m = 0; m < cluster_.size(); ++m) {
      const int a = cluster_[m].ball;
      for (int k = 0; k < n_; ++k) {
        if (in_cluster_[idx(k)] || !active_[idx(k)]) continue;
        if (!boxes_within(path_box_[idx(a)], path_box_[idx(k)], contact_ + reach + kBoxSlack)) continue;
        const BallState s = state_at_now(k);
        if (norm(s.position - cluster_[m].state.position) - contact_ <= reach) join(k, s);
      }
    }
    if (cluster_.size() == 2) return false;
    for (std::size_t m = 0; m < cluster_.size(); ++m)
      for (std::size_t k = m + 1; k < cluster_.size(); ++k) {
        const double gap = norm(cluster_[k].state.position - cluster_[m].state.position) - contact_;
        if (gap <= reach) cluster_contacts_.push_back({m, k, gap <= kContactTolerance ? 0.0 : gap});
      }
    return true;
  }

  // Every contact of the cluster at once (contact_cluster.hpp). The impact
  // that found it is recorded first, then each other contact that carried
  // an impulse, the lower id first.
  void resolve_cluster() {
    std::vector<Vec2> positions, velocities;
    for (const ClusterBall& c : cluster_) {
      positions.push_back(c.state.position);
      velocities.push_back(c.state.velocity);
    }
    const ClusterImpact impact = resolve_cluster_impact(positions, velocities, cluster_contacts_, cluster_settings_);
    std::vector<int> changed;
    for (std::size_t m = 0; m < cluster_.size(); ++m) {
      BallState s = cluster_[m].state;
      s.velocity = impact.velocities[m];
      state_[idx(cluster_[m].ball)] = s;
      changed.push_back(cluster_[m].ball);
    }
    for (std::size_t k = 0; k < cluster_contacts_.size(); ++k) {
      if (!(impact.impulses[k] > 0.0) || (cluster_contacts_[k].a == 0 && cluster_contacts_[k].b == 1)) continue;
      int a = cluster_[cluster_contacts_[k].a].ball, b = cluster_[cluster_contacts_[k].b].ball;
      if (result_.balls[idx(b)].id < result_.balls[idx(a)].id) std::swap(a, b);
      record(EventType::ball_ball, a, result_.balls[idx(b)].id);
    }
    commit(std::span<const int>(changed));
  }

  // The inward normal of each wall (cushion nose or jaw) that ball state s
  // is entering now (touching and closing, or pressed: contact_prediction.hpp), with the
  // event that names it. A wall the ball only grazes is not one of them.
  struct WallContact {
    Vec2 normal;
    EventType type;
    int index;
    int ball;
  };
  void walls_entered(int ball, const BallState& s, std::vector<WallContact>& out) const {
    const QuadraticPath path = quadratic_path(s, p_);
    const double horizon = phase_end_time(s, p_);
    for (std::size_t c = 0; c < cushion_lines_.size(); ++c) {
      if (!boxes_within({s.position, s.position}, cushion_boxes_[c], 0.0)) continue;
      if (line_contact_now(path, cushion_lines_[c], horizon))
        out.push_back({cushion_lines_[c].normal, EventType::ball_cushion, static_cast<int>(c), ball});
    }
    for (std::size_t j = 0; j < table_.jaws.size(); ++j) {
      const Vec2 d = s.position - table_.jaws[j].centre;
      if (std::abs(norm(d) - jaw_distance_[j]) > kContactTolerance) continue;
      if (contact_now({table_.jaws[j].centre, {}, {}}, path, jaw_distance_[j], horizon))
        out.push_back({unit(d), EventType::ball_jaw, static_cast<int>(j), ball});
    }
  }

  // A slow contact of balls i and j: the group of balls that the contact
  // gathers moves on as one, rolling at its mean velocity, less what walls
  // it touches take away (resting_contact.hpp, 3.). A ball touching the
  // group joins it when the group closes on it, slower than kPushSpeed
  // (faster: an impact of its own at this instant).
  void push_group(int i, int j) {
    std::vector<int> group{i, j};
    std::vector<BallState> now(idx(n_));
    std::vector<char> member(idx(n_), 0);
    for (int k = 0; k < n_; ++k)
      if (active_[idx(k)]) now[idx(k)] = state_at_now(k);
    member[idx(i)] = member[idx(j)] = 1;
    std::vector<WallContact> walls;
    std::vector<Vec2> normals;
    Vec2 mean, v;
    for (;;) {
      Vec2 sum;
      for (int m : group) sum = sum + end_slip(now[idx(m)], p_.ball.radius).velocity;
      mean = sum / static_cast<double>(group.size());
      // The walls the group, rolling at its mean velocity, would enter.
      walls.clear();
      for (int m : group) walls_entered(m, rolling_with(now[idx(m)], mean, p_.ball.radius), walls);
      normals.clear();
      for (const WallContact& w : walls) normals.push_back(w.normal);
      v = nearest_clear_of_walls(mean, normals);
      const std::size_t before = group.size();
      for (std::size_t g = 0; g < before; ++g) {
        const int m = group[g];
        const BallState rolling = rolling_with(now[idx(m)], v, p_.ball.radius);
        const QuadraticPath moving = quadratic_path(rolling, p_);
        for (int k = 0; k < n_; ++k) {
          if (member[idx(k)] || !active_[idx(k)]) continue;
          const Vec2 d = now[idx(k)].position - now[idx(m)].position;
          if (norm(d) - contact_ > kContactTolerance) continue;
          const double closing = -dot(now[idx(k)].velocity - v, unit(d));
          const double horizon = std::min(phase_end_time(rolling, p_), phase_end_time(now[idx(k)], p_));
          if (closing < kPushSpeed && contact_now(moving, quadratic_path(now[idx(k)], p_), contact_, horizon)) {
            member[idx(k)] = 1;
            group.push_back(k);
            record(EventType::ball_ball, m, result_.balls[idx(k)].id);
          }
        }
      }
      if (group.size() == before) break;
    }
    for (const WallContact& w : walls)
      if (dot(mean, w.normal) < 0.0) record(w.type, w.ball, w.index);
    for (int m : group) state_[idx(m)] = rolling_with(now[idx(m)], v, p_.ball.radius);
    commit(std::span<const int>(group));
  }

  // A slow or pressed contact of ball i with a wall of inward normal n
  // (resting_contact.hpp, 1.), taken together with every other wall it
  // touches (a cushion and a jaw at their tangent point, a corner). A ball
  // leaving the wall is here only when it was found pressed, parting too
  // slowly to clear kContactTolerance: it is held at the wall. Should the
  // walls' impulses change nothing (a rolling ball's own deceleration
  // pressing it), the ball rolls on along the wall: its slip ended, no
  // normal velocity.
  BallState rest_on_wall(int i, BallState s, Vec2 n) const {
    const double leaving = dot(s.velocity, n);
    if (leaving > 0.0) s.velocity = s.velocity - leaving * n;
    std::vector<WallContact> walls;
    walls_entered(i, s, walls);
    std::vector<Vec2> normals{n};
    for (const WallContact& w : walls)
      if (normals.size() < kMaxWalls) normals.push_back(w.normal);
    const BallState out = rest_against_walls(s, normals, p_.ball.radius);
    if (!(out.velocity == s.velocity && horizontal(out.angular_velocity) == horizontal(s.angular_velocity)) || leaving > 0.0)
      return out;
    const BallState rolled = end_slip(out, p_.ball.radius);
    const Vec2 along = rolled.velocity - dot(rolled.velocity, n) * n;
    return rolling_with(rolled, nearest_clear_of_walls(along, normals), p_.ball.radius);
  }

  // A ball meeting a cushion or jaw whose inward normal at the contact is n:
  // solved in the impact frame by the chosen cushion model (cushion_model.hpp).
  BallState wall_impact(int i, const BallState& s, Vec2 n, const CushionContact& model) const {
    if (-dot(s.velocity, n) < kPushSpeed) return rest_on_wall(i, s, n);
    const CushionImpactFrame frame(n);
    IncomingBall in;
    in.velocity = frame.to_frame(s.velocity, 0.0);
    in.angular_velocity = frame.to_frame(horizontal(s.angular_velocity), s.angular_velocity.z);
    if (!(in.velocity.y > 0.0)) return s;  // grazing by round-off: nothing to exchange
    CushionRebound r;
    try {
      r = cushion_rebound(in, model);  // models validated at construction
    } catch (const InfeasibleShot&) {
      // The model has no rebound: the ball wedges between cushion and bed
      // (normal velocity never reverses). A resting contact.
      return rest_on_wall(i, s, n);
    }
    BallState out = s;
    out.velocity = frame.from_frame(r.velocity);
    const Vec2 w = frame.from_frame(r.angular_velocity);
    out.angular_velocity = {w.x, w.y, r.angular_velocity.z};
    // A model may leave the ball pressing on (han_2005 with a small e): a
    // resting contact from there.
    if (!(dot(out.velocity, n) > 0.0)) return rest_on_wall(i, out, n);
    return out;
  }

  // Every ball not pocketed is inside the closed playing area (pocket
  // throats included) at every event; the contact rules make this
  // unreachable, and the stress tool checks it (stress/).
  void check_on_table(int i) const {
    const Vec2 r = state_[idx(i)].position;
    const bool in_box = r.x >= inner_box_.lo.x && r.x <= inner_box_.hi.x && r.y >= inner_box_.lo.y && r.y <= inner_box_.hi.y;
    if (!in_box && !inside_playing_area(table_, r, kContactTolerance)) {
      throw SimulationError("ball " + std::to_string(result_.balls[idx(i)].id) + " left the table at t = " + num(now_) +
                            " s, position (" + num(r.x) + ", " + num(r.y) + ") m: please report this shot");
    }
  }

  const Table& table_;
  const SimulationSettings& settings_;
  const Parameters& p_;
  int n_;
  double now_ = 0.0;
  // The table's and settings' part (table_contacts()), shared while it is used.
  std::shared_ptr<const TableContacts> contacts_;
  const BallCollisionContact& ball_contact_;
  const ClusterSettings& cluster_settings_;
  const std::vector<CushionContact>& cushion_models_;
  const std::vector<CushionContact>& jaw_models_;
  const std::vector<ContactLine>& cushion_lines_;
  const std::vector<Box>& cushion_boxes_;  // where a ball centre can touch each cushion
  const std::vector<double>& jaw_distance_;
  const std::vector<PocketGroup>& groups_;
  Box inner_box_;  // wholly inside the playing area (check_on_table's fast path)
  struct ClusterBall {
    int ball;
    BallState state;
  };
  std::vector<ClusterBall> cluster_;  // touching_cluster()'s
  std::vector<ClusterContact> cluster_contacts_;
  std::vector<char> in_cluster_;
  std::vector<BallState> state_;  // state at time_
  std::vector<double> time_;
  std::vector<MotionPhase> phase_;
  std::vector<NextTransition> transition_;  // relative to time_
  std::vector<QuadraticPath> path_;         // from time_
  std::vector<double> path_end_;            // absolute time the path changes (sliding or rolling ends)
  std::vector<Box> path_box_;               // bounds path_ from time_ to path_end_
  std::vector<Candidate> transition_next_;
  double contact_ = 0.0;                    // 2R
  std::vector<char> active_;
  std::vector<Candidate> ball_next_;
  std::vector<double> pair_next_;  // the time of each pair's next contact, [pair_index(i, j)], i < j
  SimulationResult result_;
};

std::string ball_field(std::size_t i, const char* what) { return "balls[" + std::to_string(i) + "]." + what; }

}  // namespace

const char* to_string(EventType t) {
  switch (t) {
    case EventType::cue_strike: return "cue_strike";
    case EventType::slide_to_roll: return "slide_to_roll";
    case EventType::roll_to_spin: return "roll_to_spin";
    case EventType::roll_to_rest: return "roll_to_rest";
    case EventType::spin_stop: return "spin_stop";
    case EventType::ball_ball: return "ball_ball";
    case EventType::ball_cushion: return "ball_cushion";
    case EventType::ball_jaw: return "ball_jaw";
    case EventType::ball_pocket: return "ball_pocket";
  }
  return "unknown";
}

BallState SimulationResult::state_at(std::size_t index, double t, const Parameters& p) const {
  const BallTrajectory& b = balls.at(index);
  if (b.pocketed && t >= b.pocket_time) return b.final_state;
  const auto after = std::upper_bound(b.segments.begin(), b.segments.end(), t,
                                      [](double time, const TrajectorySegment& s) { return time < s.start_time; });
  const TrajectorySegment& seg = after == b.segments.begin() ? b.segments.front() : *(after - 1);
  return evolve(seg.state, std::max(0.0, t - seg.start_time), p);
}

namespace {

// The table and settings of this thread's last validate_simulation_input()
// that passed: the same again (==, which no NaN passes) are not checked again
// (issue 29: simulate() in a user's loop over one scenario). Comparing them
// costs a small part of checking them (the table's geometry, every cushion's
// impact model).
struct CheckedTableAndSettings {
  bool valid = false;
  Table table;
  SimulationSettings settings;
  // The positions of the balls of the last call that passed, in its order:
  // a ball at the same place on the same table is on it (ball_on_table, the
  // dearest check of a ball; a loop over one layout re-strikes the cue ball
  // from where it stands).
  std::vector<Vec2> on_table;
};
thread_local CheckedTableAndSettings t_checked;

}  // namespace

void validate_simulation_input(const Table& table, const std::vector<SimulationBall>& balls,
                               const SimulationSettings& settings) {
  if (!(t_checked.valid && t_checked.settings == settings && t_checked.table == table)) {
    t_checked.valid = false;
    validate(settings.parameters);
    validate(table);
    (void)ball_collision_contact(settings.parameters, settings.ball_collision_model, settings.ball_collision);
    if (settings.max_events < 1)
      throw InvalidArgument("max_events", static_cast<double>(settings.max_events), "[1, 2^31)");
    // The impact model of every cushion and jaw (the simulator builds them when it starts).
    for (const CushionSegment& c : table.cushions) (void)cushion_contact(settings.parameters, settings.cushion, c.contact_height);
    for (const JawArc& j : table.jaws) (void)cushion_contact(settings.parameters, settings.cushion, j.contact_height);
    t_checked.table = table;
    t_checked.settings = settings;
    t_checked.on_table.clear();
    t_checked.valid = true;
  }
  const double radius = settings.parameters.ball.radius;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    try {
      validate(balls[i].state);
    } catch (const InvalidArgument& e) {
      throw InvalidArgument(ball_field(i, e.field().c_str()), ball_field(i, "") + e.what());
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (balls[j].id == balls[i].id)
        throw InvalidArgument(ball_field(i, "id"), ball_field(i, "id") + " = " + std::to_string(balls[i].id) +
                                                       " is used twice (also by balls[" + std::to_string(j) + "])");
      const double d = norm(balls[i].state.position - balls[j].state.position);
      if (d < 2 * radius - kContactTolerance)
        throw InvalidArgument(ball_field(i, "position"),
                              ball_field(i, "position") + ": balls " + std::to_string(balls[j].id) + " and " + std::to_string(balls[i].id) +
                                  " overlap by " + num(2 * radius - d) + " m (centres " + num(d) +
                                  " m apart, allowed >= 2R = " + num(2 * radius) + " m)");
    }
    const bool known = i < t_checked.on_table.size() && t_checked.on_table[i] == balls[i].state.position;
    if (!known && !ball_on_table(table, balls[i].state.position, radius))
      throw InvalidArgument(ball_field(i, "position"),
                            ball_field(i, "position") + " = (" + num(balls[i].state.position.x) + ", " +
                                num(balls[i].state.position.y) + ") m is off the playing surface or inside a cushion");
  }
  t_checked.on_table.resize(balls.size());
  for (std::size_t i = 0; i < balls.size(); ++i) t_checked.on_table[i] = balls[i].state.position;
}

SimulationResult simulate(const Table& table, const std::vector<SimulationBall>& balls,
                          const SimulationSettings& settings) {
  validate_simulation_input(table, balls, settings);
  return Simulation(table, balls, settings).run();
}

SimulationResult simulate_unchecked(const Table& table, const std::vector<SimulationBall>& balls,
                                    const SimulationSettings& settings) {
  return Simulation(table, balls, settings).run();
}

std::size_t index_of(const std::vector<SimulationBall>& balls, int id) {
  for (std::size_t i = 0; i < balls.size(); ++i)
    if (balls[i].id == id) return i;
  return balls.size();
}

const SimulationBall* find_ball(const std::vector<SimulationBall>& balls, int id) {
  for (const SimulationBall& b : balls)
    if (b.id == id) return &b;
  return nullptr;
}

}  // namespace cueball
