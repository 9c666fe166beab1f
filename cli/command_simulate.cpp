// cueball simulate, cueball batch: whole shots on a table (scenario.hpp).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>
#include <vector>

#include "common.hpp"
#include "cueball/io/batch_json.hpp"
#include "cueball/io/scenario_json.hpp"
#include "cueball/io/result_json.hpp"
#include "cueball/simulation/batch.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/simulation/scenario.hpp"
#include "cueball/io/viewer_page.hpp"

namespace cueball::cli {

namespace {

Scenario load_scenario(const std::string& path) {
  return path.empty() ? default_scenario()
                      : scenario_from_json(read_text_file(path, "the scenario file", kMaxScenarioBytes));
}


// ------------------------------------------------------------------ simulate

struct SimulateFlags {
  std::string scenario;
  std::string output;
  std::string html;
  double sample = 0.0;
  bool json = false;
};

void run_simulate(const SimulateFlags& f, std::ostream& out, std::ostream& err) {
  check_flag("--sample", f.sample, 0.0, 10000.0, "sampling rate, Hz (0: none)");
  // A result file (-o) replays its "scenario" (scenario_from_document).
  const Scenario s = f.scenario.empty()
                         ? default_scenario()
                         : scenario_from_document(read_text_file(f.scenario, "the scenario file", kMaxScenarioBytes));
  SimulationResult r;
  try {
    r = run_scenario(s);
  } catch (const SimulationError& e) {
    throw std::runtime_error(std::string("simulation stopped: ") + e.what());
  }
  const std::string json = result_to_json(s, r, f.sample);
  if (!f.output.empty()) write_text_file(f.output, json + '\n', "-o", "the result file");
  if (!f.html.empty())
    write_text_file(f.html, viewer_page(viewer_template(), result_to_json(s, r, f.sample, -1)), "--html",
                    "the viewer page");
  if (f.json) {
    out << json << '\n';
    return;
  }
  std::map<std::string, int> by_type;
  for (const Event& e : r.events) ++by_type[to_string(e.type)];
  out << (f.scenario.empty() ? std::string("built-in 9-ball break") : f.scenario) << " on " << s.table.name << ": "
      << r.events.size() << " events, every ball at rest after " << fixed(r.end_time, 2) << " s\n";
  std::string counts;
  for (const auto& [type, count] : by_type) counts += (counts.empty() ? " " : ", ") + type + " " + std::to_string(count);
  out << "  events:" << counts << "\n  ball  name      pocketed          final position (m)   at t (s)\n";
  for (const BallTrajectory& b : r.balls) {
    char line[160];
    const std::string pocket = b.pocketed ? s.table.pockets[static_cast<std::size_t>(b.pocket)].name : "-";
    std::snprintf(line, sizeof line, "  %4d  %-8s  %-16s  (%6.3f, %6.3f)      %s\n", b.id, b.name.c_str(), pocket.c_str(),
                  b.final_state.position.x, b.final_state.position.y,
                  b.pocketed ? fixed(b.pocket_time, 3).c_str() : "-");
    out << line;
  }
  if (!f.output.empty()) out << "  result written to " << f.output << '\n';
  if (!f.html.empty()) out << "  viewer written to " << f.html << " (open it in a browser)\n";
  (void)err;
}

// ------------------------------------------------------------------ outcomes CSV

// Per-shot outcomes as CSV (README, "Batches"): one header line, then one
// row per shot in shot order:
//   shot,miscue,failure,speed_reflected,elevation_reflected,events,first_contact,
//   then for each ball, in the scenario's order, with its id:
//   pocketed_ID,pocket_ID,x_ID,y_ID,cushions_before_contact_ID,cushions_ID
// Flags 0/1; pocket the table's pocket index (-1 not pocketed); x, y the
// final position in m, shortest round-trip decimal ("nan" when the shot was
// not simulated); first_contact the id of the cue ball's first ball (-1).
// Each row is written when its shot's block is merged, so memory does not
// grow with the number of shots.
class OutcomeCsv {
 public:
  OutcomeCsv(const std::string& path, const Scenario& s) : path_(path), file_(path, std::ios::binary) {
    if (!file_) fail();
    line_ = "shot,miscue,failure,speed_reflected,elevation_reflected,events,first_contact";
    for (const SimulationBall& b : s.balls) {
      const std::string id = std::to_string(b.id);
      for (const char* column : {"pocketed_", "pocket_", "x_", "y_", "cushions_before_contact_", "cushions_"})
        line_ += std::string(",") + column + id;
    }
    line_ += '\n';
    write();
  }

