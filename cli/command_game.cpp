// cueball game: new, shoot, play and replay (games/game.hpp, agents/,
// io/game_json.hpp). A state file is a scenario plus its "game" object;
// a record file holds whole games that `replay` re-plays bit for bit.
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "common.hpp"
#include "cueball/agents/match.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/io/game_json.hpp"
#include "cueball/io/game_viewer_json.hpp"
#include "cueball/io/scenario_json.hpp"
#include "cueball/planning/shot_planner.hpp"
#include "cueball/io/viewer_page.hpp"

namespace cueball::cli {

namespace {

// ------------------------------------------------------------------ flag values

constexpr double kMaxSeed = 9.0e15;

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, sep);) parts.push_back(part);
  if (!text.empty() && text.back() == sep) parts.emplace_back();
  return parts;
}

// A whole number in [lo, hi] given as `flag` (the value as written: "1e3" is refused).
long long whole(const std::string& flag, const std::string& value, long long lo, long long hi, const char* meaning) {
  std::size_t used = 0;
  long long x = 0;
  try {
    x = std::stoll(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != value.size())
    throw UsageError(flag + " = " + quote_input(value) + " is not a whole number; allowed: [" + std::to_string(lo) + ", " +
                     std::to_string(hi) + "] (" + meaning + ")");
  if (x < lo || x > hi)
    throw UsageError(flag + " = " + value + " is outside the allowed range [" + std::to_string(lo) + ", " +
                     std::to_string(hi) + "] (" + meaning + ")");
  return x;
}

double finite(const std::string& flag, const std::string& whole_value, const std::string& part, const char* allowed) {
  std::size_t used = 0;
  double x = 0.0;
  try {
    x = std::stod(part, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != part.size() || !std::isfinite(x))
    throw UsageError(flag + " = " + quote_input(whole_value) + ": " + quote_input(part) + " is not a finite number; allowed: " +
                     allowed);
  return x;
}

std::uint64_t seed_flag(const std::string& value) {
  return static_cast<std::uint64_t>(whole("--seed", value, 0, static_cast<long long>(kMaxSeed), "random seed"));
}

GameKind game_flag(const std::string& value) {
  const std::optional<GameKind> kind = game_kind_from_string(value);
  if (!kind) throw UsageError("--game = " + quote_input(value) + " is not a game; allowed: " + game_kind_names());
  return *kind;
}

// --noise: tournament, none, or a scenario "noise" object; `fallback` when not given.
CueStrikeNoise noise_flag(const std::string& value, double radius, const CueStrikeNoise& fallback, bool json_allowed) {
  if (value.empty()) return fallback;
  if (value == "none") return CueStrikeNoise{};
  if (value == "tournament") return tournament_noise();
  if (json_allowed && value.front() == '{') return noise_from_json(value, radius, "--noise");
  throw UsageError("--noise = " + quote_input(value) + " is not known; allowed: tournament, none" +
                   (json_allowed ? ", or a JSON object {\"speed\", \"aim_deg\", \"elevation_deg\", \"side\", \"height\"}" : ""));
}

// A library error about a game (new_game's "kind", an agent's "agent") as the flag that chose it.
[[noreturn]] void rethrow_as_flag(const InvalidArgument& e, const std::string& game, const std::string& players) {
  if (e.field() == "kind") throw UsageError("--game = " + game + ": " + e.what());
  if (e.field() == "agent" || e.field().rfind("players[", 0) == 0)
    throw UsageError("--players = " + quote_input(players) + ": " + e.what());
  throw e;
}

std::string ids(const std::vector<int>& v) {
  std::string s;
  for (const int id : v) s += (s.empty() ? "" : ", ") + std::to_string(id);
  return s.empty() ? "none" : s;
}

std::string region_text(const std::optional<PlacementRegion>& r) {
  if (!r) return "";
  if (r->kind != PlacementRegion::Kind::rectangle) return to_string(r->kind);
  return "rectangle [" + fixed(r->x_min) + ", " + fixed(r->x_max) + "] x [" + fixed(r->y_min) + ", " + fixed(r->y_max) + "]";
}

// What the player to act does next, in a few words.
std::string next_text(const GameState& s) {
  if (s.over) {
    if (s.truncated) return "game over, truncated (" + s.end_reason + ")";
    return "game over: player " + std::to_string(*s.winner) + " wins (" + s.end_reason + "); scores " +
           std::to_string(s.scores[0]) + "-" + std::to_string(s.scores[1]);
  }
  const LegalActions legal = legal_actions(s);
  std::string t = "player " + std::to_string(legal.player) + " to ";
  if (!legal.shoot) {
    std::string open;
    for (const Decision d : legal.decisions) open += (open.empty() ? "" : ", ") + std::string(to_string(d));
    return t + "decide: " + open;
  }
  t += std::string(s.phase == GamePhase::break_shot ? "break" : "shoot") + " (on: " + ids(legal.on) + ")";
  if (legal.ball_in_hand) t += ", cue ball in hand " + region_text(legal.ball_in_hand);
  if (legal.call_required) t += ", call a ball and a pocket";
  if (legal.nominate_required) t += ", nominate one of " + ids(legal.nominable);
  if (legal.push_out) t += ", may push out";
  return t;
}

// ------------------------------------------------------------------ game new

struct NewFlags {
  std::string game;
  std::string seed = "0";
  std::string noise;
  std::string output;
};

void run_new(const NewFlags& f, std::ostream& out) {
  GameConfig config = default_config(game_flag(f.game));
  const std::uint64_t seed = seed_flag(f.seed);
  config.noise = noise_flag(f.noise, preset_table(config.table).ball.radius, config.noise, true);
  GameState s;
  try {
    s = new_game(config, seed);
  } catch (const InvalidArgument& e) {
    rethrow_as_flag(e, f.game, "");
  }
  const std::string json = game_state_to_json(s) + '\n';
  if (f.output.empty()) {
    out << json;
    return;
  }
  write_text_file(f.output, json, "-o", "the state file");
  out << "game new: " << to_string(config.kind) << " on " << s.table.table.name << ", " << s.table.balls.size()
      << " balls; " << next_text(s) << "; state written to " << f.output << '\n';
}

// ------------------------------------------------------------------ game shoot

struct ShootFlags {
  std::string state;
  std::string cue;
  std::string place;
  std::string call;
  bool push_out = false;
  std::string nominate;
  std::string decision;
  std::string noise;
  std::string seed = "0";
  std::string output;
  bool json = false;
};

// The library's field of an illegal action, as the flag that sets it.
std::string flag_of_action_field(const std::string& field) {
  if (field == "place") return "--place";
  if (field == "called_ball" || field == "called_pocket") return "--call";
  if (field == "nominate") return "--nominate";
  if (field == "decision") return "--decision";
  if (field == "push_out") return "--push-out";
  if (field == "aim_at") return "--cue.target";
  for (const char* key : {"speed", "aim_deg", "elevation_deg", "side", "height"})
    if (field == key) return std::string("--cue.") + key;
  return "";
}

Action action_from_flags(const ShootFlags& f, const GameState& s) {
  const Table& table = s.table.table;
  if (!f.decision.empty()) {
    if (!f.cue.empty()) throw UsageError("--decision = " + quote_input(f.decision) + " and --cue are both given; allowed: one of them");
    for (const auto& [given, flag] : {std::pair{!f.place.empty(), "--place"}, std::pair{!f.call.empty(), "--call"},
                                      std::pair{f.push_out, "--push-out"}, std::pair{!f.nominate.empty(), "--nominate"}})
      if (given) throw UsageError(std::string(flag) + " goes with a shot (--cue), not with --decision");
    const std::optional<Decision> d = decision_from_string(f.decision);
    if (!d) throw UsageError("--decision = " + quote_input(f.decision) + " is not a decision; allowed: " + decision_names());
    Action a;
    a.decision = d;
    return a;
  }
  if (f.cue.empty()) throw UsageError("--cue is required: the strike as a JSON object {\"speed\", \"aim_deg\" or \"target\", ...} (or --decision)");
  Action a = action_from_json(f.cue, &table, "--cue");
  if (a.decision) {
    if (!f.place.empty() || !f.call.empty() || f.push_out || !f.nominate.empty())
      throw UsageError("--cue = {\"decision\": ...} takes no --place, --call, --push-out or --nominate");
    return a;
  }
  if (!f.place.empty()) {
    if (a.place) throw UsageError("--place = " + quote_input(f.place) + " and --cue's \"place\" are both given; allowed: one");
    const std::vector<std::string> p = split(f.place, ',');
    if (p.size() != 2) throw UsageError("--place = " + quote_input(f.place) + " must be X,Y (m, the cue ball's spot)");
    a.place = Vec2{finite("--place", f.place, p[0], "X,Y in m"), finite("--place", f.place, p[1], "X,Y in m")};
  }
  if (!f.call.empty()) {
    if (a.called_ball || a.called_pocket)
      throw UsageError("--call = " + quote_input(f.call) + " and --cue's \"call\" are both given; allowed: one");
    const std::vector<std::string> c = split(f.call, ',');
    std::string pockets;
    for (const Pocket& p : table.pockets) pockets += (pockets.empty() ? "" : ", ") + p.name;
    if (c.size() != 2)
      throw UsageError("--call = " + quote_input(f.call) + " must be BALL,POCKET (a pocket's name or index: " + pockets + ")");
    a.called_ball = static_cast<int>(whole("--call", c[0], 0, 1000, "the called ball's id"));
    for (std::size_t k = 0; k < table.pockets.size(); ++k)
      if (table.pockets[k].name == c[1]) a.called_pocket = static_cast<int>(k);
    if (!a.called_pocket) {
      if (c[1].empty() || c[1].find_first_not_of("0123456789") != std::string::npos)
        throw UsageError("--call = " + quote_input(f.call) + ": " + quote_input(c[1]) + " is not a pocket; allowed: " + pockets +
                         " (or its index)");
      a.called_pocket = static_cast<int>(
          whole("--call", c[1], 0, static_cast<long long>(table.pockets.size()) - 1, "the called pocket's index"));
    }
  }
  if (f.push_out) a.push_out = true;
  if (!f.nominate.empty()) {
    if (a.nominate) throw UsageError("--nominate and --cue's \"nominate\" are both given; allowed: one");
    a.nominate = static_cast<int>(whole("--nominate", f.nominate, 0, 1000, "the nominated ball's id"));
  }
  return a;
}

std::string shot_text(const GameState& before, const GameStep& step) {
  const Ruling& r = step.ruling;
  std::string t = "shot " + std::to_string(before.shots + 1) + ", player " + std::to_string(before.to_shoot) + ": ";
  if (step.action.decision) {
    t += std::string("decision ") + to_string(*step.action.decision) + " (" + r.reason + ")";
  } else {
    t += "first contact " + (step.facts.first_contact >= 0 ? std::to_string(step.facts.first_contact) : std::string("none"));
    t += ", pocketed " + ids(r.pocketed);
    if (!r.respotted.empty()) t += ", respotted " + ids(r.respotted);
    t += r.foul ? std::string("; foul ") + to_string(*r.foul) + " (" + r.reason + ")" : "; no foul (" + r.reason + ")";
  }
  if (r.points[0] != 0 || r.points[1] != 0)
    t += "; points " + std::to_string(r.points[0]) + "-" + std::to_string(r.points[1]);
  return t + "; " + next_text(step.next);
}

void run_shoot(const ShootFlags& f, std::ostream& out) {
  const GameState s = game_state_from_json(read_text_file(f.state, "the state file", kMaxScenarioBytes));
  const Action action = action_from_flags(f, s);
  const std::uint64_t seed = seed_flag(f.seed);
  GameState as_played = s;
  as_played.config.noise = noise_flag(f.noise, s.table.table.ball.radius, s.config.noise, true);
  GameStep step;
  try {
    step = play(as_played, action, seed);
  } catch (const InvalidArgument& e) {
    if (e.field() == "action") throw UsageError(quote_input(f.state, kMaxEchoedPathChars) + ": " + e.what());
    const std::string flag = flag_of_action_field(e.field());
    if (flag.empty()) throw;
    throw UsageError(flag + ": illegal action: " + e.what());
  }
  step.next.config.noise = s.config.noise;  // --noise is this shot's, not the game's
  if (!f.output.empty()) write_text_file(f.output, game_state_to_json(step.next) + '\n', "-o", "the state file");
  if (f.json) {
    out << game_step_to_json(step) << '\n';
    return;
  }
  out << shot_text(s, step) << '\n';
  if (!f.output.empty()) out << "  state written to " << f.output << '\n';
}

// ------------------------------------------------------------------ game play

struct PlayFlags {
  std::string game;
  std::string players;
  std::string games = "1";
  std::string seed = "0";
  std::string noise = "none";
  std::string simulations;
  std::string seconds;
  std::string record;
  std::string html;
  bool json = false;
};

std::array<AgentOptions, 2> players_flag(const PlayFlags& f, const CueStrikeNoise& noise) {
  const std::vector<std::string> names = split(f.players, ',');
  if (names.size() != 2)
    throw UsageError("--players = " + quote_input(f.players) + " must name two agents, A,B; allowed: " + agent_names());
  std::array<AgentOptions, 2> players;
  for (std::size_t p = 0; p < 2; ++p) {
    const std::optional<AgentOptions> agent = agent_named(names[p]);
    if (!agent)
      throw UsageError("--players = " + quote_input(f.players) + ": " + quote_input(names[p]) + " is not an agent; allowed: " +
                       agent_names());
    players[p] = *agent;
    players[p].noise = noise;
    if (!f.simulations.empty())
      players[p].simulations = static_cast<int>(whole("--simulations", f.simulations, 1, 1'000'000, "engine runs a decision may spend"));
    if (!f.seconds.empty()) {
      const double s = finite("--seconds", f.seconds, f.seconds, "[0, 3600] (seconds a decision; 0: none)");
      if (!(s >= 0.0 && s <= kMaxAgentSeconds))
        throw UsageError("--seconds = " + f.seconds + " is outside the allowed range [0, 3600] (seconds a decision; 0: none)");
      players[p].seconds = s;
    }
  }
  return players;
}

void run_play(const PlayFlags& f, std::ostream& out) {
  GameConfig config = default_config(game_flag(f.game));
  config.noise = noise_flag(f.noise, preset_table(config.table).ball.radius, config.noise, false);
  const std::array<AgentOptions, 2> players = players_flag(f, config.noise);
  const long long games = whole("--games", f.games, 1, 100000, "games to play");
  const std::uint64_t seed = seed_flag(f.seed);
  std::vector<GameRecord> records;
  for (long long g = 0; g < games; ++g) {
    try {
      records.push_back(play_game(config, players, seed + static_cast<std::uint64_t>(g)));
    } catch (const InvalidArgument& e) {
      rethrow_as_flag(e, f.game, f.players);
    }
  }
  if (!f.record.empty()) write_text_file(f.record, game_records_to_json(records) + '\n', "--record", "the game record");
  if (!f.html.empty())
    write_text_file(f.html, viewer_page(viewer_template(), game_viewer_json(records.front())), "--html", "the viewer page");
  if (f.json) {
    out << game_summary_to_json(records) << '\n';
    return;
  }
  std::array<int, 2> wins{}, fouls{}, pots{};
  int truncated = 0;
  out << "game play: " << to_string(config.kind) << ", player 0 " << to_string(players[0].kind) << " against player 1 "
      << to_string(players[1].kind) << ", noise " << f.noise << '\n';
  for (std::size_t g = 0; g < records.size(); ++g) {
    const GameRecord& r = records[g];
    const GameState& end = r.steps.empty() ? r.start : r.steps.back().state;
    const GameTally t = tally(r);
    out << "  game " << g + 1 << " (seed " << r.seed << "): " << end.scores[0] << "-" << end.scores[1] << ", "
        << (end.truncated ? std::string("truncated") : "won by player " + std::to_string(*end.winner)) << " in "
        << r.steps.size() << " shots; fouls " << t.fouls[0] << "-" << t.fouls[1] << ", pots " << t.pots[0] << "-"
        << t.pots[1] << " (" << end.end_reason << ")\n";
    if (end.winner) wins[static_cast<std::size_t>(*end.winner)] += 1;
    truncated += end.truncated ? 1 : 0;
    for (std::size_t p = 0; p < 2; ++p) {
      fouls[p] += t.fouls[p];
      pots[p] += t.pots[p];
    }
  }
  out << "  total: " << records.size() << " games, wins " << wins[0] << "-" << wins[1] << " (" << truncated
      << " truncated), fouls " << fouls[0] << "-" << fouls[1] << ", pots " << pots[0] << "-" << pots[1] << '\n';
  if (!f.record.empty()) out << "  record written to " << f.record << " (cueball game replay checks it)\n";
  if (!f.html.empty()) out << "  viewer of game 1 written to " << f.html << " (open it in a browser)\n";
}

// ------------------------------------------------------------------ game replay

struct ReplayFlags {
  std::string record;
};

void run_replay(const ReplayFlags& f, std::ostream& out) {
  const std::vector<GameRecord> records =
      game_records_from_json(read_text_file(f.record, "the game record", kMaxGameRecordBytes));
  std::size_t steps = 0;
  for (std::size_t g = 0; g < records.size(); ++g) {
    if (const std::optional<ReplayDifference> d = replay_difference(records[g], static_cast<int>(g)))
      throw CheckFailed("game replay: " + quote_input(f.record, kMaxEchoedPathChars) + " differs at " + d->path + ": recorded " +
                        d->recorded + ", replayed " + d->replayed);
    steps += records[g].steps.size();
  }
  out << "game replay: " << records.size() << (records.size() == 1 ? " game, " : " games, ") << steps
      << " steps replayed: every ruling and state identical, bit for bit\n";
}

}  // namespace

Command add_game_command(CLI::App& app) {
  CLI::App* game = app.add_subcommand(
      "game",
      "Plays games by their rules (9-ball, 8-ball, 10-ball, snooker, three-cushion): `game new` writes a\n"
      "state ready to break, `game shoot` plays one shot or decision from a state file, `game play` plays\n"
      "whole games between agents, `game replay` re-plays a record and checks it bit for bit.");
  game->require_subcommand(1);

  auto nf = std::make_shared<NewFlags>();
  CLI::App* n = game->add_subcommand("new", "Writes a new game's state (a scenario plus its \"game\" object), ready to break.");
  n->add_option("--game", nf->game, "The game: " + game_kind_names())->required();
  n->add_option("--seed", nf->seed, "Seed of the rack's gaps (when the config has them)")->capture_default_str();
  n->add_option("--noise", nf->noise,
                "The game's execution noise on every shot: none (default), tournament, or a JSON object\n"
                "{\"speed\": m/s, \"aim_deg\", \"elevation_deg\": deg, \"side\", \"height\": ball radii}");
  n->add_option("-o,--output", nf->output, "Write the state here (default: print it)");

  auto sf = std::make_shared<ShootFlags>();
  CLI::App* s = game->add_subcommand("shoot", "Plays one shot (--cue) or decision (--decision) from STATE.json.");
  s->add_option("state", sf->state, "The state file (game new -o, or game shoot -o)")->required();
  s->add_option("--cue", sf->cue,
                "The strike, as the scenario's \"cue\": {\"speed\": m/s, \"aim_deg\": deg | \"target\": id,\n"
                "\"elevation_deg\", \"side\", \"height\"}; may also hold \"place\", \"call\", \"push_out\", \"nominate\"");
  s->add_option("--place", sf->place, "X,Y: the cue ball's spot when in hand, m");
  s->add_option("--call", sf->call, "BALL,POCKET: the called ball and pocket (name or index)");
  s->add_flag("--push-out", sf->push_out, "Announce a push-out (9-ball, 10-ball: the shot after the break)");
  s->add_option("--nominate", sf->nominate, "Snooker: the nominated ball");
  s->add_option("--decision", sf->decision, "A decision instead of a shot: " + decision_names());
  s->add_option("--noise", sf->noise, "This shot's execution noise: none, tournament or a JSON object (default: the game's)");
  s->add_option("--seed", sf->seed, "Seed of the noise")->capture_default_str();
  s->add_option("-o,--output", sf->output, "Write the next state here");
  s->add_flag("--json", sf->json, "Print {\"action\", \"ruling\", \"facts\", \"state\"} instead of one line");

  auto pf = std::make_shared<PlayFlags>();
  CLI::App* p = game->add_subcommand("play", "Plays whole games between two agents and prints each game's score, fouls and pots.");
  p->add_option("--game", pf->game, "The game: " + game_kind_names())->required();
  p->add_option("--players", pf->players, "A,B: the agents of players 0 and 1 (" + agent_names() + ")")->required();
  p->add_option("--games", pf->games, "Games to play; game g (from 0) uses seed --seed + g")->capture_default_str();
  p->add_option("--seed", pf->seed, "Seed of the first game (rack, agents, noise)")->capture_default_str();
  p->add_option("--noise", pf->noise, "Execution noise of every shot, also what the agents plan under: tournament, none")
      ->capture_default_str();
  p->add_option("--simulations", pf->simulations, "Engine runs an agent may spend on a decision (planner, carom_search, safety_planner)");
  p->add_option("--seconds", pf->seconds,
                 "Wall-clock seconds an agent may spend on a decision, [0, 3600]: planned at doubling budgets from 500 runs up to "
                 "--simulations (or the agent's own) while the next round fits (AgentOptions::seconds); 0: none");
  p->add_option("--record", pf->record, "Write the game record here (game replay re-plays it)");
  p->add_option("--html", pf->html, "Write the first game as a self-contained HTML viewer page (every shot, its ruling) to this file");
  p->add_flag("--json", pf->json, "Print one JSON object: the games and the totals");

  auto rf = std::make_shared<ReplayFlags>();
  CLI::App* r = game->add_subcommand("replay", "Re-plays a game record and checks every ruling and state, bit for bit (exit 1 at the first difference).");
  r->add_option("record", rf->record, "The record file (game play --record)")->required();

  return [=](std::ostream& out, std::ostream&) {
    if (n->parsed()) run_new(*nf, out);
    if (s->parsed()) run_shoot(*sf, out);
    if (p->parsed()) run_play(*pf, out);
    if (r->parsed()) run_replay(*rf, out);
  };
}

}  // namespace cueball::cli
