// Pieces shared by the CLI's subcommands: physical-parameter flags and the
// checks that turn bad input into one clear line and exit status 2.
#pragma once

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

#include "cueball/physics/cue_strike.hpp"
#include "cueball/core/parameters.hpp"
#include "output.hpp"

namespace cueball::cli {

/// Bad input from the command line: printed as one line, exit status 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Flags common to every subcommand: --preset and one override per parameter.
/// The preset defaults to pool, as the default table, rack and scenario and
/// the Python module's params= (README "Units and defaults"); only the
/// commands that redraw the cushion paper's figures (cushion-sweep, figures)
/// default to its snooker ball.
struct ParameterFlags {
  std::string preset = "pool";
  std::optional<double> mass, radius, mu_s, mu_r, mu_sp, g;
  bool json = false;
};

void add_parameter_flags(CLI::App& app, ParameterFlags& flags);

/// The preset with the overrides applied, validated (throws UsageError
/// naming the flag).
Parameters resolve_parameters(const ParameterFlags& flags);

/// Throws UsageError "FLAG = VALUE is outside the allowed range [lo, hi] (meaning)"
/// unless value is finite and within [lo, hi].
void check_flag(const char* flag, double value, double lo, double hi, const char* meaning);

/// The --sigma-* flags of `batch` and `plan-shot`: standard deviations of
/// the execution noise in the units of the scenario's "noise" (m/s, degrees,
/// ball radii); each one given replaces that sigma of a base noise.
struct SigmaFlags {
  std::optional<double> speed, aim, elevation, side, height;
  bool any() const { return speed || aim || elevation || side || height; }
};

void add_sigma_flags(CLI::App& app, SigmaFlags& flags);

/// `noise` with each given flag in its place (radians, metres; `radius` the
/// ball radius, m); throws UsageError naming the flag, the value and the
/// allowed range (the scenario's "noise" ranges).
CueStrikeNoise with_sigma_flags(const SigmaFlags& flags, CueStrikeNoise noise, double radius);

/// Longest result file `view` reads, bytes (256 MiB).
inline constexpr std::size_t kMaxResultFileBytes = std::size_t{256} << 20;
/// Longest measurement file `fit-cushion` reads, bytes (16 MiB).
inline constexpr std::size_t kMaxDataFileBytes = std::size_t{16} << 20;

/// The whole file; throws UsageError naming the (quoted) path when it cannot
/// be opened or read, is a directory or holds more than max_bytes.
std::string read_text_file(const std::string& path, const std::string& what, std::size_t max_bytes);
/// Writes (replaces) the file; throws UsageError "FLAG PATH: cannot write WHAT".
void write_text_file(const std::string& path, std::string_view text, const std::string& flag, const std::string& what);

/// v with `decimals` digits after the point ("%.*f"), -0 shown as 0.
std::string fixed(double v, int decimals = 3);

/// The CLI flag that sets a library field ("mu_s" -> "--mu-s").
std::string flag_for_field(const std::string& field);

/// The flag an InvalidArgument of the library stands for ("e_e" -> "--e",
/// "sample_rate" -> "--sample"), or "" when no flag sets that field.
std::string flag_of_library_field(const std::string& field);

/// A subcommand: registers its flags and returns what to run when chosen.
using Command = std::function<void(std::ostream& out, std::ostream& err)>;
Command add_roll_command(CLI::App& app);
Command add_plan_command(CLI::App& app);
Command add_cushion_command(CLI::App& app);
Command add_cushion_sweep_command(CLI::App& app);
Command add_figures_command(CLI::App& app);
Command add_fit_cushion_command(CLI::App& app);
Command add_simulate_command(CLI::App& app);
Command add_batch_command(CLI::App& app);
Command add_many_command(CLI::App& app);
Command add_plan_shot_command(CLI::App& app);
Command add_view_command(CLI::App& app);
Command add_calibrate_command(CLI::App& app);

/// Prints the report, then its warnings on stderr.
void emit(const Report& report, bool json, std::ostream& out, std::ostream& err);

}  // namespace cueball::cli
