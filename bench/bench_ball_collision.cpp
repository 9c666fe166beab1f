// Throughput of the ball-ball collision kernel (src/ball_collision.cpp), which
// the table simulator calls at every ball-ball event. Each benchmark cycles
// through the same batch of 4096 random touching, approaching pairs (speeds up
// to 4 m/s, spins up to 2 v_max / R) so branch prediction cannot memorise one
// path. Time per iteration = time per collision.
//
//   BM_CollideBalls/alciatore     e = 0.95, speed-dependent friction (TP A.14):
//                                 most pairs have a vertical slip component,
//                                 the slip direction turns, and the kernel
//                                 integrates it (Gauss-Legendre + Newton)
//   BM_CollideBalls/stun          the same pairs without spins about horizontal
//                                 axes: horizontal slip only, closed form
//   BM_CollideBalls/frictionless  normal impulse only
//   BM_CollideBalls/constant      e = 0.89, constant mu = 0.05: the ball-ball part
//                                 of Mathavan et al. (2014), for the two below
//   BM_Mathavan2014/paper         src/models/ball_collision/mathavan_2014.cpp with the
//                                 paper's constants (e_b = 0.89, mu_b = 0.05,
//                                 mu_s = 0.21): the cloth's friction during the
//                                 impact, integrated by DOPRI5 in the slip age
//   BM_Mathavan2014/no_cloth      the same with mu_s = 0 (the physics of
//                                 BM_CollideBalls/constant, by the integrator)
// Counter gripped: the fraction of the batch whose slip stopped during the impact.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "cueball/models/ball_collision/coulomb_impulse.hpp"
#include "cueball/models/ball_collision/mathavan_2014.hpp"
#include "cueball/core/parameters.hpp"

namespace {

using namespace cueball;

constexpr std::size_t kBatch = 4096;

struct Pair {
  BallState a;
  BallState b;
};

std::vector<Pair> make_batch(bool horizontal_spins) {
  const double radius = pool_parameters().ball.radius;
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double v_max = 4.0;
  const double w_max = 2.0 * v_max / radius;
  std::vector<Pair> out;
  out.reserve(kBatch);
  while (out.size() < kBatch) {
    Pair p;
    const double theta = 3.14159265358979323846 * unit(rng);
    p.a.position = {unit(rng), unit(rng)};
    p.b.position = p.a.position + 2.0 * radius * Vec2{std::cos(theta), std::sin(theta)};
    p.a.velocity = v_max * Vec2{unit(rng), unit(rng)};
    p.b.velocity = 0.5 * v_max * Vec2{unit(rng), unit(rng)};
    p.a.angular_velocity = w_max * Vec3{unit(rng), unit(rng), unit(rng)};
    p.b.angular_velocity = 0.5 * w_max * Vec3{unit(rng), unit(rng), unit(rng)};
    if (!horizontal_spins) {
      p.a.angular_velocity.x = p.a.angular_velocity.y = 0.0;
      p.b.angular_velocity.x = p.b.angular_velocity.y = 0.0;
    }
    if (balls_approaching(p.a, p.b)) out.push_back(p);
  }
  return out;
}

const std::vector<Pair>& batch(bool horizontal_spins) {
  static const std::vector<Pair> spinning = make_batch(true);
  static const std::vector<Pair> stun = make_batch(false);
  return horizontal_spins ? spinning : stun;
}

// Times collide(a, b, ball, contact) over the batch.
template <class Contact, class Collide>
void run_kernel(benchmark::State& state, bool horizontal_spins, const Contact& contact, Collide collide) {
  const BallParameters ball = pool_parameters().ball;
  const std::vector<Pair>& pairs = batch(horizontal_spins);
  std::size_t i = 0;
  for (auto _ : state) {
    const BallCollisionResult r = collide(pairs[i].a, pairs[i].b, ball, contact);
    benchmark::DoNotOptimize(r);
    i = (i + 1) & (kBatch - 1);
  }
  double gripped = 0.0;
  for (const Pair& p : pairs) gripped += collide(p.a, p.b, ball, contact).gripped ? 1.0 : 0.0;
  state.counters["gripped"] = gripped / static_cast<double>(kBatch);
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}

void run(benchmark::State& state, bool horizontal_spins, const BallCollisionParameters& contact) {
  run_kernel(state, horizontal_spins, contact, resolve_ball_collision);
}

void BM_CollideBalls_Alciatore(benchmark::State& state) { run(state, true, ball_collision_alciatore()); }
BENCHMARK(BM_CollideBalls_Alciatore)->Name("BM_CollideBalls/alciatore");

void BM_CollideBalls_Stun(benchmark::State& state) { run(state, false, ball_collision_alciatore()); }
BENCHMARK(BM_CollideBalls_Stun)->Name("BM_CollideBalls/stun");

void BM_CollideBalls_Frictionless(benchmark::State& state) { run(state, true, ball_collision_frictionless(0.95)); }
BENCHMARK(BM_CollideBalls_Frictionless)->Name("BM_CollideBalls/frictionless");

void BM_CollideBalls_Constant(benchmark::State& state) {
  run(state, true, BallCollisionParameters{0.89, 0.05, 0.0, 0.0});
}
BENCHMARK(BM_CollideBalls_Constant)->Name("BM_CollideBalls/constant");

void BM_Mathavan2014_Paper(benchmark::State& state) {
  run_kernel(state, true, mathavan_2014_contact(), mathavan_2014_collision);
}
BENCHMARK(BM_Mathavan2014_Paper)->Name("BM_Mathavan2014/paper");

void BM_Mathavan2014_NoCloth(benchmark::State& state) {
  Mathavan2014Contact contact = mathavan_2014_contact();
  contact.cloth_friction = 0.0;
  run_kernel(state, true, contact, mathavan_2014_collision);
}
BENCHMARK(BM_Mathavan2014_NoCloth)->Name("BM_Mathavan2014/no_cloth");

}  // namespace
