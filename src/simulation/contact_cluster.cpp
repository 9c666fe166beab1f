// Simultaneous impact of a cluster of touching balls; see contact_cluster.hpp
// for the model (C1)-(C3) and its sources.
#include "cueball/simulation/contact_cluster.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "cueball/simulation/simulator.hpp"

namespace cueball {

namespace {

constexpr int kMaxSteps = 200000;

// A contact in the cluster's canonical order: balls by rank, a < b.
struct Spring {
  std::size_t a = 0, b = 0;  // ranks
  std::size_t input = 0;     // index in the caller's contacts
  Vec2 normal;               // from a to b
  double approach = 0.0;     // delta, (C1); negative: apart
  double deepest = 0.0;      // delta_max
  double impulse = 0.0;      // integral of F dt
  double force = 0.0;        // F at the present approach (ClusterSolve::update_forces)
  bool touching = true;      // no gap at the start
};

struct ClusterSolve {
  double e = 1.0;
  double k = 1.0;           // Hertz stiffness per unit mass
  double slow = 0.0;        // ClusterSettings::slow_speed
  double window = 0.0;      // a pair's contact time at the speed scale, s
  std::vector<std::size_t> by_rank;  // input index of the ball of each rank
  std::vector<Vec2> v;               // by rank
  std::vector<Vec2> acceleration;    // by rank
  std::vector<Spring> springs;
  double dt = 0.0;
  double steps_per_contact_time = kClusterStepsPerContactTime;
  int steps = 0;
  std::size_t going = 0;  // parted(): the contact last found still going

