// Tracked shots from CSV files, one a shot (io/tracked_shots_csv.hpp).
#include "cueball/io/tracked_shots_csv.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>

#include "cueball/core/errors.hpp"
#include "cueball/table/table.hpp"

namespace cueball {

namespace {

// The parse of one file: its name, the column positions, the balls by name.
struct CsvContext {
  const CsvShotFile& file;
  const Table& table;
  int column_ball = -1, column_t = -1, column_x = -1, column_y = -1;
  std::vector<std::string> header;
  std::vector<TrackedBall> balls;  // in order of first appearance
  std::map<std::string, std::size_t> index;
  int row = 0;
};

[[noreturn]] void fail(const CsvContext& c, const std::string& column, const std::string& what) {
  const std::string name = quote_input(c.file.name, kMaxEchoedPathChars);
  throw InvalidArgument(c.file.name, name + ": row " + std::to_string(c.row) + (column.empty() ? "" : ", column " + column) +
                                         ": " + what);
}

std::string trim(std::string_view field) {
  std::size_t a = 0, b = field.size();
  while (a < b && (field[a] == ' ' || field[a] == '\t')) ++a;
  while (b > a && (field[b - 1] == ' ' || field[b - 1] == '\t' || field[b - 1] == '\r')) --b;
  if (b - a >= 2 && field[a] == '"' && field[b - 1] == '"') ++a, --b;
  return std::string(field.substr(a, b - a));
}

std::vector<std::string> split(std::string_view line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= line.size(); ++i)
    if (i == line.size() || line[i] == ',') out.push_back(trim(line.substr(start, i - start))), start = i + 1;
  return out;
}

void read_header(CsvContext& c, const std::vector<std::string>& fields) {
  c.header = fields;
  for (std::size_t k = 0; k < fields.size(); ++k) {
    const auto at = static_cast<int>(k);
    int* slot = fields[k] == "ball" ? &c.column_ball
                : fields[k] == "t"  ? &c.column_t
                : fields[k] == "x"  ? &c.column_x
                : fields[k] == "y"  ? &c.column_y
                                    : nullptr;
    if (!slot)
      fail(c, quote_input(fields[k]), "is not a known column; allowed: ball, t, x, y (a header row naming them comes first)");
    if (*slot >= 0) fail(c, fields[k], "appears twice in the header");
    *slot = at;
  }
  for (const auto& [column, name] : {std::pair{c.column_ball, "ball"}, std::pair{c.column_t, "t"}, std::pair{c.column_x, "x"},
                                     std::pair{c.column_y, "y"}})
    if (column < 0) fail(c, name, "is missing from the header (the columns are ball, t, x, y, in any order)");
}

double number(const CsvContext& c, const std::string& field, const char* column) {
  if (field.empty()) fail(c, column, "is empty; allowed: a number");
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(field.c_str(), &end);
  if (end != field.c_str() + field.size() || errno == ERANGE || !std::isfinite(v))
    fail(c, column, quote_input(field) + " is not a finite number");
  return v;
}

void check_range(const CsvContext& c, const char* column, double v, double lo, double hi, const char* unit, const char* meaning) {
  if (v < lo || v > hi)
    fail(c, column, format_number(v) + " is outside [" + format_number(lo) + ", " + format_number(hi) + "] " + unit + " (" +
                        meaning + ")");
}

void read_row(CsvContext& c, const std::vector<std::string>& fields) {
  if (fields.size() != c.header.size())
    fail(c, "", "has " + std::to_string(fields.size()) + " fields; allowed: " + std::to_string(c.header.size()) +
                    " (as the header)");
  const std::string& name = fields[static_cast<std::size_t>(c.column_ball)];
  if (name.empty()) fail(c, "ball", "is empty; allowed: the ball's name");
  const double t = number(c, fields[static_cast<std::size_t>(c.column_t)], "t");
  const double x = number(c, fields[static_cast<std::size_t>(c.column_x)], "x");
  const double y = number(c, fields[static_cast<std::size_t>(c.column_y)], "y");
  check_range(c, "t", t, -kMaxRecordSeconds, kMaxRecordSeconds, "s", "sample time");
  check_range(c, "x", x, -kMaxLayoutNudge, c.table.length + kMaxLayoutNudge, "m", "position along the table");
  check_range(c, "y", y, -kMaxLayoutNudge, c.table.width + kMaxLayoutNudge, "m", "position across the table");
  auto [it, added] = c.index.emplace(name, c.balls.size());
  if (added) {
    if (c.balls.size() >= kMaxTrackedBalls)
      fail(c, "ball", quote_input(name) + " is one ball too many; allowed: at most " + std::to_string(kMaxTrackedBalls));
    c.balls.push_back(TrackedBall{name, {}, {}, {}});
  }
  TrackedBall& b = c.balls[it->second];
  if (!b.t.empty() && !(t > b.t.back()))
    fail(c, "t", format_number(t) + " is not after ball " + quote_input(name) + "'s previous sample " + format_number(b.t.back()) +
                     " (each ball's sample times must increase)");
  if (b.t.size() >= kMaxTrackedSamples)
    fail(c, "", "ball " + quote_input(name) + " has too many samples; allowed: at most " + std::to_string(kMaxTrackedSamples));
  b.t.push_back(t), b.x.push_back(x), b.y.push_back(y);
}

// The ball whose record first moves kMoveThreshold from its first sample.
std::string first_to_move(const std::vector<TrackedBall>& balls) {
  std::string best;
  double earliest = std::numeric_limits<double>::infinity();
  for (const TrackedBall& b : balls)
    for (std::size_t i = 1; i < b.t.size(); ++i)
      if (std::hypot(b.x[i] - b.x[0], b.y[i] - b.y[0]) >= kMoveThreshold) {
        if (b.t[i] < earliest) earliest = b.t[i], best = b.name;
        break;
      }
  return best;
}

std::string shot_id(const std::string& file_name) {
  std::string id = file_name.substr(file_name.find_last_of("/\\") == std::string::npos ? 0 : file_name.find_last_of("/\\") + 1);
  if (id.size() > 4 && (id.compare(id.size() - 4, 4, ".csv") == 0 || id.compare(id.size() - 4, 4, ".CSV") == 0))
    id.resize(id.size() - 4);
  return id;
}

}  // namespace

