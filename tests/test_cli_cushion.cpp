// Tests of the cushion subcommands of the CLI (cli/command_cushion.cpp):
// cushion, cushion-sweep and figures.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "cueball/models/cushion/impact.hpp"

namespace cueball {
namespace {

using namespace test;  // the CLI tests' helpers (tests/support/)

constexpr double kDeg = 3.14159265358979323846 / 180.0;

std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::istringstream cols(line);
    std::string cell;
    while (std::getline(cols, cell, ',')) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

TEST(CliCushion, JsonMatchesTheLibraryAndHasTheDocumentedKeys) {
  const CliRun r = run_cli({"cushion", "--v0", "1.2", "--alpha", "35", "--topspin-k", "0.5", "--sidespin-k", "-1",
                            "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const Parameters p = pool_parameters();
  const PaperIncidence in{1.2, 35 * kDeg, 0.5 * 1.2 / p.ball.radius, -1.2 / p.ball.radius};
  const CushionImpactResult expected = cushion_impact(incoming_ball(in), p, cushion_mathavan2010_paper_fit(p.ball));
  EXPECT_DOUBLE_EQ(j.at("speed").get<double>(), expected.rebound_speed);
  EXPECT_NEAR(j.at("angle").get<double>(), expected.rebound_angle / kDeg, 1e-12);
  EXPECT_EQ(j.at("v").size(), 2u);
  EXPECT_EQ(j.at("w").size(), 3u);
  EXPECT_DOUBLE_EQ(j.at("v")[1].get<double>(), expected.velocity.y);
  EXPECT_DOUBLE_EQ(j.at("w")[2].get<double>(), expected.angular_velocity.z);
  EXPECT_DOUBLE_EQ(j.at("impulse_compression").get<double>(), expected.compression_impulse);
  EXPECT_DOUBLE_EQ(j.at("impulse_total").get<double>(), expected.total_impulse);
  EXPECT_DOUBLE_EQ(j.at("work_compression").get<double>(), expected.compression_work);
  EXPECT_FALSE(j.contains("warnings"));
}

TEST(CliCushion, ConstantsDefaultToThePaperFitForBothSolvers) {
  const auto cushion_of = [](const std::vector<std::string>& extra) {
    std::vector<std::string> args{"cushion", "--v0", "1", "--alpha", "60", "--json"};
    args.insert(args.end(), extra.begin(), extra.end());
    const CliRun r = run_cli(args);
    EXPECT_EQ(r.status, 0) << r.err;
    return nlohmann::json::parse(r.out).at("cushion");
  };
  for (const char* solver : {"paper", "exact"}) {
    EXPECT_EQ(cushion_of({"--solver", solver}).at("e").get<double>(), 0.98);
    EXPECT_EQ(cushion_of({"--solver", solver}).at("mu_w").get<double>(), 0.14);
  }
  EXPECT_EQ(cushion_of({"--constants", "translator-fit"}).at("e").get<double>(), 0.986);
  EXPECT_EQ(cushion_of({"--constants", "translator-fit"}).at("mu_w").get<double>(), 0.2093);
  const CliRun overridden = run_cli({"cushion", "--v0", "1", "--alpha", "60", "--e", "0.9", "--mu-w", "0.1", "--json"});
  ASSERT_EQ(overridden.status, 0);
  EXPECT_EQ(nlohmann::json::parse(overridden.out).at("cushion").at("e").get<double>(), 0.9);
}

TEST(CliCushion, SpinInRadiansPerSecondEqualsTheKForm) {
  const double radius = pool_parameters().ball.radius;
  const std::string w = std::to_string(1.5 * 0.8 / radius);
  const CliRun a = run_cli({"cushion", "--v0", "0.8", "--alpha", "50", "--topspin", w, "--json"});
  const CliRun b = run_cli({"cushion", "--v0", "0.8", "--alpha", "50", "--topspin-k", "1.5", "--json"});
  ASSERT_EQ(a.status, 0);
  ASSERT_EQ(b.status, 0);
  EXPECT_NEAR(nlohmann::json::parse(a.out).at("speed").get<double>(),
              nlohmann::json::parse(b.out).at("speed").get<double>(), 1e-6);
}

TEST(CliCushion, HistoryRunsOverIncreasingNormalImpulse) {
  const CliRun r = run_cli({"cushion", "--v0", "2", "--alpha", "45", "--topspin-k", "1.5", "--sidespin-k", "2",
                            "--history", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& h = j.at("history");
  ASSERT_GT(h.size(), 3u);
  for (std::size_t i = 1; i < h.size(); ++i) EXPECT_GE(h[i].at("P").get<double>(), h[i - 1].at("P").get<double>());
  EXPECT_NEAR(h.back().at("P").get<double>(), j.at("impulse_total").get<double>(), 1e-12);
}

TEST(CliCushion, FastImpactWarnsButSucceeds) {
  const CliRun r = run_cli({"cushion", "--v0", "3", "--alpha", "80", "--json"});
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.err.find("warning"), std::string::npos);
  EXPECT_NE(r.err.find("2.5"), std::string::npos);
  EXPECT_EQ(nlohmann::json::parse(r.out).at("warnings").size(), 1u);
}

TEST(CliCushion, BadInputExitsWithStatusTwoNamingTheFlag) {
  expect_usage_error({"cushion", "--v0", "1", "--alpha", "0"}, "--alpha");
  expect_usage_error({"cushion", "--v0", "1", "--alpha", "95"}, "--alpha");
  expect_usage_error({"cushion", "--v0", "1", "--alpha", "nan"}, "--alpha");
  expect_usage_error({"cushion", "--v0", "0", "--alpha", "30"}, "--v0");
  expect_usage_error({"cushion", "--v0", "-1", "--alpha", "30"}, "--v0");
  expect_usage_error({"cushion", "--v0", "1", "--alpha", "30", "--e", "1.5"}, "--e");
  expect_usage_error({"cushion", "--v0", "1", "--alpha", "30", "--e", "0"}, "--e");
  expect_usage_error({"cushion", "--v0", "1", "--alpha", "30", "--mu-w", "-0.1"}, "--mu-w");
  expect_usage_error({"cushion", "--v0", "1", "--alpha", "30", "--steps", "0"}, "--steps");
  // --steps belongs to the paper solver: with the exact one it would be ignored.
  expect_usage_error({"cushion", "--v0", "1", "--alpha", "30", "--steps", "100"}, "--steps");
  expect_usage_error({"cushion-sweep", "--family", "fig8", "--steps", "100"}, "--steps");
  EXPECT_EQ(run_cli({"cushion", "--v0", "1", "--alpha", "30", "--solver", "paper", "--steps", "100"}).status, 0);
  expect_usage_error({"cushion", "--v0", "1", "--alpha", "30", "--topspin", "3", "--topspin-k", "1"}, "--topspin");
  expect_usage_error({"cushion", "--v0", "1", "--alpha", "30", "--solver", "rk45"}, "--solver");
  expect_usage_error({"cushion-sweep", "--family", "fig99"}, "--family");
}

TEST(CliCushion, Fig8SweepHasOneAngleForEverySpeed) {
  const CliRun r = run_cli({"cushion-sweep", "--family", "fig8"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = parse_csv(r.out);
  ASSERT_EQ(rows.size(), 1u + 90u * 6u);
  EXPECT_EQ(rows[0][7], "angle_deg");
  // Rolling without sidespin: the rebound angle does not depend on V0 (Fig 8).
  std::map<std::string, std::vector<double>> angles_by_alpha;
  for (std::size_t i = 1; i < rows.size(); ++i) angles_by_alpha[rows[i][3]].push_back(std::stod(rows[i][7]));
  for (const auto& [alpha, angles] : angles_by_alpha) {
    for (double a : angles) EXPECT_NEAR(a, angles.front(), 1e-6) << "alpha " << alpha;
  }
}

TEST(CliCushion, SweepsRedrawThePapersFiguresWithItsSnookerBall) {
  // Every other command defaults to the pool preset; the paper's figures keep the paper's ball.
  const CliRun by_default = run_cli({"cushion-sweep", "--family", "fig9"});
  const CliRun snooker = run_cli({"cushion-sweep", "--family", "fig9", "--preset", "snooker"});
  const CliRun pool = run_cli({"cushion-sweep", "--family", "fig9", "--preset", "pool"});
  ASSERT_EQ(by_default.status, 0) << by_default.err;
  EXPECT_EQ(by_default.out, snooker.out);
  EXPECT_NE(by_default.out, pool.out);
}

TEST(CliCushion, GridSweepCoversTheDocumentedGrid) {
  const CliRun r = run_cli({"cushion-sweep", "--family", "grid"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(parse_csv(r.out).size(), 1u + 90u * 7u * 9u);
}

TEST(CliCushion, Fig12SweepIsTheImpactHistory) {
  const CliRun r = run_cli({"cushion-sweep", "--family", "fig12", "--solver", "paper"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = parse_csv(r.out);
  EXPECT_EQ(rows[0][0], "P");
  EXPECT_GT(rows.size(), 1000u) << "one row per Euler step";
}

// Issue 24: --json was listed by cushion-sweep and figures, and ignored.
TEST(CliCushion, SweepJsonHoldsTheCsvRowsAsObjects) {
  const CliRun csv = run_cli({"cushion-sweep", "--family", "fig9"});
  const CliRun r = run_cli({"cushion-sweep", "--family", "fig9", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["family"], "fig9");
  EXPECT_EQ(j["model"], "mathavan_2010");
  EXPECT_EQ(j["solver"], "exact");
  EXPECT_EQ(j["preset"], "snooker");
  const auto rows = parse_csv(csv.out);
  ASSERT_EQ(j["rows"].size() + 1, rows.size());
  for (std::size_t i = 0; i < j["rows"].size(); i += 97) {
    const nlohmann::json& row = j["rows"][i];
    for (std::size_t c = 2; c < 8; ++c)  // the CSV's columns v0 ... angle_deg, printed to fewer digits
      EXPECT_NEAR(row[rows[0][c]].get<double>(), std::stod(rows[i + 1][c]), 1e-5 * (1 + std::abs(std::stod(rows[i + 1][c]))))
          << rows[0][c] << " row " << i;
  }
  const nlohmann::json other = nlohmann::json::parse(run_cli({"cushion-sweep", "--family", "fig8", "--model", "han_2005", "--json"}).out);
  EXPECT_EQ(other["model"], "han_2005");
  EXPECT_FALSE(other.contains("solver"));
  EXPECT_EQ(other["rows"].size(), 90u * 6u);
  const CliRun fig12 = run_cli({"cushion-sweep", "--family", "fig12", "--solver", "paper", "--steps", "200", "--json"});
  ASSERT_EQ(fig12.status, 0) << fig12.err;
  const nlohmann::json history = nlohmann::json::parse(fig12.out)["history"];
  ASSERT_GT(history.size(), 100u);
  EXPECT_TRUE(history[0].contains("P"));
  EXPECT_TRUE(history[0].contains("phi_prime"));
}

TEST(CliCushion, FiguresJsonListsTheImages) {
  if (!std::filesystem::exists("/usr/bin/gnuplot") && !std::filesystem::exists("/usr/local/bin/gnuplot"))
    GTEST_SKIP() << "gnuplot is not installed";
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "cueball_test_figures_json";
  std::filesystem::remove_all(dir);
  const CliRun r = run_cli({"figures", "--out", dir.string(), "--format", "svg", "--steps", "50", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["out"], dir.string());
  EXPECT_EQ(j["format"], "svg");
  ASSERT_EQ(j["files"].size(), 5u);
  for (const auto& file : j["files"]) EXPECT_TRUE(std::filesystem::exists(file.get<std::string>())) << file;
  std::filesystem::remove_all(dir);
}

TEST(CliCushion, FiguresWritesThePapersPlotsAndTheModels) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "cueball_test_figures";
  std::filesystem::remove_all(dir);
  const CliRun r = run_cli({"figures", "--out", dir.string(), "--format", "svg", "--steps", "500"});
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* name : {"fig8", "fig9", "fig10", "fig12", "models"}) {
    const std::filesystem::path svg = dir / (std::string(name) + ".svg");
    ASSERT_TRUE(std::filesystem::exists(svg)) << svg;
    std::ifstream in(svg);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("<svg"), std::string::npos) << name;
    EXPECT_NE(text.find("<path"), std::string::npos) << name << " has no curves";
    EXPECT_NE(r.out.find(svg.string()), std::string::npos);
  }
  // The models' figure has a curve of each model with and without side spin.
  std::ifstream data(dir / "models.dat");
  const std::string text((std::istreambuf_iterator<char>(data)), std::istreambuf_iterator<char>());
  for (const char* title : {"# mathavan_2010\n", "# mathavan_2010/side=1\n", "# han_2005\n", "# han_2005/side=1\n", "# stronge_compliant\n"})
    EXPECT_NE(text.find(title), std::string::npos) << title;
  std::filesystem::remove_all(dir);
}

TEST(CliCushion, ModelFlagChoosesTheCushionModel) {
  const CliRun han = run_cli({"cushion", "--model", "han_2005", "--v0", "1", "--alpha", "90", "--json"});
  ASSERT_EQ(han.status, 0) << han.err;
  const nlohmann::json j = nlohmann::json::parse(han.out);
  // Rolling head-on with e = 0.85, mu = 0.2: 0.689644 m/s back (test_cushion_han_2005).
  EXPECT_NEAR(j.at("speed").get<double>(), 0.689644, 1e-6);
  EXPECT_NEAR(j.at("angle").get<double>(), 90.0, 1e-9);
  EXPECT_EQ(j.at("cushion").at("model"), "han_2005");
  EXPECT_EQ(j.at("cushion").at("e").get<double>(), 0.85);
  const CliRun custom = run_cli({"cushion", "--model", "han_2005", "--v0", "1", "--alpha", "90", "--e", "0.5", "--mu-w", "0", "--json"});
  ASSERT_EQ(custom.status, 0) << custom.err;
  EXPECT_NEAR(nlohmann::json::parse(custom.out).at("speed").get<double>(), 1.5 * 0.84 - 1.0, 1e-12);
  const CliRun mathavan = run_cli({"cushion", "--v0", "1", "--alpha", "90", "--json"});
  EXPECT_EQ(nlohmann::json::parse(mathavan.out).at("cushion").at("model"), "mathavan_2010");

  const CliRun stronge = run_cli({"cushion", "--model", "stronge_compliant", "--frequency-ratio", "2", "--v0", "1",
                                  "--alpha", "90", "--topspin-k", "0", "--json"});
  ASSERT_EQ(stronge.status, 0) << stronge.err;
  // Head-on without spin at the equator: no slip, so the ball leaves at e V0.
  EXPECT_NEAR(nlohmann::json::parse(stronge.out).at("speed").get<double>(), 0.85, 1e-12);
  EXPECT_EQ(nlohmann::json::parse(stronge.out).at("cushion").at("omega").get<double>(), 2.0);
  EXPECT_EQ(run_cli({"cushion", "--frequency-ratio", "2", "--model", "han_2005", "--v0", "1", "--alpha", "45"}).status, 2);
  // cushion-sweep --model: the same impacts as cushion --model, as CSV rows.
  const CliRun sweep = run_cli({"cushion-sweep", "--family", "fig8", "--model", "han_2005", "--preset", "pool"});
  ASSERT_EQ(sweep.status, 0) << sweep.err;
  const std::string row = "\nfig8,han_2005,1,90,1,0,";  // V0 = 1, head-on, rolling
  const std::size_t at = sweep.out.find(row);
  ASSERT_NE(at, std::string::npos) << sweep.out.substr(0, 300);
  EXPECT_NEAR(std::stod(sweep.out.substr(at + row.size())), 0.689644, 1e-6);
  EXPECT_EQ(run_cli({"cushion-sweep", "--family", "fig12", "--model", "han_2005"}).status, 2);
  EXPECT_EQ(run_cli({"cushion-sweep", "--family", "fig9", "--model", "han_2005", "--solver", "paper"}).status, 2);
  const CliRun unknown = run_cli({"cushion", "--model", "stronge", "--v0", "1", "--alpha", "45"});
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.err.find("--model = \"stronge\" is not known; allowed: mathavan_2010, han_2005, stronge_compliant"), std::string::npos)
      << unknown.err;
  const CliRun solver = run_cli({"cushion", "--model", "han_2005", "--v0", "1", "--alpha", "45", "--solver", "paper"});
  EXPECT_EQ(solver.status, 2);
  EXPECT_NE(solver.err.find("apply to --model mathavan_2010 only"), std::string::npos) << solver.err;
  const CliRun mu = run_cli({"cushion", "--model", "han_2005", "--v0", "1", "--alpha", "45", "--mu-w", "3"});
  EXPECT_EQ(mu.status, 2);
  EXPECT_NE(mu.err.find("--mu-w"), std::string::npos) << mu.err;
}

}  // namespace
}  // namespace cueball

namespace cueball {
namespace {

// Synthetic measurements from known constants, written as the CSV the
// command reads.
std::filesystem::path write_fit_data(const std::string& name, bool oblique, double e, double mu_w) {
  const Parameters p = pool_parameters();
  CushionParameters c = cushion_mathavan2010_paper_fit(p.ball);
  c.restitution = e;
  c.friction = mu_w;
  const std::filesystem::path path = std::filesystem::temp_directory_path() / name;
  std::ofstream csv(path);
  csv << "# synthetic impacts\n";
  for (double v0 : {0.4, 0.8, 1.2, 1.6}) {
    const PaperIncidence head_on{v0, 90 * kDeg, v0 / p.ball.radius, 0.0};
    csv << v0 << "," << cushion_impact(incoming_ball(head_on), p, c).rebound_speed << "\n";
    if (oblique) {
      for (double alpha : {20.0, 45.0, 70.0}) {
        for (double side : {-1.5, 1.5}) {
          const PaperIncidence in{v0, alpha * kDeg, 0.0, side * v0 / p.ball.radius};
          const CushionImpactResult r = cushion_impact(incoming_ball(in), p, c);
          csv << v0 << "," << alpha << ",0," << side << "," << r.rebound_speed << "," << r.rebound_angle / kDeg << "\n";
        }
      }
    }
  }
  return path;
}

TEST(CliCushion, FitRecoversKnownConstantsFromObliqueData) {
  const auto path = write_fit_data("cueball_fit_oblique.csv", true, 0.93, 0.2);
  const CliRun r = run_cli({"fit-cushion", path.string(), "--grid-step", "0.05", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j.at("e").get<double>(), 0.93, 1e-3);
  EXPECT_NEAR(j.at("mu_w").get<double>(), 0.2, 1e-3);
  EXPECT_EQ(j.at("oblique_points").get<int>(), 24);
  EXPECT_FALSE(j.contains("warnings")) << r.err;
  std::filesystem::remove(path);
}

TEST(CliCushion, FitWarnsThatHeadOnDataBarelySeparateTheConstants) {
  const auto path = write_fit_data("cueball_fit_head_on.csv", false, 0.93, 0.2);
  const CliRun r = run_cli({"fit-cushion", path.string(), "--grid-step", "0.05", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("barely separate"), std::string::npos) << r.err;
  std::filesystem::remove(path);
}

TEST(CliCushion, FitRejectsBadDataNamingTheLine) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "cueball_fit_bad.csv";
  {
    std::ofstream csv(path);
    csv << "v0,v_out\n1.0,0.8\n1.2,0.9,3\n";
  }
  expect_usage_error({"fit-cushion", path.string()}, ":3: expected 2 numbers");
  {
    std::ofstream csv(path);
    csv << "1.0,0.8\n-1.0,0.5\n";
  }
  expect_usage_error({"fit-cushion", path.string()}, ":2: v0");
  expect_usage_error({"fit-cushion", "/nonexistent/impacts.csv"}, "cannot open");
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace cueball
