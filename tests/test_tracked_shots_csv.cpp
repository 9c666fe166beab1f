// Tracked shots read from CSV, one file a shot (io/tracked_shots_csv.cpp):
// a synthetic shot written as CSV (rows of the balls interleaved, comments,
// CRLF line ends, quoted names, columns in another order) reads back sample
// for sample; the cue ball is the one named or the first to move; and every
// error names the file, the row and the column.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "cueball/core/errors.hpp"
#include "cueball/io/tracked_shots_csv.hpp"
#include "synthetic_tracks.hpp"

namespace cueball {
namespace {

TrackedShot shot() {
  return test::synthetic_shot(test::carom_model(), test::carom_layout({0.7, 0.5}, {2.1, 0.35}, {1.9, 1.05}),
                              {3.2, 25.0, 4.0, 0.2, 0.15}, 0.3, 9);
}

// The shot's samples in time order across the balls, columns t, "ball", y, x.
std::string as_csv(const TrackedShot& s) {
  struct Row {
    double t;
    std::string ball;
    double x, y;
  };
  std::vector<Row> rows;
  for (const TrackedBall& b : s.balls)
    for (std::size_t k = 0; k < b.t.size(); ++k) rows.push_back({b.t[k], b.name, b.x[k], b.y[k]});
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.t < b.t; });
  std::ostringstream out;
  out.precision(17);
  out << "# exported by a tracker\r\n t , ball , y , x \r\n\r\n";
  for (const Row& r : rows) out << r.t << ",\"" << r.ball << "\"," << r.y << "," << r.x << "\r\n";
  return out.str();
}

const Table& carom() {
  static const Table t = preset_table("carom_10ft");
  return t;
}

TEST(TrackedShotsCsv, ReadsAShotBackSampleForSample) {
  const TrackedShot s = shot();
  const TrackedShot r = tracked_shot_from_csv({"tracks/shot-17.csv", as_csv(s)}, carom(), "");
  EXPECT_EQ(r.id, "shot-17");
  EXPECT_EQ(r.cue_ball, "white");  // the first to move
  ASSERT_EQ(r.balls.size(), s.balls.size());
  for (std::size_t j = 0; j < s.balls.size(); ++j) {
    EXPECT_EQ(r.balls[j].name, s.balls[j].name);
    EXPECT_EQ(r.balls[j].t, s.balls[j].t);
    EXPECT_EQ(r.balls[j].x, s.balls[j].x);
    EXPECT_EQ(r.balls[j].y, s.balls[j].y);
  }
  EXPECT_EQ(tracked_shot_from_csv({"a.csv", as_csv(s)}, carom(), "red").cue_ball, "red");
  const TrackedShots set = tracked_shots_from_csv({{"a.csv", as_csv(s)}, {"b.CSV", as_csv(s)}}, "carom_10ft", "");
  ASSERT_EQ(set.shots.size(), 2u);
  EXPECT_EQ(set.shots[1].id, "b");
  EXPECT_EQ(set.table.length, carom().length);
}

// The message of the InvalidArgument a file throws.
std::string error_of(const std::string& text, const std::string& cue_ball = "") {
  try {
    (void)tracked_shot_from_csv({"dir/s.csv", text}, carom(), cue_ball);
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.field(), "dir/s.csv");
    return e.what();
  }
  ADD_FAILURE() << "no error for\n" << text;
  return {};
}

TEST(TrackedShotsCsv, ErrorsNameTheFileTheRowAndTheColumn) {
  const std::string head = "ball,t,x,y\nwhite,0,0.7,0.5\nwhite,0.02,0.75,0.5\n";
  EXPECT_EQ(error_of(head + "red,0.1,abc,0.4\n"), "\"dir/s.csv\": row 4, column x: \"abc\" is not a finite number");
  EXPECT_EQ(error_of(head + "red,0.1,,0.4\n"), "\"dir/s.csv\": row 4, column x: is empty; allowed: a number");
  EXPECT_EQ(error_of(head + "red,0.1,0.4,nan\n"), "\"dir/s.csv\": row 4, column y: \"nan\" is not a finite number");
  EXPECT_EQ(error_of(head + "red,0.1,4.2,0.4\n"),
            "\"dir/s.csv\": row 4, column x: 4.2 is outside [-0.02, 2.86] m (position along the table)");
  EXPECT_EQ(error_of(head + "white,0.01,0.8,0.5\n"),
            "\"dir/s.csv\": row 4, column t: 0.01 is not after ball \"white\"'s previous sample 0.02 (each ball's sample times must increase)");
  EXPECT_EQ(error_of(head + "red,0.1,0.4\n"), "\"dir/s.csv\": row 4: has 3 fields; allowed: 4 (as the header)");
  EXPECT_EQ(error_of("ball,t,x,y,speed\n"),
            "\"dir/s.csv\": row 1, column \"speed\": is not a known column; allowed: ball, t, x, y (a header row naming them comes first)");
  EXPECT_EQ(error_of("# c\nball,t,x\n"), "\"dir/s.csv\": row 2, column y: is missing from the header (the columns are ball, t, x, y, in any order)");
  EXPECT_EQ(error_of("ball,t,x,x\n"), "\"dir/s.csv\": row 1, column x: appears twice in the header");
  EXPECT_NE(error_of("").find("no header row"), std::string::npos);
  EXPECT_NE(error_of("ball,t,x,y\nwhite,0,0.7,0.5\n").find("no ball moves"), std::string::npos);
  // What validate_tracked_shot finds, prefixed by the file.
  EXPECT_NE(error_of(head, "blue").find("\"dir/s.csv\": "), std::string::npos);
  EXPECT_THROW(tracked_shots_from_csv({{"a.csv", head}}, "carom_9ft", ""), InvalidArgument);
  EXPECT_THROW(tracked_shots_from_csv({}, "carom_10ft", ""), InvalidArgument);
}

}  // namespace
}  // namespace cueball