  void add(long long shot, const ShotOutcome& o) {
    line_.clear();
    number(shot);
    flag(o.kind == ShotOutcome::Kind::miscue);
    flag(o.kind == ShotOutcome::Kind::failure);
    flag(o.speed_reflected);
    flag(o.elevation_reflected);
    number(o.events);
    number(o.first_contact);
    for (std::size_t j = 0; j < o.pocketed.size(); ++j) {
      flag(o.pocketed[j] != 0);
      number(o.pocket[j]);
      real(o.final_position[j].x);
      real(o.final_position[j].y);
      number(o.cushions_before_contact[j]);
      number(o.cushions[j]);
    }
    line_.back() = '\n';
    write();
  }

  void close() {
    if (!file_.flush()) fail();
    file_.close();
    if (!file_) fail();
  }

 private:
  [[noreturn]] void fail() const {
    throw UsageError("--outcomes " + quote_input(path_, kMaxEchoedPathChars) + ": cannot write the outcomes file");
  }
  void write() {
    if (!file_.write(line_.data(), static_cast<std::streamsize>(line_.size()))) fail();
  }
  void flag(bool b) { line_ += b ? "1," : "0,"; }
  void number(long long v) {
    line_ += std::to_string(v);
    line_ += ',';
  }
  void real(double v) {
    char buf[32];
    if (std::isnan(v)) {
      line_ += "nan,";
      return;
    }
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    line_.append(buf, r.ptr);
    line_ += ',';
  }

  std::string path_;
  std::ofstream file_;
  std::string line_;
};

// ------------------------------------------------------------------ batch

// Noisy copies without noise are identical shots: said on stderr, since
// it is seldom what was meant (the scenario has no "noise").
void warn_if_noiseless(const Scenario& s, const char* flags, std::ostream& err) {
  if (s.noise == CueStrikeNoise{})
    err << "cueball: warning: the noise is zero (the scenario has no \"noise\"" << flags
        << "): every shot is the nominal strike\n";
}

struct BatchFlags {
  std::string scenario;
  std::string outcomes;
  double shots = 1000;  // read as a number so that 1e9 or 1e20 get the range error, not a parse error
  int threads = 1;
  long long seed = 0;
  bool json = false;
  SigmaFlags sigma;
};

void run_batch(const BatchFlags& f, std::ostream& out, std::ostream& err) {
  check_flag("--shots", f.shots, 1, kMaxBatchShots, "number of shots; memory does not grow with it");
  if (f.shots != std::floor(f.shots))
    throw UsageError("--shots = " + format_number_beside(f.shots, {std::round(f.shots)}) + " is not a whole number of shots");
  check_flag("--threads", f.threads, 1, kMaxBatchThreads, "worker threads");
  check_flag("--seed", static_cast<double>(f.seed), 0, 9.0e15, "random seed");
  Scenario s = load_scenario(f.scenario);
  if (!s.cue) throw UsageError("the scenario has no \"cue\" strike to repeat");
  s.noise = with_sigma_flags(f.sigma, s.noise, s.settings.parameters.ball.radius);
  warn_if_noiseless(s, " and no --sigma-* flag sets one", err);

  std::optional<OutcomeCsv> csv;
  if (!f.outcomes.empty()) csv.emplace(f.outcomes, s);
  const BatchResult r =
      simulate_batch(s, {static_cast<int>(f.shots), f.threads, static_cast<std::uint64_t>(f.seed)},
                     csv ? OutcomeSink([&](int shot, const ShotOutcome& o) { csv->add(shot, o); }) : OutcomeSink());
  if (csv) csv->close();
  if (f.json) {
    out << batch_result_to_json(s, r) << '\n';
    return;
  }
  const Report report = batch_report(r, "batch of " + std::to_string(r.shots) + " noisy shots (" +
                                            std::to_string(f.threads) + " threads, seed " + std::to_string(f.seed) + ")");
  emit(report, false, out, err);
  out << "  ball  name      P(pocketed)   final position: mean (m)      std (m)\n";
  for (std::size_t i = 0; i < r.balls.size(); ++i) {
    const BallOutcome& b = r.balls[i];
    char line[160];
    std::snprintf(line, sizeof line, "  %4d  %-8s  %11.3f   (%6.3f, %6.3f)   (%5.3f, %5.3f)\n", b.id, s.balls[i].name.c_str(),
                  b.pocketed_probability, b.mean_position.x, b.mean_position.y, b.position_std.x, b.position_std.y);
    out << line;
  }
  if (csv) out << "  per-shot outcomes written to " << f.outcomes << '\n';
}

// ------------------------------------------------------------------ many

// A CSV of numbers with a fixed header: the data rows, row-major. With
// `empty`, a cell left empty is allowed: NaN in the values, 1 in `empty`
// (one flag per value); without it, it is an error like any non-number.
std::vector<double> read_number_csv(const std::string& path, const char* flag, const std::string& header,
                                    std::size_t& rows, std::vector<std::uint8_t>* empty = nullptr) {
  const std::string text = read_text_file(path, std::string("the ") + (flag + 2) + " file", kMaxResultFileBytes);
  const std::string where = std::string(flag) + " " + quote_input(path, kMaxEchoedPathChars);
  std::vector<double> values;
  std::size_t columns = 1;
  for (char c : header) columns += c == ',' ? 1 : 0;
  rows = 0;
  std::size_t line_no = 0, start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    start = end + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line_no == 1) {
      if (line != header)
        throw UsageError(where + " line 1: the header must be \"" + header + "\", got " + quote_input(line));
      continue;
    }
    if (line.empty()) continue;
    std::size_t column = 0, cell_start = 0;
    while (true) {
      const std::size_t comma = line.find(',', cell_start);
      const std::string cell = line.substr(cell_start, comma == std::string::npos ? std::string::npos : comma - cell_start);
      ++column;
      double v = 0.0;
      const char* first = cell.data();
      while (first < cell.data() + cell.size() && *first == ' ') ++first;
      const bool blank = first == cell.data() + cell.size();
      const auto r = std::from_chars(first, cell.data() + cell.size(), v);
      if (blank && empty != nullptr) v = std::numeric_limits<double>::quiet_NaN();
      else if (r.ec != std::errc() || r.ptr != cell.data() + cell.size())
        throw UsageError(where + " line " + std::to_string(line_no) + ", column " + std::to_string(column) + ": " +
                         quote_input(cell) + " is not a number");
      values.push_back(v);
      if (empty != nullptr) empty->push_back(blank ? 1 : 0);
      if (comma == std::string::npos) break;
      cell_start = comma + 1;
    }
    if (column != columns)
      throw UsageError(where + " line " + std::to_string(line_no) + ": " + std::to_string(column) + " values, expected " +
                       std::to_string(columns) + " (" + header + ")");
    ++rows;
  }
  if (line_no == 0) throw UsageError(where + ": the file is empty; it needs the header \"" + header + "\"");
  return values;
}

