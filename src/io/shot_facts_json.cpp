// ShotFacts as JSON (io/shot_facts_json.hpp): balls by id, cushions and jaws
// by index and name, pockets by name, null for "none".
#include "cueball/io/shot_facts_json.hpp"

#include "io/json_output.hpp"

namespace cueball {

namespace io {

using Json = nlohmann::json;

Json shot_facts_json(const Table& t, const ShotFacts& f) {
  const auto id_or_null = [](int id) { return id >= 0 ? Json(id) : Json(nullptr); };
  const auto cushion = [&](int c) { return cushion_name(t, static_cast<std::size_t>(c)); };
  Json out;
  out["cue_ball"] = id_or_null(f.cue_ball);
  out["first_contact"] = {{"ball", id_or_null(f.first_contact)},
                          {"time", f.first_contact >= 0 ? Json(f.first_contact_time) : Json(nullptr)},
                          {"simultaneous", id_or_null(f.first_contact_simultaneous)}};
  Json& contacts = out["contacts"] = Json::array();
  for (const BallContact& c : f.contacts) contacts.push_back({{"time", c.time}, {"balls", {c.ball, c.other}}});
  Json& pots = out["pots"] = Json::array();
  for (const Pot& p : f.pots)
    pots.push_back({{"time", p.time}, {"ball", p.ball}, {"pocket", t.pockets[static_cast<std::size_t>(p.pocket)].name}});
  Json& cushions = out["cushions"] = Json::array();
  for (const CushionHit& c : f.cushions)
    cushions.push_back({{"time", c.time}, {"ball", c.ball}, {"cushion", c.cushion}, {"cushion_name", cushion(c.cushion)},
                        {"after_first_contact", c.after_first_contact}});
  Json& before = out["cue_cushions_before_contact"] = Json::array();
  for (const CueCushionsBeforeContact& c : f.cue_cushions_before_contact)
    before.push_back({{"time", c.time}, {"ball", c.ball}, {"cushions", c.cushions}});
  Json& jaws = out["jaws"] = Json::array();
  for (const JawHit& j : f.jaws)
    jaws.push_back({{"time", j.time}, {"ball", j.ball}, {"jaw", j.jaw},
                    {"jaw_name", jaw_name(t, static_cast<std::size_t>(j.jaw))}});
  Json& crossings = out["head_string_crossings"] = Json::array();
  for (const HeadStringCrossing& c : f.head_string_crossings)
    crossings.push_back({{"time", c.time}, {"ball", c.ball}, {"toward_head", c.toward_head}});
  Json frozen_balls = Json::array(), frozen_cushions = Json::array();
  for (const FrozenBalls& b : f.frozen_balls) frozen_balls.push_back({b.ball, b.other});
  for (const FrozenToCushion& c : f.frozen_to_cushion)
    frozen_cushions.push_back({{"ball", c.ball}, {"cushion", c.cushion}, {"cushion_name", cushion(c.cushion)}});
  out["frozen_at_start"] = {{"balls", frozen_balls}, {"cushions", frozen_cushions}};
  return out;
}

}  // namespace io

std::string shot_facts_to_json(const Table& table, const ShotFacts& facts, int indent) {
  return io::shot_facts_json(table, facts).dump(indent);
}

}  // namespace cueball
