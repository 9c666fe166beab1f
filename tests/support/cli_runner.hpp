// Runs the cueball CLI in-process and captures its exit status and output.
#pragma once

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"

namespace cueball::test {

struct CliRun {
  int status;
  std::string out;
  std::string err;
};

inline CliRun run_cli(std::vector<std::string> args) {
  args.insert(args.begin(), "cueball");
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  std::ostringstream out, err;
  const int status = cli::run(static_cast<int>(argv.size()), argv.data(), out, err);
  return {status, out.str(), err.str()};
}

inline int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += (c == '\n');
  return n;
}

/// A bad invocation: status 2, exactly one line on stderr naming `what`,
/// nothing on stdout.
inline void expect_usage_error(const std::vector<std::string>& args, const std::string& what) {
  const CliRun r = run_cli(args);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(what), std::string::npos) << "stderr should name " << what << ": " << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

// Runs `batch ... --json` (expecting success) and parses it.
inline nlohmann::json batch_json(const std::vector<std::string>& args) {
  std::vector<std::string> all{"batch"};
  all.insert(all.end(), args.begin(), args.end());
  all.push_back("--json");
  const CliRun r = run_cli(all);
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

}  // namespace cueball::test
