// src/rl/vector_environment.cpp: many tables on threads, auto-reset.
#include <gtest/gtest.h>

#include "cueball/core/errors.hpp"
#include "cueball/core/random.hpp"
#include "cueball/rl/environment.hpp"

namespace cueball {
namespace {

std::vector<EnvAction> actions(std::size_t n, RandomStream& rng) {
  std::vector<EnvAction> a(n);
  for (EnvAction& x : a) {
    for (double& v : x.strike) v = rng.uniform(-1, 1);
    for (double& v : x.place) v = rng.uniform(-1, 1);
    x.ball = 1;
  }
  return a;
}

// Table i is seeded seed + i: the same as a single table with that seed,
// whatever the thread count; a table whose game ends starts the next episode.
TEST(VectorEnvironment, ResultsDoNotDependOnTheThreads) {
  EnvOptions o;
  o.opponent.kind = AgentKind::random;
  VectorEnvironment one = make_vector_environment(o, 6, 1, 40);
  VectorEnvironment two = make_vector_environment(o, 6, 2, 40);
  EnvTable single;
  env_reset(o, single, 43);  // table 3
  const std::size_t d = static_cast<std::size_t>(env_observation_size(o.game));
  EXPECT_EQ(one.observations, two.observations);
  EXPECT_TRUE(std::equal(single.observation.begin(), single.observation.end(), one.observations.begin() + 3 * static_cast<std::ptrdiff_t>(d)));
  RandomStream rng(1);
  int ended = 0;
  for (int k = 0; k < 25; ++k) {
    const std::vector<EnvAction> a = actions(6, rng);
    vector_step(one, a);
    vector_step(two, a);
    EXPECT_EQ(one.observations, two.observations);
    for (std::size_t i = 0; i < 6; ++i) {
      EXPECT_EQ(one.results[i].reward, two.results[i].reward);
      if (one.results[i].terminated || one.results[i].truncated) {
        ++ended;
        EXPECT_FALSE(one.tables[i].state.over);  // reset at once
        EXPECT_EQ(std::vector<float>(one.final_observations.begin() + static_cast<std::ptrdiff_t>(i * d),
                                     one.final_observations.begin() + static_cast<std::ptrdiff_t>((i + 1) * d)),
                  std::vector<float>(two.final_observations.begin() + static_cast<std::ptrdiff_t>(i * d),
                                     two.final_observations.begin() + static_cast<std::ptrdiff_t>((i + 1) * d)));
      }
    }
    if (!single.state.over) env_step(o, single, a[3]);
    if (single.state.over) break;
    EXPECT_TRUE(std::equal(single.observation.begin(), single.observation.end(), one.observations.begin() + 3 * static_cast<std::ptrdiff_t>(d)));
  }
  EXPECT_GT(ended, 0);
}

TEST(VectorEnvironment, BadSizesNameTheField) {
  EnvOptions o;
  EXPECT_THROW(make_vector_environment(o, 0, 1, 0), InvalidArgument);
  EXPECT_THROW(make_vector_environment(o, 2, 0, 0), InvalidArgument);
  VectorEnvironment v = make_vector_environment(o, 2, 1, 0);
  EXPECT_THROW(vector_step(v, std::vector<EnvAction>(3)), InvalidArgument);
}

}  // namespace
}  // namespace cueball