// A layouts CSV's empty cells as simulate_many's present flags (empty when
// every ball is in every row): a ball whose x and y cells are both empty is
// not on the table in that shot; one of the two empty is an error.
std::vector<std::uint8_t> absent_balls(const std::vector<std::uint8_t>& empty, const Scenario& s,
                                       const std::string& path) {
  if (std::find(empty.begin(), empty.end(), 1) == empty.end()) return {};
  const std::size_t n = s.balls.size();
  std::vector<std::uint8_t> present(empty.size() / 2, 1);
  for (std::size_t e = 0; e < present.size(); ++e) {
    if (empty[2 * e] != empty[2 * e + 1])
      throw UsageError("--layouts " + quote_input(path, kMaxEchoedPathChars) + " line " + std::to_string(e / n + 2) +
                       ": one of x_" + std::to_string(s.balls[e % n].id) + ", y_" + std::to_string(s.balls[e % n].id) +
                       " is empty; leave both empty for a ball not on the table");
    present[e] = empty[2 * e] ? 0 : 1;
  }
  return present;
}

struct ManyFlags {
  std::string scenario;
  std::string actions;
  std::string layouts;
  std::string outcomes;
  int threads = 1;
  long long seed = 0;
  long long first_shot = 0;
  bool noise = false;
  bool json = false;
};

