// include/cueball/table/rack.hpp: opening positions and table markings.
#include "bindings.hpp"

#include <cstdint>
#include <string>
#include "cueball/table/rack.hpp"

namespace cueball_python {

void bind_rack(py::module_& m) {
  using cueball::PlacedBall;
  using cueball::RackOptions;
  using cueball::SnookerSpots;
  using cueball::Table;

  py::class_<PlacedBall> placed(m, "PlacedBall",
                                "A ball of a rack: id (0 = cue ball), name ('cue', '1', 'red1', 'black', ...),\n"
                                "position (x, y) of its centre, m.");
  placed
      .def(py::init([](int id, const std::string& name, const Pair& position) {
             return PlacedBall{id, name, to_vec2(position)};
           }),
           "id"_a, "name"_a, "position"_a)
      .def_readwrite("id", &PlacedBall::id)
      .def_readwrite("name", &PlacedBall::name)
      .def_property(
          "position", [](const PlacedBall& b) { return to_tuple(b.position); },
          [](PlacedBall& b, const Pair& p) { b.position = to_vec2(p); }, "(x, y), m");
  add_value_semantics(
      placed, "PlacedBall", {"id", "name", "position"},
      [](const PlacedBall& b) { return py::make_tuple(b.id, b.name, to_tuple(b.position)); },
      [](const py::tuple& t) { return PlacedBall{t[0].cast<int>(), t[1].cast<std::string>(), to_vec2(t[2].cast<Pair>())}; });

  py::class_<RackOptions> options(m, "RackOptions",
                                  "gap_sigma: scale of random gaps between the racked balls, m, [0, 0.005]\n"
                                  "(0: frozen rack); seed: of the gaps' random numbers.");
  options
      .def(py::init([](double gap_sigma, std::uint64_t seed) { return RackOptions{gap_sigma, seed}; }),
           "gap_sigma"_a = 0.0, "seed"_a = 0)
      .def_readwrite("gap_sigma", &RackOptions::gap_sigma, "m, [0, 0.005]")
      .def_readwrite("seed", &RackOptions::seed);
  add_value_semantics(
      options, "RackOptions", {"gap_sigma", "seed"},
      [](const RackOptions& o) { return py::make_tuple(o.gap_sigma, o.seed); },
      [](const py::tuple& t) { return RackOptions{t[0].cast<double>(), t[1].cast<std::uint64_t>()}; });

  const char* rack_doc =
      "Validates the table and options, then checks every ball can be placed (InvalidArgument 'rack'\n"
      "naming the ball and the table size it needs). Returns a list of PlacedBall, the cue ball (id 0) first.";
  m.def("rack_nine_ball", &cueball::rack_nine_ball, "table"_a, "options"_a = RackOptions{},
        (std::string("10 balls: cue behind the head string; 1-9 in a diamond, the 1 on the foot spot, the 9\n"
                     "in the centre (WPA). ") + rack_doc).c_str());
  m.def("rack_eight_ball", &cueball::rack_eight_ball, "table"_a, "options"_a = RackOptions{},
        (std::string("16 balls: cue as in 9-ball; 1-15 in a triangle, apex on the foot spot, the 8 in the\n"
                     "centre (WPA). ") + rack_doc).c_str());
  m.def("rack_snooker", &cueball::rack_snooker, "table"_a, "options"_a = RackOptions{},
        (std::string("22 balls: cue in the D; reds 1-15 behind the pink; yellow 16, green 17, brown 18,\n"
                     "blue 19, pink 20, black 21 on their spots (WPBSA). ") + rack_doc).c_str());
  m.def("foot_spot", [](const Table& t) { return to_tuple(cueball::foot_spot(t)); }, "table"_a,
        "(3L/4, W/2), m: the apex ball's spot of a pool rack.");
  m.def("head_string_x", &cueball::head_string_x, "table"_a, "x of the head string, L/4, m.");

  py::class_<SnookerSpots> spots(m, "SnookerSpots",
                                 "Snooker markings (WPBSA Rules 1(d)-(f)) scaled to the table, m: baulk_line_x,\n"
                                 "d_radius, and the spots (x, y) of black, pink, blue, brown, yellow, green.");
  spots.def_readonly("baulk_line_x", &SnookerSpots::baulk_line_x, "m")
      .def_readonly("d_radius", &SnookerSpots::d_radius, "m");
  for (const auto& [name, member] : {std::pair{"black", &SnookerSpots::black}, std::pair{"pink", &SnookerSpots::pink},
                                     std::pair{"blue", &SnookerSpots::blue}, std::pair{"brown", &SnookerSpots::brown},
                                     std::pair{"yellow", &SnookerSpots::yellow}, std::pair{"green", &SnookerSpots::green}}) {
    const auto field = member;
    spots.def_property_readonly(name, [field](const SnookerSpots& s) { return to_tuple(s.*field); }, "(x, y), m");
  }
  add_repr(spots, "SnookerSpots", {"baulk_line_x", "d_radius", "black", "pink", "blue", "brown", "yellow", "green"},
           [](const SnookerSpots& s) {
             return py::make_tuple(s.baulk_line_x, s.d_radius, to_tuple(s.black), to_tuple(s.pink), to_tuple(s.blue),
                                   to_tuple(s.brown), to_tuple(s.yellow), to_tuple(s.green));
           });
  m.def("snooker_spots", &cueball::snooker_spots, "table"_a, "The snooker markings of the table (any size).");
}

}  // namespace cueball_python
