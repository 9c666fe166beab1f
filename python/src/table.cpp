// include/cueball/table/table.hpp: tables (presets, specs, custom geometry, JSON)
// and their parts. A Table is a read-only value that is always valid: every
// way of making one validates it (validate(const Table&)), so its methods can
// call the library's unchecked queries.
#include "bindings.hpp"

#include <pybind11/operators.h>

#include <cmath>
#include <string>
#include <vector>
#include "cueball/core/errors.hpp"
#include "cueball/io/table_json.hpp"
#include "cueball/table/table.hpp"

namespace cueball_python {

namespace {

using cueball::CushionSegment;
using cueball::JawArc;
using cueball::Pocket;
using cueball::PocketSpec;
using cueball::Table;
using cueball::TableSpec;

py::list points(const std::vector<cueball::Vec2>& v) {
  py::list out;
  for (const cueball::Vec2& p : v) out.append(to_tuple(p));
  return out;
}

// A ball of `radius` against a validated table: the radius in its parameter
// range and every contact height in (0, 2 radius) (ball_on_table's precondition).
void check_radius(const Table& t, double radius) {
  cueball::check_range(cueball::kRadiusRange, radius);
  double highest = 0.0;
  for (const CushionSegment& c : t.cushions) highest = std::fmax(highest, c.contact_height);
  for (const JawArc& j : t.jaws) highest = std::fmax(highest, j.contact_height);
  if (!(highest < 2.0 * radius))
    throw cueball::InvalidArgument("radius", radius, "(" + cueball::format_number(highest / 2.0) + ", 0.1]",
                                   "ball radius, m: above half the table's highest cushion contact height");
}

cueball::Vec2 finite_point(const char* field, const Pair& p) {
  if (!(std::isfinite(p[0]) && std::isfinite(p[1])))
    throw cueball::InvalidArgument(field, std::string(field) + " must be finite (got a NaN or infinity)");
  return to_vec2(p);
}

// A table's parts with the names in use (cushion_name(), jaw_name()), validated.
Table validated_table(Table t) {
  cueball::name_parts(t);
  cueball::validate(t);
  return t;
}

}  // namespace

void bind_table(py::module_& m) {
  py::class_<CushionSegment> cushion(
      m, "CushionSegment",
      "A straight cushion nose from start to end (x, y), m; the playing surface on its LEFT (the\n"
      "boundary runs anticlockwise seen from above). contact_height: h of the nose above the bed, m,\n"
      "in (R, 2R). name: as the result's events give it ('bottom rail', 'cushions[3]').");
  cushion
      .def(py::init([](const Pair& start, const Pair& end, double contact_height, const std::string& name) {
             return CushionSegment{to_vec2(start), to_vec2(end), contact_height, name};
           }),
           "start"_a, "end"_a, "contact_height"_a, "name"_a = "")
      .def_property_readonly("start", [](const CushionSegment& c) { return to_tuple(c.start); }, "(x, y), m")
      .def_property_readonly("end", [](const CushionSegment& c) { return to_tuple(c.end); }, "(x, y), m")
      .def_readonly("contact_height", &CushionSegment::contact_height, "h, m")
      .def_readonly("name", &CushionSegment::name)
      .def_property_readonly(
          "inward_normal",
          [](const CushionSegment& c) {
            if (!(cueball::norm(c.end - c.start) > 0.0))
              throw cueball::InvalidArgument("end", "end = start: a cushion of zero length has no normal");
            return to_tuple(cueball::inward_normal(c));
          },
          "unit normal of the nose line pointing onto the playing surface");
  add_value_semantics(
      cushion, "CushionSegment", {"start", "end", "contact_height", "name"},
      [](const CushionSegment& c) { return py::make_tuple(to_tuple(c.start), to_tuple(c.end), c.contact_height, c.name); },
      [](const py::tuple& t) {
        return CushionSegment{to_vec2(t[0].cast<Pair>()), to_vec2(t[1].cast<Pair>()), t[2].cast<double>(),
                              t[3].cast<std::string>()};
      });

  py::class_<JawArc> jaw(m, "JawArc",
                         "The rounded cushion tip at a pocket: a circle about centre (x, y), m, of radius m, its\n"
                         "nose at contact_height h, m, in (R, 2R).");
  jaw.def(py::init([](const Pair& centre, double radius, double contact_height, const std::string& name) {
            return JawArc{to_vec2(centre), radius, contact_height, name};
          }),
          "centre"_a, "radius"_a, "contact_height"_a, "name"_a = "")
      .def_property_readonly("centre", [](const JawArc& j) { return to_tuple(j.centre); }, "(x, y), m")
      .def_readonly("radius", &JawArc::radius, "m")
      .def_readonly("contact_height", &JawArc::contact_height, "h, m")
      .def_readonly("name", &JawArc::name);
  add_value_semantics(
      jaw, "JawArc", {"centre", "radius", "contact_height", "name"},
      [](const JawArc& j) { return py::make_tuple(to_tuple(j.centre), j.radius, j.contact_height, j.name); },
      [](const py::tuple& t) {
        return JawArc{to_vec2(t[0].cast<Pair>()), t[1].cast<double>(), t[2].cast<double>(), t[3].cast<std::string>()};
      });

  py::class_<Pocket> pocket(m, "Pocket",
                            "A pocket's capture circle: a ball whose centre comes within radius (m) of centre\n"
                            "(x, y), m, drops.");
  pocket
      .def(py::init([](const std::string& name, const Pair& centre, double radius) {
             return Pocket{name, to_vec2(centre), radius};
           }),
           "name"_a, "centre"_a, "radius"_a)
      .def_readonly("name", &Pocket::name)
      .def_property_readonly("centre", [](const Pocket& p) { return to_tuple(p.centre); }, "(x, y), m")
      .def_readonly("radius", &Pocket::radius, "m");
  add_value_semantics(
      pocket, "Pocket", {"name", "centre", "radius"},
      [](const Pocket& p) { return py::make_tuple(p.name, to_tuple(p.centre), p.radius); },
      [](const py::tuple& t) { return Pocket{t[0].cast<std::string>(), to_vec2(t[1].cast<Pair>()), t[2].cast<double>()}; });

  py::class_<PocketSpec> pocket_spec(
      m, "PocketSpec",
      "One kind of pocket: mouth (m, lip to lip), cut_angle_deg (degrees, [90, 170]), jaw_radius (m),\n"
      "shelf (m, mouth line to the slate's cut).");
  pocket_spec
      .def(py::init([](double mouth, double cut_angle_deg, double jaw_radius, double shelf) {
             return PocketSpec{mouth, cut_angle_deg, jaw_radius, shelf};
           }),
           "mouth"_a, "cut_angle_deg"_a, "jaw_radius"_a, "shelf"_a = 0.0)
      .def_readwrite("mouth", &PocketSpec::mouth, "m, (0, 0.5]")
      .def_readwrite("cut_angle_deg", &PocketSpec::cut_angle_deg, "degrees, [90, 170]")
      .def_readwrite("jaw_radius", &PocketSpec::jaw_radius, "m, (0, 0.2]")
      .def_readwrite("shelf", &PocketSpec::shelf, "m, [0, 0.2]");
  add_value_semantics(
      pocket_spec, "PocketSpec", {"mouth", "cut_angle_deg", "jaw_radius", "shelf"},
      [](const PocketSpec& p) { return py::make_tuple(p.mouth, p.cut_angle_deg, p.jaw_radius, p.shelf); },
      [](const py::tuple& t) {
        return PocketSpec{t[0].cast<double>(), t[1].cast<double>(), t[2].cast<double>(), t[3].cast<double>()};
      });

  py::class_<TableSpec> spec(
      m, "TableSpec",
      "A rectangular table (build_table()): four corner and two side pockets (has_pockets) or a\n"
      "carom table. Lengths in m; read/write, checked by build_table(). preset_table_spec(name) gives a\n"
      "preset's spec to change.");
  spec.def(py::init([](const std::string& name, double length, double width, double cushion_height,
                       const cueball::BallParameters& ball, bool has_pockets, const PocketSpec& corner_pockets,
                       const PocketSpec& side_pockets, bool has_diamonds, double diamond_offset) {
             return TableSpec{name,         length,       width,         cushion_height, ball, has_pockets,
                              corner_pockets, side_pockets, has_diamonds, diamond_offset};
           }),
           "name"_a, "length"_a, "width"_a, "cushion_height"_a, "ball"_a, "has_pockets"_a = true,
           "corner_pockets"_a = PocketSpec{}, "side_pockets"_a = PocketSpec{}, "has_diamonds"_a = true,
           "diamond_offset"_a = 0.0)
      .def_readwrite("name", &TableSpec::name)
      .def_readwrite("length", &TableSpec::length, "m, (0, 10], cushion nose to nose along x")
      .def_readwrite("width", &TableSpec::width, "m, (0, 10], along y")
      .def_readwrite("cushion_height", &TableSpec::cushion_height, "h of every nose, m, (R, 2R)")
      .def_readwrite("ball", &TableSpec::ball)
      .def_readwrite("has_pockets", &TableSpec::has_pockets)
      .def_readwrite("corner_pockets", &TableSpec::corner_pockets, "ignored without pockets")
      .def_readwrite("side_pockets", &TableSpec::side_pockets, "ignored without pockets")
      .def_readwrite("has_diamonds", &TableSpec::has_diamonds)
      .def_readwrite("diamond_offset", &TableSpec::diamond_offset, "m, sight centre behind the nose line, [0, 0.5]");
  add_value_semantics(
      spec, "TableSpec",
      {"name", "length", "width", "cushion_height", "ball", "has_pockets", "corner_pockets", "side_pockets",
       "has_diamonds", "diamond_offset"},
      [](const TableSpec& s) {
        return py::make_tuple(s.name, s.length, s.width, s.cushion_height, s.ball, s.has_pockets, s.corner_pockets,
                              s.side_pockets, s.has_diamonds, s.diamond_offset);
      },
      [](const py::tuple& t) {
        return TableSpec{t[0].cast<std::string>(), t[1].cast<double>(),    t[2].cast<double>(),
                         t[3].cast<double>(),      t[4].cast<cueball::BallParameters>(), t[5].cast<bool>(),
                         t[6].cast<PocketSpec>(),  t[7].cast<PocketSpec>(), t[8].cast<bool>(),
                         t[9].cast<double>()};
      });

  py::class_<Table> table(
      m, "Table",
      "A table's geometry, read-only and always valid: cushions, jaws and pockets (lists of\n"
      "CushionSegment, JawArc, Pocket, every part named), diamonds, the ball played on it. Frame: x\n"
      "along the length (0..length), y across (0..width), m. Made by Table.preset(name), Table.from_spec(spec),\n"
      "Table.from_json(text) or Table(...) from parts; == compares the geometry; pickled as its JSON.");
  table
      .def(py::init([](double length, double width, const std::vector<CushionSegment>& cushions,
                       const cueball::BallParameters& ball, const std::vector<JawArc>& jaws,
                       const std::vector<Pocket>& pockets, const std::vector<Pair>& diamonds, const std::string& name) {
             Table t{name, length, width, cushions, jaws, pockets, {}, ball};
             for (const Pair& d : diamonds) t.diamonds.push_back(to_vec2(d));
             return validated_table(std::move(t));
           }),
           "length"_a, "width"_a, "cushions"_a, "ball"_a, "jaws"_a = std::vector<JawArc>{},
           "pockets"_a = std::vector<Pocket>{}, "diamonds"_a = std::vector<Pair>{}, "name"_a = "custom",
           "A custom table from its parts, validated (InvalidArgument naming e.g. 'cushions[3].end');\n"
           "unnamed cushions and jaws get their default names 'cushions[i]', 'jaws[j]'.")
      .def_static("preset", [](const std::string& name) { return cueball::preset_table(name); }, "name"_a,
                  "A preset: 'pool_9ft', 'snooker_12ft' or 'carom_10ft' (TABLE_PRESETS).")
      .def_static("from_spec", &cueball::build_table, "spec"_a,
                  "The geometry of a rectangular TableSpec (validated: InvalidArgument naming the field).")
      .def_static(
          "from_json", [](const std::string& text) { return cueball::table_from_json(text); }, "text"_a,
          "A table from its JSON text (a preset with overrides or the full geometry; README 'Scenario format').")
      .def("to_json", [](const Table& t) { return cueball::table_to_json(t); },
           "The full geometry as JSON text (from_json of it gives an equal table).")
      .def_readonly("name", &Table::name)
      .def_readonly("length", &Table::length, "m, along x, cushion nose to nose")
      .def_readonly("width", &Table::width, "m, along y")
      .def_property_readonly("ball", [](const Table& t) { return t.ball; }, "the balls played on this table (a copy)")
      .def_property_readonly(
          "cushions", [](const Table& t) { return t.cushions; }, "list of CushionSegment, the boundary in order (copies)")
      .def_property_readonly("jaws", [](const Table& t) { return t.jaws; }, "list of JawArc (copies)")
      .def_property_readonly("pockets", [](const Table& t) { return t.pockets; }, "list of Pocket (copies)")
      .def_property_readonly("diamonds", [](const Table& t) { return points(t.diamonds); },
                             "list of (x, y), m: the sights, for drawing")
      .def("validate", [](const Table& t) { cueball::validate(t); },
           "Checks the geometry again (it always passes: every Table is validated when made).")
      .def(
          "ball_on_table",
          [](const Table& t, const Pair& position, std::optional<double> radius) {
            const double r = radius ? *radius : t.ball.radius;
            check_radius(t, r);
            return cueball::ball_on_table(t, to_vec2(position), r);
          },
          "position"_a, "radius"_a = py::none(),
          "True when a ball of radius (m; default the table's ball) can be placed with its centre at\n"
          "position (x, y), m: inside the playing area, overlapping no cushion or jaw, not over a pocket.")
      .def(
          "inside_playing_area",
          [](const Table& t, const Pair& position, double margin) {
            if (!(std::isfinite(margin) && margin >= 0.0))
              throw cueball::InvalidArgument("margin", margin, "[0, infinity)", "m");
            return cueball::inside_playing_area(t, finite_point("position", position), margin);
          },
          "position"_a, "margin"_a = 0.0,
          "True when a ball's centre at position (x, y), m, is inside the closed playing area (the\n"
          "pockets' throats included) or within margin (m, >= 0) of it.")
      .def(py::self == py::self)
      .def("__repr__",
           [](const Table& t) {
             return "Table(name=" + py::repr(py::str(t.name)).cast<std::string>() +
                    ", length=" + py::repr(py::float_(t.length)).cast<std::string>() +
                    ", width=" + py::repr(py::float_(t.width)).cast<std::string>() +
                    ", cushions=" + std::to_string(t.cushions.size()) + ", jaws=" + std::to_string(t.jaws.size()) +
                    ", pockets=" + std::to_string(t.pockets.size()) + ")";
           })
      .def(py::pickle([](const Table& t) { return cueball::table_to_json(t); },
                      [](const std::string& text) { return cueball::table_from_json(text); }));

  py::tuple presets(cueball::kTablePresetNames.size());
  for (std::size_t i = 0; i < cueball::kTablePresetNames.size(); ++i)
    presets[i] = py::str(std::string(cueball::kTablePresetNames[i]));
  m.attr("TABLE_PRESETS") = presets;

  // The library's free functions, under their C++ names.
  m.def("preset_table", [](const std::string& name) { return cueball::preset_table(name); }, "name"_a,
        "Table.preset(name): 'pool_9ft', 'snooker_12ft' or 'carom_10ft'.");
  m.def("pool_table_9ft", &cueball::pool_table_9ft, "9-ft pool table (WPA Equipment Specifications; BCA shelf).");
  m.def("snooker_table_12ft", &cueball::snooker_table_12ft, "Full-size snooker table (WPBSA Rules, section 1).");
  m.def("carom_table_10ft", &cueball::carom_table_10ft, "UMB match carom table, no pockets.");
  m.def("preset_table_spec", [](const std::string& name) { return cueball::preset_table_spec(name); }, "name"_a,
        "The TableSpec of a preset, to change and build (build_table).");
  m.def("build_table", &cueball::build_table, "spec"_a, "Table.from_spec(spec).");
  m.def("table_from_json", [](const std::string& text) { return cueball::table_from_json(text); }, "text"_a,
        "Table.from_json(text).");
  m.def("table_to_json", &cueball::table_to_json, "table"_a, "table.to_json().");
}

}  // namespace cueball_python
