// cueball-agent-benchmark: how strong is an agent in whole games? (issue 27,
// item 5). Plays seeded games of one discipline between two agents (by the
// names agent_named() takes: the AgentKind names and "strongest") with the
// game's execution noise (tournament noise unless --noise none), the breaks
// alternating (game k is broken by player k mod 2: WPA 1.4's alternate
// break, the fair choice for a benchmark; UMB and WPBSA frames alternate
// too), and reports what the anchors are stated in:
//   - games won by each agent, the first agent's share with its binomial
//     standard error and 95 % Wilson interval; with --race R, the games
//     grouped into races to R (a match won by the first to R games) and the
//     matches won;
//   - pool: the breaks that make a ball (legal, an object ball down) and the
//     break-and-run rate: the breaker wins in the inning of the break (of
//     all breaks, and of those that made a ball);
//   - snooker: the mean and the highest break (points in one visit) of each
//     agent, and frames won;
//   - three-cushion: each agent's general average (points per inning, an
//     inning a visit to the table);
//   - fouls per game and the median CPU seconds of each agent's decision.
// Deterministic for a seed: game k is new_game(config, seed + k) played as
// agents/match.hpp's play_game() plays it (the same seeds), timed here.
// Uses only the public API.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <optional>
#include <string>
#include <vector>


#include "tool_support.hpp"
#include "cueball/agents/agent.hpp"
#include "cueball/agents/match.hpp"
#include "cueball/games/game.hpp"