  // Ranks by position (x, then y), springs by their ranks: the sums below do
  // not depend on the order the caller gave.
  void order_canonically(std::span<const Vec2> positions, std::span<const Vec2> velocities,
                         std::span<const ClusterContact> contacts) {
    by_rank.resize(positions.size());
    std::iota(by_rank.begin(), by_rank.end(), std::size_t{0});
    std::sort(by_rank.begin(), by_rank.end(), [&](std::size_t i, std::size_t j) {
      if (positions[i].x != positions[j].x) return positions[i].x < positions[j].x;
      return positions[i].y < positions[j].y;
    });
    std::vector<std::size_t> rank(positions.size());
    for (std::size_t r = 0; r < by_rank.size(); ++r) rank[by_rank[r]] = r;
    v.resize(positions.size());
    for (std::size_t r = 0; r < by_rank.size(); ++r) v[r] = velocities[by_rank[r]];
    acceleration.assign(positions.size(), {});
    springs.clear();
    for (std::size_t c = 0; c < contacts.size(); ++c) {
      Spring s;
      s.a = std::min(rank[contacts[c].a], rank[contacts[c].b]);
      s.b = std::max(rank[contacts[c].a], rank[contacts[c].b]);
      s.input = c;
      const Vec2 d = positions[by_rank[s.b]] - positions[by_rank[s.a]];
      s.normal = d / norm(d);
      s.approach = -contacts[c].gap;
      s.touching = !(contacts[c].gap > 0.0);
      springs.push_back(s);
    }
    std::sort(springs.begin(), springs.end(),
              [](const Spring& x, const Spring& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
  }

  Vec2 centre_of_mass_velocity() const {
    Vec2 sum;
    for (Vec2 u : v) sum = sum + u;
    return sum / static_cast<double>(v.size());
  }

  // Twice the kinetic energy per unit mass relative to the centre of mass.
  double relative_energy(Vec2 c) const {
    double sum = 0.0;
    for (Vec2 u : v) sum += dot(u - c, u - c);
    return sum;
  }

  // Any two balls' relative speed is at most sqrt(2 sum |v_i - c|^2), before
  // and (energy falling) during the impact; the step is 1/64 of a pair's
  // Hertz contact time at that speed (reduced mass m/2), less when the
  // unloading branch (its time e t_c) is the quicker.
  void choose_time_step() {
    const double speed = std::sqrt(2.0 * relative_energy(centre_of_mass_velocity()));
    window = hertz_contact_time(speed, k);
    dt = window / steps_per_contact_time * std::min(1.0, std::max(2.0 * e, 0.1));
  }

  double closing(const Spring& s) const { return dot(v[s.a] - v[s.b], s.normal); }

  // (C2): Hertz loading, Walton-Braun unloading; per unit mass.
  double force(const Spring& s) const {
    if (s.approach <= 0.0) return 0.0;
    if (s.approach >= s.deepest) return k * s.approach * std::sqrt(s.approach);
    const double set = (1.0 - e * e) * s.deepest;
    if (s.approach <= set) return 0.0;
    const double x = s.approach - set;
    return k * x * std::sqrt(x) / (e * e * e);
  }

  // Each contact's force at its present approach: computed once per step,
  // read by the kicks, the accelerations and the end test.
  void update_forces() {
    for (Spring& s : springs) s.force = force(s);
  }

  // The closing speed the work stored in a contact could still give it,
  // sqrt(2 W / mu) with mu = 1/2: W = (2/5) F delta on the loading branch,
  // (2/5) F (delta - set) on the unloading one.
  double stored_speed(const Spring& s) const {
    const double f = s.force;
    if (f == 0.0) return 0.0;
    const double x = s.approach >= s.deepest ? s.approach : s.approach - (1.0 - e * e) * s.deepest;
    return std::sqrt(4.0 * 0.4 * f * x);
  }

  // Half a step of (C3) for the velocities (the impulses: step()).
  void kick_velocities(double h) {
    for (std::size_t r = 0; r < v.size(); ++r) v[r] = v[r] + h * acceleration[r];
  }

  // One velocity Verlet step of (C1)-(C3): a half kick of the velocities by
  // the forces at the step's start, the approaches moved by the whole step,
  // the forces and accelerations there, the second half kick. Each contact's
  // work is done in one pass (its impulse gets both half kicks, in order),
  // the accelerations summed in the contacts' canonical order.
  void step() {
    const double h = 0.5 * dt;
    kick_velocities(h);
    std::fill(acceleration.begin(), acceleration.end(), Vec2{});
    for (Spring& s : springs) {
      if (s.force != 0.0) s.impulse += h * s.force;
      s.approach += dt * closing(s);
      s.deepest = std::max(s.deepest, s.approach);
      s.force = force(s);
      if (s.force == 0.0) continue;  // apart or unloaded: no acceleration, no impulse
      const Vec2 f = s.force * s.normal;
      acceleration[s.a] = acceleration[s.a] - f;
      acceleration[s.b] = acceleration[s.b] + f;
      s.impulse += h * s.force;
    }
    kick_velocities(h);
    ++steps;
  }

  // Whether contact s is over: it carries no force and does not close, or,
  // apart across a gap it had at the start, would not close it within a
  // contact time (it is a later collision, the simulator's), or everything
  // it carries and closes is slower than `slow` (the simulator's resting
  // contacts take it from there).
  bool over(const Spring& s) const {
    const double f = s.force, speed = closing(s);
    if (f == 0.0 && speed <= 0.0) return true;
    if (f == 0.0 && !s.touching && s.approach < 0.0 && -s.approach > speed * window) return true;
    return std::max(speed, 0.0) + stored_speed(s) < slow;
  }

  // Whether every contact is over. The look starts at the contact found
  // still going the last time (`going`), which usually still is: one test a
  // step instead of one for each contact over before it (the same answer,
  // over() reading nothing but the state).
  bool parted() {
    const std::size_t n = springs.size();
    for (std::size_t m = 0; m < n; ++m) {
      const std::size_t c = going + m < n ? going + m : going + m - n;
      if (!over(springs[c])) {
        going = c;
        return false;
      }
    }
    return true;
  }

  // The integration's error (and rounding) may not add energy: velocities
  // relative to the centre of mass scaled back to a hair under the energy
  // there was (1e-12 of it: rounding in any sum of the energies stays below
  // that), momentum unchanged.
  void keep_energy(double before, Vec2 c) {
    const double allowed = before * (1.0 - 1e-12);
    const double after = relative_energy(c);
    if (!(after > allowed)) return;
    const double scale = std::sqrt(allowed / after);
    for (Vec2& u : v) u = c + scale * (u - c);
  }
};

}  // namespace

double hertz_contact_time(double speed, double stiffness) {
  const double deepest = std::pow(5.0 * speed * speed / (8.0 * stiffness), 0.4);
  return 2.94 * deepest / speed;
}

double hertz_compression(double speed, double stiffness) { return std::pow(5.0 * speed * speed / (8.0 * stiffness), 0.4); }

double hertz_stiffness_per_mass(const BallParameters& ball) {
  const double contact_modulus = kPhenolicYoungsModulus / (2.0 * (1.0 - kPhenolicPoissonRatio * kPhenolicPoissonRatio));
  return 4.0 / 3.0 * contact_modulus * std::sqrt(0.5 * ball.radius) / ball.mass;
}

ClusterImpact resolve_cluster_impact(std::span<const Vec2> positions, std::span<const Vec2> velocities,
                                     std::span<const ClusterContact> contacts, const ClusterSettings& settings) {
  ClusterSolve solve;
  // A perfectly plastic cluster can creep on without end (contacts pushed
  // back onto their loading branch by ever smaller amounts): e is at least
  // 0.01, which returns 1e-4 of the work stored.
  solve.e = std::max(settings.restitution, 0.01);
  solve.k = settings.stiffness;
  solve.slow = settings.slow_speed;
  solve.steps_per_contact_time = settings.steps_per_contact_time;
  solve.order_canonically(positions, velocities, contacts);
  solve.update_forces();
  const Vec2 c = solve.centre_of_mass_velocity();
  const double before = solve.relative_energy(c);
  if (before > 0.0) solve.choose_time_step();
  if (before > 0.0 && !solve.parted()) {
    while (!solve.parted()) {
      if (solve.steps >= kMaxSteps)
        throw SimulationError("a cluster of " + std::to_string(positions.size()) +
                              " touching balls did not part after " + std::to_string(kMaxSteps) +
                              " steps: please report this shot");
      solve.step();
    }
    solve.keep_energy(before, c);
  }
  ClusterImpact out;
  out.velocities.resize(positions.size());
  for (std::size_t r = 0; r < solve.by_rank.size(); ++r) out.velocities[solve.by_rank[r]] = solve.v[r];
  out.impulses.resize(contacts.size());
  for (const Spring& s : solve.springs) out.impulses[s.input] = s.impulse;
  out.steps = solve.steps;
  return out;
}

}  // namespace cueball
