// simulate_many: N different shots of one scenario in one call
// (batch.hpp), their outcomes as NumPy arrays that view the library's own
// struct-of-arrays result (no copy per element).
#include <pybind11/numpy.h>

#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "cueball/simulation/batch.hpp"
#include "cueball/core/errors.hpp"

namespace cueball_python {

namespace {

using Index = py::ssize_t;

// A C-contiguous float64 copy of `x` with the given trailing shape, or an
// InvalidArgument naming `field`.
py::array_t<double> float_array(const py::object& x, const char* field, std::vector<Index> trailing,
                                const std::string& what) {
  py::array_t<double, py::array::c_style | py::array::forcecast> a;
  try {
    a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(x);
  } catch (const py::error_already_set&) {
  }
  bool ok = a && a.ndim() == static_cast<Index>(trailing.size() + 1);
  for (std::size_t k = 0; ok && k < trailing.size(); ++k) ok = trailing[k] < 0 || a.shape(static_cast<Index>(k + 1)) == trailing[k];
  if (!ok) {
    std::string shape = "(";
    if (a)
      for (Index k = 0; k < a.ndim(); ++k) shape += (k ? ", " : "") + std::to_string(a.shape(k));
    throw cueball::InvalidArgument(field, std::string(field) + ": " + what + (a ? "; got shape " + shape + ")" : "; got no array of numbers"));
  }
  return a;
}

// A read-only array viewing `data` (owned by `owner`).
template <class T>
py::array view(const std::vector<T>& data, std::vector<Index> shape, const py::object& owner, const char* dtype = nullptr) {
  const py::dtype type = dtype ? py::dtype(dtype) : py::dtype::of<T>();
  std::vector<Index> strides(shape.size());
  Index stride = static_cast<Index>(sizeof(T));
  for (std::size_t k = shape.size(); k-- > 0;) {
    strides[k] = stride;
    stride *= shape[k];
  }
  py::array a(type, shape, strides, data.data(), owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

// The (N, n_balls) on-table flags of present=, as 0 / 1 bytes; InvalidArgument
// naming "present" when it is not a boolean array of that shape.
std::vector<std::uint8_t> present_flags(const py::object& present, Index shots) {
  py::array a;
  try {
    a = py::array::ensure(present);
  } catch (const py::error_already_set&) {
  }
  if (!a || a.dtype().kind() != 'b' || a.ndim() != 2 || a.shape(0) != shots) {
    std::string got = "no array";
    if (a) {
      got = "a " + py::str(a.dtype()).cast<std::string>() + " array of shape (";
      for (Index k = 0; k < a.ndim(); ++k) got += (k ? ", " : "") + std::to_string(a.shape(k));
      got += ")";
    }
    throw cueball::InvalidArgument("present", "present: an (N, n_balls) bool array (N = " + std::to_string(shots) +
                                                  " rows of actions), True where the ball is on the table; got " + got);
  }
  const py::array_t<bool, py::array::c_style | py::array::forcecast> b(a);
  std::vector<std::uint8_t> flags(static_cast<std::size_t>(b.size()));
  for (std::size_t k = 0; k < flags.size(); ++k) flags[k] = b.data()[k] ? 1 : 0;
  return flags;
}

}  // namespace

void bind_simulate_many(py::module_& m) {
  m.def(
      "simulate_many",
      [](const py::object& scenario, const py::object& actions, const py::object& layouts, long long threads,
         std::uint64_t seed, const py::object& noise, long long first_shot, const py::object& present) {
        const py::array_t<double> a =
            float_array(actions, "actions", {5}, "an (N, 5) array of cue speed (m/s), aim (deg), elevation (deg), side and height (ball radii)");
        std::vector<cueball::ShotAction> shots(static_cast<std::size_t>(a.shape(0)));
        static_assert(sizeof(cueball::ShotAction) == 5 * sizeof(double));
        if (!shots.empty()) std::memcpy(static_cast<void*>(shots.data()), a.data(), shots.size() * sizeof(cueball::ShotAction));
        std::vector<double> positions;
        if (!layouts.is_none()) {
          const py::array_t<double> l = float_array(layouts, "layouts", {-1, 2}, "an (N, n_balls, 2) array of every scenario ball's position (m)");
          positions.assign(l.data(), l.data() + l.size());
        }
        std::vector<std::uint8_t> on_table;
        if (!present.is_none()) on_table = present_flags(present, a.shape(0));
        if (threads < 1 || threads > cueball::kMaxBatchThreads)
          throw cueball::InvalidArgument("threads", static_cast<double>(threads),
                                         "[1, " + std::to_string(cueball::kMaxBatchThreads) + "]", "worker threads");
        if (first_shot < 0 || static_cast<std::uint64_t>(first_shot) > cueball::kMaxFirstShot)
          throw cueball::InvalidArgument("first_shot", static_cast<double>(first_shot), "[0, 2^53]",
                                         "index of actions[0] in the whole study");
        const ScenarioInput input = scenario_input(scenario);
        std::shared_ptr<const cueball::Scenario> s;
        {
          py::gil_scoped_release release;
          s = load_scenario(input);
        }
        s = with_noise_argument(s, noise);
        // No noise at all: the actions as given (no draws).
        cueball::ManyOptions options{static_cast<int>(threads), seed, !(s->noise == cueball::CueStrikeNoise{})};
        options.first_shot = static_cast<std::uint64_t>(first_shot);
        auto result = std::make_unique<cueball::ManyResult>();
        {
          py::gil_scoped_release release;
          *result = cueball::simulate_many(*s, shots, positions, options, on_table);
        }
        const cueball::ManyResult& r = *result;
        const py::capsule owner(result.release(), [](void* p) { delete static_cast<cueball::ManyResult*>(p); });
        const Index n = r.shots, b = r.balls;
        py::dict out;
        out["ids"] = view(r.ids, {b}, owner);
        out["present"] = view(r.present, {n, b}, owner, "bool");
        out["pocketed"] = view(r.pocketed, {n, b}, owner, "bool");
        out["pocket"] = view(r.pocket, {n, b}, owner);
        out["final_position"] = view(r.final_position, {n, b, 2}, owner);
        out["first_contact"] = view(r.first_contact, {n}, owner);
        out["cushions_before_contact"] = view(r.cushions_before_contact, {n, b}, owner);
        out["cushions"] = view(r.cushions, {n, b}, owner);
        out["events"] = view(r.events, {n}, owner);
        out["miscue"] = view(r.miscue, {n}, owner, "bool");
        out["failure"] = view(r.failure, {n}, owner, "bool");
        out["speed_reflected"] = view(r.speed_reflected, {n}, owner, "bool");
        out["elevation_reflected"] = view(r.elevation_reflected, {n}, owner, "bool");
        out["seconds"] = r.seconds;
        out["shots_per_second"] = r.shots_per_second;
        return out;
      },
      "scenario"_a, "actions"_a, "layouts"_a = py::none(), "threads"_a = 1, "seed"_a = 0,
      "noise"_a = false, "first_shot"_a = 0, "present"_a = py::none(),
      "Simulates N different shots of the scenario (None: the built-in break) in one call, on `threads` threads (the GIL\n"
      "released): `actions` is an (N, 5) array of cue speed (m/s), aim (deg), elevation (deg),\n"
      "side and height tip offsets (ball radii), the units of the scenario's \"cue\"; the ball\n"
      "struck is the scenario's cue ball. A tip offset beyond the miscue limit (sqrt(side^2 +\n"
      "height^2) > 0.5) is that shot's outcome (miscue True, not simulated); any field outside its\n"
      "own range raises InvalidArgument naming it (\"actions[17].speed\"). `layouts`, optional, is an\n"
      "(N, n_balls, 2) array of every scenario ball's position (m), in the scenario's order.\n"
      "`present`, optional, an (N, n_balls) bool array: False leaves that ball off the table for\n"
      "that shot (its layout position is ignored, NaN allowed; its row reads present False,\n"
      "pocketed False, pocket -1, final_position NaN); the cue ball must be present. `noise`: False\n"
      "or 'none' (the default: the actions as given), True, None or 'scenario' (the scenario's\n"
      "\"noise\"; a UserWarning when it is all zero), 'tournament', or a dict of sigmas in the\n"
      "scenario's units; shot k's noise is drawn from (seed, first_shot + k). `first_shot` places\n"
      "the rows in a bigger study split into chunks (cueball.dask): a chunk gives exactly the rows\n"
      "of one run of the whole, and errors name the whole's row. Deterministic whatever `threads`. Returns a dict of read-only NumPy arrays, rows by shot and columns by ball\n"
      "(`ids`): present (N, n) bool, pocketed (N, n) bool, pocket (N, n) index or -1, final_position (N, n, 2),\n"
      "first_contact (N,) id of the first ball the cue ball touches or -1, cushions_before_contact\n"
      "and cushions (N, n) cushion contacts before the cue ball's first ball contact and in all,\n"
      "events (N,), miscue, failure, speed_reflected, elevation_reflected (N,) bool; and seconds,\n"
      "shots_per_second. An error in any shot raises what a single run of it would.");
}

}  // namespace cueball_python