namespace {

using namespace cueball;
using cueball::tools::fmt;
using cueball::tools::thread_cpu_seconds;
constexpr tools::Flags kFlags{"cueball-agent-benchmark"};


struct Options {
  GameKind game = GameKind::nine_ball;
  std::array<std::string, 2> names{"strongest", "planner"};
  int games = 20;
  int race = 0;  // 0: no races
  std::uint64_t seed = 1;
  bool noise = true;
  double seconds = 0.0;  // AgentOptions::seconds of both agents (0: none)
  // --valuations, --noisy-leaves, --depths: each agent's position play, when given (else its own).
  std::array<std::optional<LeaveValuation>, 2> valuations;
  std::array<std::optional<int>, 2> noisy_leaves;
  std::array<std::optional<int>, 2> depths;
  std::string json;
};

// "A,B" split at its comma, each part "-" (none) or parsed by `parse`.
template <class T, class Parse>
std::array<std::optional<T>, 2> pair_flag(const std::string& flag, const std::string& value, const std::string& allowed,
                                          Parse parse) {
  const std::size_t comma = value.find(',');
  if (comma == std::string::npos) kFlags.bad(flag, value, "two values A,B, each " + allowed + " or - (the agent's own)");
  std::array<std::optional<T>, 2> out;
  const std::array<std::string, 2> parts{value.substr(0, comma), value.substr(comma + 1)};
  for (std::size_t k = 0; k < 2; ++k)
    if (parts[k] != "-") out[k] = parse(parts[k]);
  return out;
}

// One game as play_game() plays it (agents/match.hpp: the same seeds), the
// breaker the agent `breaker`, each decision's CPU time kept per agent.
struct PlayedGame {
  GameRecord record;
  int breaker = 0;  // the agent (0: the first named) that broke
  std::array<std::vector<double>, 2> decision_cpu;
};

PlayedGame play_timed(const GameConfig& config, const std::array<AgentOptions, 2>& agents, int breaker,
                      std::uint64_t seed) {
  PlayedGame g;
  g.breaker = breaker;
  g.record.seed = seed;
  g.record.start = new_game(config, seed);
  GameState state = g.record.start;
  for (int k = 0; !state.over; ++k) {
    const int agent = state.to_shoot == 0 ? breaker : 1 - breaker;  // player 0 breaks
    const double start = thread_cpu_seconds();
    AgentChoice choice = choose(agents[static_cast<std::size_t>(agent)], state, agent_seed(seed, k));
    g.decision_cpu[static_cast<std::size_t>(agent)].push_back(thread_cpu_seconds() - start);
    GameStep step = play(state, choice.action, shot_seed(seed, k));
    state = step.next;
    g.record.steps.push_back(
        RecordedStep{choice.action, shot_seed(seed, k), std::move(step.ruling), std::move(step.next), {}});
  }
  return g;
}

// What one game gave, per agent.
struct GameFigures {
  std::optional<int> winner;  // the agent
  bool made_break = false;    // pool: the break was legal and made an object ball
  bool break_and_run = false; // the breaker won in the break's inning
  std::array<int, 2> fouls{};
  std::array<std::vector<int>, 2> visits;  // points (snooker, carom) or balls (pool) of each visit
};

GameFigures figures(const PlayedGame& g) {
  GameFigures f;
  const GameRecord& r = g.record;
  const auto agent_of = [&](int player) { return player == 0 ? g.breaker : 1 - g.breaker; };
  const GameState* before = &r.start;
  int visitor = -1, in_visit = 0;
  for (const RecordedStep& s : r.steps) {
    const int agent = agent_of(before->to_shoot);
    if (agent != visitor) {
      if (visitor >= 0) f.visits[static_cast<std::size_t>(visitor)].push_back(in_visit);
      visitor = agent;
      in_visit = 0;
    }
    const std::size_t p = static_cast<std::size_t>(before->to_shoot);
    if (s.ruling.foul) ++f.fouls[static_cast<std::size_t>(agent)];
    if (r.start.config.kind == GameKind::snooker || r.start.config.kind == GameKind::three_cushion) {
      in_visit += std::max(0, s.ruling.points[p]);
    } else if (!s.ruling.foul) {
      for (const int id : s.ruling.pocketed) in_visit += id != 0 ? 1 : 0;
    }
    before = &s.state;
  }
  if (visitor >= 0) f.visits[static_cast<std::size_t>(visitor)].push_back(in_visit);
  const GameState& end = r.steps.empty() ? r.start : r.steps.back().state;
  if (end.winner) f.winner = agent_of(*end.winner);
  if (!r.steps.empty() && r.start.config.kind != GameKind::snooker && r.start.config.kind != GameKind::three_cushion) {
    const Ruling& brk = r.steps.front().ruling;
    int balls = 0;
    for (const int id : brk.pocketed) balls += id != 0 ? 1 : 0;
    f.made_break = !brk.foul && balls > 0;
    bool breaker_only = true;
    const GameState* b = &r.start;
    for (const RecordedStep& s : r.steps) {
      breaker_only = breaker_only && b->to_shoot == 0;
      b = &s.state;
    }
    f.break_and_run = breaker_only && end.winner == 0;
  }
  return f;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The 95 % Wilson score interval of k successes in n.
std::array<double, 2> wilson(int k, int n) {
  if (n == 0) return {0.0, 1.0};
  const double z = 1.959963984540054, p = static_cast<double>(k) / n, nn = n;
  const double centre = (p + z * z / (2 * nn)) / (1 + z * z / nn);
  const double half = z * std::sqrt(p * (1 - p) / nn + z * z / (4 * nn * nn)) / (1 + z * z / nn);
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

void usage() {
  std::printf(
      "usage: cueball-agent-benchmark [--game G] [--players A,B] [--games N] [--race R] [--seed S]\n"
      "                               [--noise tournament|none] [--seconds S] [--valuations V,W]\n"
      "                               [--noisy-leaves N,M] [--depths D,E] [--json FILE]\n"
      "Whole games between two agents: games and races won, breaks, break-and-runs, snooker breaks,\n"
      "three-cushion averages, fouls and decision times (docs/planner-benchmark.md, \"Games\").\n"
      "  --game G           %s (default nine_ball)\n"
      "  --players A,B      two of %s (default strongest,planner)\n"
      "  --games N          games, [1, 100000] (default 20); game k from seed S + k, broken by A when k is even\n"
      "  --race R           group the games into races to R games, [1, 1000] (default: none)\n"
      "  --seed S           first seed, [0, 1e18] (default 1)\n"
      "  --noise N          the execution noise: tournament (the default) or none\n"
      "  --seconds S        each decision's wall-clock budget, [0, 3600] (AgentOptions::seconds; default 0: none)\n"
      "  --valuations V,W   each agent's leave valuation in position play, windows or ghost_ball, - for the\n"
      "                     agent's own (AgentOptions::position_valuation; default -,-)\n"
      "  --noisy-leaves N,M each agent's noisy leaves per finalist, [0, %d], - for the agent's own\n"
      "                     (AgentOptions::position_noisy_leaves; default -,-)\n"
      "  --depths D,E       each agent's shots looked ahead in position play, [1, %d] (3: ghost_ball only), - for the agent's own\n"
      "                     (AgentOptions::position_depth; default -,-)\n"
      "  --json FILE        also write the results as JSON\n"
      "Exit status: 0 done, 1 an engine error, 2 bad flags.\n",
      game_kind_names().c_str(), agent_names().c_str(), kMaxPositionNoisyLeaves, kMaxPositionDepth);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--help" || flag == "-h") {
      usage();
      std::exit(0);
    }
    static const char* const known[] = {"--game",    "--players", "--games",      "--race",         "--seed",
                                        "--noise",   "--seconds", "--valuations", "--noisy-leaves", "--depths", "--json"};
    if (std::find_if(std::begin(known), std::end(known), [&](const char* k) { return flag == k; }) == std::end(known))
      kFlags.bad("flag", flag,
                 "--game, --players, --games, --race, --seed, --noise, --seconds, --valuations, --noisy-leaves, --depths, "
                 "--json, --help");
    if (i + 1 >= argc) kFlags.bad(flag, "", "a value after the flag");
    const std::string value = argv[++i];
    if (flag == "--game") {
      const std::optional<GameKind> kind = game_kind_from_string(value);
      if (!kind) kFlags.bad(flag, value, game_kind_names());
      o.game = *kind;
    } else if (flag == "--players") {
      const std::size_t comma = value.find(',');
      if (comma == std::string::npos) kFlags.bad(flag, value, "two agents A,B of " + agent_names());
      o.names = {value.substr(0, comma), value.substr(comma + 1)};
      for (const std::string& n : o.names)
        if (!agent_named(n)) kFlags.bad(flag, value, "two agents A,B of " + agent_names());
    } else if (flag == "--games") {
      o.games = static_cast<int>(kFlags.integer(flag, value, 1, 100000));
    } else if (flag == "--race") {
      o.race = static_cast<int>(kFlags.integer(flag, value, 1, 1000));
    } else if (flag == "--seed") {
      o.seed = static_cast<std::uint64_t>(kFlags.integer(flag, value, 0, 1000000000000000000LL));
    } else if (flag == "--noise") {
      if (value != "tournament" && value != "none") kFlags.bad(flag, value, "tournament, none");
      o.noise = value == "tournament";
    } else if (flag == "--seconds") {
      o.seconds = kFlags.number(flag, value, 0.0, kMaxAgentSeconds, "[0, 3600] s a decision");
    } else if (flag == "--valuations") {
      o.valuations = pair_flag<LeaveValuation>(flag, value, leave_valuation_names(), [&](const std::string& v) {
        const std::optional<LeaveValuation> parsed = leave_valuation_from_string(v);
        if (!parsed) kFlags.bad(flag, value, "two values A,B, each " + leave_valuation_names() + " or -");
        return *parsed;
      });
    } else if (flag == "--noisy-leaves") {
      o.noisy_leaves = pair_flag<int>(flag, value, "[0, " + std::to_string(kMaxPositionNoisyLeaves) + "]",
                                      [&](const std::string& v) {
                                        return static_cast<int>(kFlags.integer(flag, v, 0, kMaxPositionNoisyLeaves));
                                      });
    } else if (flag == "--depths") {
      o.depths = pair_flag<int>(flag, value, "[1, " + std::to_string(kMaxPositionDepth) + "]", [&](const std::string& v) {
        return static_cast<int>(kFlags.integer(flag, v, 1, kMaxPositionDepth));
      });
    } else {
      if (value.empty()) kFlags.bad(flag, value, "a file path");
      o.json = value;
    }
  }
  // Three shots deep by the ghost ball only (position_play.hpp, kMaxWindowsDepth).
  for (std::size_t k = 0; k < 2; ++k) {
    const LeaveValuation valuation = o.valuations[k] ? *o.valuations[k] : agent_named(o.names[k])->position_valuation;
    if (o.depths[k] && *o.depths[k] > max_position_depth(valuation))
      kFlags.bad("--depths", std::to_string(*o.depths[k]) + " (" + o.names[k] + ")",
                 "[1, " + std::to_string(kMaxWindowsDepth) + "] with valuation windows (deeper: --valuations ghost_ball)");
  }
  return o;
}

int run(const Options& o) {
  GameConfig config = default_config(o.game);
  config.noise = o.noise ? tournament_noise() : CueStrikeNoise{};
  // The agents plan under the game's noise, tournament noise when it has none (planning_noise()).
  std::array<AgentOptions, 2> agents{*agent_named(o.names[0]), *agent_named(o.names[1])};
  for (std::size_t k = 0; k < 2; ++k) {
    agents[k].seconds = o.seconds;
    if (o.valuations[k]) agents[k].position_valuation = *o.valuations[k];
    if (o.noisy_leaves[k]) agents[k].position_noisy_leaves = *o.noisy_leaves[k];
    if (o.depths[k]) agents[k].position_depth = *o.depths[k];
  }
  std::printf("cueball-agent-benchmark: %s, %s v %s, %d games from seed %llu, %s noise%s\n", to_string(o.game),
              o.names[0].c_str(), o.names[1].c_str(), o.games, static_cast<unsigned long long>(o.seed),
              o.noise ? "tournament" : "no", o.seconds > 0.0 ? fmt(", %g s a decision", o.seconds).c_str() : "");
  std::array<int, 2> won{}, fouls{};
  std::array<std::vector<int>, 2> visits;
  std::array<std::vector<double>, 2> cpu;
  std::array<int, 2> breaks{}, made{}, runs{};
  int undecided = 0;
  std::array<int, 2> race_games{}, matches{};
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < o.games; ++k) {
    const int breaker = k % 2;
    const PlayedGame g = play_timed(config, agents, breaker, o.seed + static_cast<std::uint64_t>(k));
    const GameFigures f = figures(g);
    for (std::size_t a = 0; a < 2; ++a) {
      fouls[a] += f.fouls[a];
      visits[a].insert(visits[a].end(), f.visits[a].begin(), f.visits[a].end());
      cpu[a].insert(cpu[a].end(), g.decision_cpu[a].begin(), g.decision_cpu[a].end());
    }
    const auto b = static_cast<std::size_t>(breaker);
    ++breaks[b];
    made[b] += f.made_break ? 1 : 0;
    runs[b] += f.break_and_run ? 1 : 0;
    if (f.winner) {
      ++won[static_cast<std::size_t>(*f.winner)];
      if (o.race > 0 && ++race_games[static_cast<std::size_t>(*f.winner)] == o.race) {
        ++matches[static_cast<std::size_t>(*f.winner)];
        race_games = {};
      }
    } else {
      ++undecided;
    }
    std::fprintf(stderr, "\r  game %d of %d: %d-%d", k + 1, o.games, won[0], won[1]);
  }
  std::fprintf(stderr, "\n");
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const int decided = won[0] + won[1];
  const double share = decided > 0 ? static_cast<double>(won[0]) / decided : 0.0;
  const std::array<double, 2> ci = wilson(won[0], decided);
  std::printf("games: %s %d, %s %d, undecided %d; %s's share %.3f +- %.3f (95 %% Wilson [%.3f, %.3f]); %.1f s\n",
              o.names[0].c_str(), won[0], o.names[1].c_str(), won[1], undecided, o.names[0].c_str(), share,
              decided > 0 ? std::sqrt(share * (1 - share) / decided) : 0.0, ci[0], ci[1], wall);
  if (o.race > 0) std::printf("races to %d: %s %d, %s %d\n", o.race, o.names[0].c_str(), matches[0], o.names[1].c_str(), matches[1]);
  const bool pool = o.game != GameKind::snooker && o.game != GameKind::three_cushion;
  std::string json = fmt("{\n \"tool\": \"cueball-agent-benchmark\",\n \"game\": \"%s\", \"players\": [\"%s\", \"%s\"], "
                         "\"games\": %d, \"seed\": %llu, \"noise\": \"%s\", \"seconds\": %.6g,\n \"won\": [%d, %d], \"undecided\": %d, "
                         "\"share\": %.6g, \"share_wilson_95\": [%.6g, %.6g], \"wall_seconds\": %.6g,\n",
                         to_string(o.game), o.names[0].c_str(), o.names[1].c_str(), o.games,
                         static_cast<unsigned long long>(o.seed), o.noise ? "tournament" : "none", o.seconds, won[0], won[1],
                         undecided, share, ci[0], ci[1], wall);
  if (o.race > 0) json += fmt(" \"race_to\": %d, \"matches\": [%d, %d],\n", o.race, matches[0], matches[1]);
  json += fmt(" \"valuations\": [\"%s\", \"%s\"], \"noisy_leaves\": [%d, %d], \"depths\": [%d, %d],\n",
              to_string(agents[0].position_valuation), to_string(agents[1].position_valuation),
              agents[0].position_noisy_leaves, agents[1].position_noisy_leaves, agents[0].position_depth,
              agents[1].position_depth);
  json += " \"agents\": [\n";
  for (std::size_t a = 0; a < 2; ++a) {
    const std::vector<int>& v = visits[a];
    long long total = 0;
    int best = 0;
    for (const int x : v) {
      total += x;
      best = std::max(best, x);
    }
    int scoring = 0;
    long long scored = 0;
    for (const int x : v)
      if (x > 0) {
        ++scoring;
        scored += x;
      }
    const double per_visit = v.empty() ? 0.0 : static_cast<double>(total) / static_cast<double>(v.size());
    const double mean_break = scoring > 0 ? static_cast<double>(scored) / scoring : 0.0;
    const double made_share = breaks[a] > 0 ? static_cast<double>(made[a]) / breaks[a] : 0.0;
    const double run_share = breaks[a] > 0 ? static_cast<double>(runs[a]) / breaks[a] : 0.0;
    const double run_after_made = made[a] > 0 ? static_cast<double>(runs[a]) / made[a] : 0.0;
    std::printf("%s:\n", o.names[a].c_str());
    if (pool)
      std::printf("  breaks %d: made a ball %.3f, break-and-run %.3f (%.3f of the made ones); balls per visit %.2f\n",
                  breaks[a], made_share, run_share, run_after_made, per_visit);
    else if (o.game == GameKind::snooker)
      std::printf("  breaks (scoring visits) %d: mean %.1f, highest %d; points per visit %.2f\n", scoring, mean_break,
                  best, per_visit);
    else
      std::printf("  general average %.3f points per inning (%lld in %zu innings), highest run %d\n", per_visit, total,
                  v.size(), best);
    std::printf("  fouls per game %.2f; median decision %.3f s CPU over %zu decisions\n",
                static_cast<double>(fouls[a]) / o.games, median(cpu[a]), cpu[a].size());
    json += fmt("  {\"name\": \"%s\", \"won\": %d, \"breaks\": %d, \"made_breaks\": %d, \"break_and_runs\": %d, "
                "\"visits\": %zu, \"points_per_visit\": %.6g, \"mean_break\": %.6g, \"highest_break\": %d, "
                "\"fouls_per_game\": %.6g, \"median_decision_cpu_seconds\": %.6g, \"decisions\": %zu}%s\n",
                o.names[a].c_str(), won[a], breaks[a], made[a], runs[a], v.size(), per_visit, mean_break, best,
                static_cast<double>(fouls[a]) / o.games, median(cpu[a]), cpu[a].size(), a == 0 ? "," : "");
  }
  json += " ]\n}\n";
  if (!o.json.empty()) tools::write_file(kFlags, "--json", o.json, json);
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return cueball::tools::tool_main("cueball-agent-benchmark", parse(argc, argv), run); }
