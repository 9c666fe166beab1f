// Many tables of the learning environment stepped together on worker
// threads (rl/environment.hpp, VectorEnvironment). Each table is stepped
// from its own seed and writes only its own rows, so the results do not
// depend on the number of threads or on which thread steps which table.
#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

#include "cueball/core/errors.hpp"
#include "cueball/rl/environment.hpp"

namespace cueball {

namespace {

inline constexpr int kMaxVectorTables = 65536;
inline constexpr int kMaxVectorThreads = 256;

std::size_t row(const VectorEnvironment& env, std::size_t i) {
  return i * static_cast<std::size_t>(env_observation_size(env.options.game));
}

void copy_observation(const std::vector<float>& from, std::vector<float>& to, std::size_t offset) {
  std::copy(from.begin(), from.end(), to.begin() + static_cast<std::ptrdiff_t>(offset));
}

// Runs `work(i)` for every table i on env.threads threads (tables handed out
// one at a time); the first exception, by table index, is rethrown.
template <class Work>
void for_each_table(const VectorEnvironment& env, const Work& work) {
  const std::size_t n = env.tables.size();
  const std::size_t threads = std::min<std::size_t>(static_cast<std::size_t>(env.threads), n);
  std::atomic<std::size_t> next{0};
  std::mutex failure_lock;
  std::size_t failed_at = n;
  std::exception_ptr failure;
  auto worker = [&] {
    for (std::size_t i = next++; i < n; i = next++) {
      try {
        work(i);
      } catch (...) {
        const std::lock_guard lock(failure_lock);
        if (i < failed_at) {
          failed_at = i;
          failure = std::current_exception();
        }
      }
    }
  };
  if (threads <= 1) {
    worker();
  } else {
    std::vector<std::jthread> pool;
    pool.reserve(threads - 1);
    for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace

VectorEnvironment make_vector_environment(const EnvOptions& options, int n, int threads, std::uint64_t seed) {
  validate(options);
  if (n < 1 || n > kMaxVectorTables)
    throw InvalidArgument("n", n, "[1, " + std::to_string(kMaxVectorTables) + "]", "tables");
  if (threads < 1 || threads > kMaxVectorThreads)
    throw InvalidArgument("threads", threads, "[1, " + std::to_string(kMaxVectorThreads) + "]", "worker threads");
  VectorEnvironment env;
  env.options = options;
  env.threads = threads;
  env.tables.resize(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < env.tables.size(); ++i) env.tables[i].seed = seed + i;
  const std::size_t size = row(env, env.tables.size());
  env.observations.assign(size, 0.0f);
  env.final_observations.assign(size, 0.0f);
  env.results.resize(env.tables.size());
  vector_reset(env, seed);
  return env;
}

void vector_reset(VectorEnvironment& env, std::optional<std::uint64_t> seed) {
  for_each_table(env, [&](std::size_t i) {
    EnvTable& t = env.tables[i];
    env_reset(env.options, t, seed ? std::optional<std::uint64_t>(*seed + i) : std::nullopt);
    copy_observation(t.observation, env.observations, row(env, i));
    env.results[i] = EnvStepResult{};
  });
}

void vector_step(VectorEnvironment& env, const std::vector<EnvAction>& actions) {
  if (actions.size() != env.tables.size())
    throw InvalidArgument("actions", "actions: " + std::to_string(actions.size()) + " actions for " +
                                         std::to_string(env.tables.size()) + " tables");
  for_each_table(env, [&](std::size_t i) {
    EnvTable& t = env.tables[i];
    env.results[i] = env_step(env.options, t, actions[i]);
    if (t.state.over) {
      copy_observation(t.observation, env.final_observations, row(env, i));
      env_reset(env.options, t);
    }
    copy_observation(t.observation, env.observations, row(env, i));
  });
}

}  // namespace cueball
