// ShotFacts (simulation/shot_facts.hpp) as JSON: the result JSON's "facts"
// object, also what Python's Result.facts gives.
//
//   {"cue_ball": id | null,
//    "first_contact": {"ball": id | null, "time": s | null, "simultaneous": id | null},
//    "contacts": [{"time", "balls": [id, id]}, ...],
//    "pots": [{"time", "ball", "pocket": name}, ...],
//    "cushions": [{"time", "ball", "cushion": index, "cushion_name", "after_first_contact"}, ...],
//    "cue_cushions_before_contact": [{"time", "ball", "cushions"}, ...],
//    "jaws": [{"time", "ball", "jaw": index, "jaw_name"}, ...],
//    "head_string_crossings": [{"time", "ball", "toward_head"}, ...],
//    "frozen_at_start": {"balls": [[id, id], ...], "cushions": [{"ball", "cushion", "cushion_name"}, ...]}}
#pragma once

#include <string>

#include "cueball/simulation/shot_facts.hpp"
#include "cueball/table/table.hpp"

namespace cueball {

/// The facts of a shot on `table` (the names of its pockets, cushions and
/// jaws) as the JSON above; `indent` as in result_to_json (-1: one line).
std::string shot_facts_to_json(const Table& table, const ShotFacts& facts, int indent = 1);

}  // namespace cueball