void run_many(const ManyFlags& f, std::ostream& out, std::ostream& err) {
  check_flag("--threads", f.threads, 1, kMaxBatchThreads, "worker threads");
  check_flag("--seed", static_cast<double>(f.seed), 0, 9.0e15, "random seed");
  check_flag("--first-shot", static_cast<double>(f.first_shot), 0, static_cast<double>(kMaxFirstShot),
             "index of the first data row in the whole study");
  const Scenario s = load_scenario(f.scenario);
  if (f.noise) warn_if_noiseless(s, "", err);
  std::size_t shots = 0;
  const std::vector<double> numbers =
      read_number_csv(f.actions, "--actions", "speed,aim_deg,elevation_deg,side,height", shots);
  if (shots < 1 || shots > static_cast<std::size_t>(kMaxManyShots))
    throw UsageError("--actions " + quote_input(f.actions, kMaxEchoedPathChars) + ": " + std::to_string(shots) +
                     " shots; allowed [1, " + std::to_string(kMaxManyShots) + "]");
  std::vector<ShotAction> actions(shots);
  for (std::size_t k = 0; k < shots; ++k)
    actions[k] = {numbers[5 * k], numbers[5 * k + 1], numbers[5 * k + 2], numbers[5 * k + 3], numbers[5 * k + 4]};
  std::vector<double> layouts;
  std::vector<std::uint8_t> present;  // empty: every ball on the table in every shot
  if (!f.layouts.empty()) {
    std::string header;
    for (const SimulationBall& b : s.balls)
      header += (header.empty() ? "" : ",") + std::string("x_") + std::to_string(b.id) + ",y_" + std::to_string(b.id);
    std::size_t rows = 0;
    std::vector<std::uint8_t> empty;
    layouts = read_number_csv(f.layouts, "--layouts", header, rows, &empty);
    if (rows != shots)
      throw UsageError("--layouts " + quote_input(f.layouts, kMaxEchoedPathChars) + ": " + std::to_string(rows) +
                       " layouts for " + std::to_string(shots) + " actions; give one per action");
    present = absent_balls(empty, s, f.layouts);
  }
  ManyResult r;
  try {
    ManyOptions options{f.threads, static_cast<std::uint64_t>(f.seed), f.noise};
    options.first_shot = static_cast<std::uint64_t>(f.first_shot);
    r = simulate_many(s, actions, layouts, options, present);
  } catch (const InvalidArgument& e) {
    // actions[first_shot + k] is data row k (line k + 2) of the file.
    const std::string& field = e.field();
    const std::string row = f.first_shot == 0 ? "k" : std::to_string(f.first_shot) + " + k";
    if (field.rfind("actions[", 0) == 0)
      throw UsageError("--actions (data row k is actions[" + row + "]): " + std::string(e.what()));
    if (field.rfind("layouts[", 0) == 0 || field.rfind("present[", 0) == 0)
      throw UsageError("--layouts (data row k is layouts[" + row + "]): " + std::string(e.what()));
    throw;
  }
  if (!f.outcomes.empty()) {
    OutcomeCsv csv(f.outcomes, s);
    for (int k = 0; k < r.shots; ++k) csv.add(static_cast<long long>(f.first_shot) + k, r.outcome(k));
    csv.close();
  }
  if (f.json) {
    out << many_result_to_json(r, f.outcomes) << '\n';
    return;
  }
  std::vector<int> potted(s.balls.size(), 0);
  for (std::size_t k = 0; k < shots; ++k)
    for (std::size_t j = 0; j < s.balls.size(); ++j) potted[j] += r.pocketed[k * s.balls.size() + j];
  const Report report = many_report(r, "many: " + std::to_string(r.shots) + " shots (" + std::to_string(f.threads) +
                                           " threads" +
                                           (f.noise ? ", noise, seed " + std::to_string(f.seed) : std::string(", no noise")) +
                                           ")");
  emit(report, false, out, err);
  out << "  ball  name      pocketed (shots)\n";
  for (std::size_t i = 0; i < s.balls.size(); ++i) {
    char line[96];
    std::snprintf(line, sizeof line, "  %4d  %-8s  %d\n", s.balls[i].id, s.balls[i].name.c_str(), potted[i]);
    out << line;
  }
  if (!f.outcomes.empty()) out << "  per-shot outcomes written to " << f.outcomes << '\n';
}

}  // namespace