TrackedShot tracked_shot_from_csv(const CsvShotFile& file, const Table& table, const std::string& cue_ball) {
  CsvContext c{file, table, -1, -1, -1, -1, {}, {}, {}, 0};
  if (file.text.size() > kMaxTrackedShotCsvBytes)
    fail(c, "", "the file is " + std::to_string(file.text.size()) + " bytes; allowed: at most " +
                    std::to_string(kMaxTrackedShotCsvBytes));
  std::size_t start = 0;
  while (start <= file.text.size()) {
    std::size_t end = file.text.find('\n', start);
    if (end == std::string::npos) end = file.text.size();
    const std::string_view line(file.text.data() + start, end - start);
    ++c.row;
    start = end + 1;
    const std::string content = trim(line);
    if (content.empty() || content[0] == '#') continue;
    const std::vector<std::string> fields = split(line);
    if (c.header.empty())
      read_header(c, fields);
    else
      read_row(c, fields);
  }
  ++c.row;
  if (c.header.empty()) fail(c, "", "the file has no header row (ball, t, x, y)");
  if (c.balls.empty()) fail(c, "", "the file has no samples");
  TrackedShot shot;
  shot.id = shot_id(file.name);
  shot.balls = std::move(c.balls);
  shot.cue_ball = cue_ball.empty() ? first_to_move(shot.balls) : cue_ball;
  if (shot.cue_ball.empty()) fail(c, "", "no ball moves 5 mm from its first sample (which was struck?)");
  const std::string name = quote_input(file.name, kMaxEchoedPathChars);
  try {
    validate_tracked_shot(shot, table, "shot");
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(file.name, name + ": " + e.what());
  }
  return shot;
}

TrackedShots tracked_shots_from_csv(const std::vector<CsvShotFile>& files, const std::string& table_name,
                                    const std::string& cue_ball) {
  TrackedShots out;
  out.table_name = table_name;
  try {
    out.table = preset_table(table_name);
  } catch (const InvalidArgument&) {
    throw InvalidArgument("table", "table = " + quote_input(table_name) + " is not a preset; allowed: pool_9ft, snooker_12ft, carom_10ft");
  }
  if (files.empty()) throw InvalidArgument("shots", "no CSV files (one a shot)");
  if (files.size() > kMaxTrackedShots)
    throw InvalidArgument("shots", std::to_string(files.size()) + " CSV files; allowed: at most " + std::to_string(kMaxTrackedShots));
  for (const CsvShotFile& f : files) out.shots.push_back(tracked_shot_from_csv(f, out.table, cue_ball));
  return out;
}

}  // namespace cueball