Command add_many_command(CLI::App& app) {
  auto flags = std::make_shared<ManyFlags>();
  CLI::App* sub = app.add_subcommand(
      "many",
      "Plays N different cue actions on the scenario's table and balls (simulate_many), each from the\n"
      "scenario's layout or its own (--layouts), across threads; deterministic whatever --threads is.\n"
      "--actions CSV: header speed,aim_deg,elevation_deg,side,height (m/s, degrees, degrees, ball radii,\n"
      "ball radii: the scenario's \"cue\" units), one row per shot, struck on the scenario's cue ball.\n"
      "--layouts CSV: header x_ID,y_ID for every ball in the scenario's order (m), one row per action;\n"
      "both cells of a ball left empty: that ball is not on the table in that shot (the cue ball must be).\n"
      "An action's tip offset beyond the miscue limit (sqrt(side^2+height^2) > 0.5) is a miscue, counted.\n"
      "--noise adds the scenario's execution noise (seeded per shot by --seed, as batch does).\n"
      "--outcomes writes every shot's outcome as CSV in batch --outcomes' format. At most 1e6 shots.\n"
      "--first-shot K: the file's rows are shots K, K+1, ... of a bigger study split into files (their\n"
      "noise and their rows' numbers in --outcomes and in errors): the parts' outcomes are the whole's.");
  sub->add_option("scenario", flags->scenario, "Scenario JSON file (default: the built-in 9-ball break)");
  sub->add_option("--actions", flags->actions, "CSV of the shots' cue actions")->required();
  sub->add_option("--layouts", flags->layouts, "CSV of the shots' ball positions");
  sub->add_option("--outcomes", flags->outcomes, "Write each shot's outcome to this CSV file (one row per shot)");
  sub->add_option("--threads", flags->threads, "Worker threads")->capture_default_str();
  sub->add_option("--seed", flags->seed, "Random seed of the noise")->capture_default_str();
  sub->add_option("--first-shot", flags->first_shot, "Shot number of the first data row in the whole study")
      ->capture_default_str();
  sub->add_flag("--noise", flags->noise, "Perturb each action with the scenario's execution noise");
  sub->add_flag("--json", flags->json, "Print one JSON object");
  return [flags](std::ostream& out, std::ostream& err) { run_many(*flags, out, err); };
}

Command add_simulate_command(CLI::App& app) {
  auto flags = std::make_shared<SimulateFlags>();
  CLI::App* sub = app.add_subcommand(
      "simulate",
      "Simulates a whole shot, event by event, until every ball is at rest or pocketed. SCENARIO.json\n"
      "describes the table, the balls (or a rack), the cue strike and the parameters (see README,\n"
      "'Scenario format'); without it, a built-in 9-ball break. Positions in m from the table's corner,\n"
      "x along the length; speeds m/s; angles degrees in the scenario. Prints a summary; -o writes the\n"
      "full result (events, final states, trajectory segments, the cue strike and the whole scenario),\n"
      "--json prints it. SCENARIO.json may also be such a result file: its \"scenario\" is replayed,\n"
      "bit for bit.");
  sub->add_option("scenario", flags->scenario,
                  "Scenario JSON file, or a result file to replay (default: the built-in 9-ball break)");
  sub->add_option("-o,--output", flags->output, "Write the result JSON to this file");
  sub->add_option("--html", flags->html, "Write the shot as a self-contained HTML viewer page to this file");
  sub->add_option("--sample", flags->sample, "Also sample every ball's state at this rate, Hz");
  sub->add_flag("--json", flags->json, "Print the result JSON instead of the summary");
  return [flags](std::ostream& out, std::ostream& err) { run_simulate(*flags, out, err); };
}

Command add_batch_command(CLI::App& app) {
  auto flags = std::make_shared<BatchFlags>();
  CLI::App* sub = app.add_subcommand(
      "batch",
      "Simulates N copies of the scenario's shot with Gaussian execution noise on the cue strike (speed,\n"
      "aim, elevation, tip offsets; sigmas from the scenario's \"noise\" or the --sigma-* flags) across\n"
      "threads. Deterministic for a seed whatever --threads is. Reports each ball's pocketing\n"
      "probability and final-position spread, and the throughput. A noisy speed above the 12 m/s cap\n"
      "or an elevation below 0 is reflected at the limit (2 cap - v, -e) and counted; a noisy tip\n"
      "offset beyond the miscue limit (0.5 R) is a miscue, counted and not simulated. Memory does\n"
      "not grow with --shots (at most 1e8). --outcomes FILE also writes every shot's outcome as CSV\n"
      "(pocketing, pocket, final position, first ball contacted, cushion contacts per ball; README).");
  sub->add_option("scenario", flags->scenario, "Scenario JSON file (default: the built-in 9-ball break)");
  sub->add_option("--shots", flags->shots, "Number of shots, [1, 1e8]")->capture_default_str();
  sub->add_option("--threads", flags->threads, "Worker threads")->capture_default_str();
  sub->add_option("--seed", flags->seed, "Random seed")->capture_default_str();
  add_sigma_flags(*sub, flags->sigma);
  sub->add_option("--outcomes", flags->outcomes, "Write each shot's outcome to this CSV file (one row per shot)");
  sub->add_flag("--json", flags->json, "Print one JSON object");
  return [flags](std::ostream& out, std::ostream& err) { run_batch(*flags, out, err); };
}

}  // namespace cueball::cli
