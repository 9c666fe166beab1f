# Runs cueball-planner-benchmark on a tiny size (TOOL, JSON set by ctest) and
# checks that it exits 0 and that its JSON has the keys docs/planner-benchmark.md documents.
execute_process(
  COMMAND ${TOOL} --suite all --layouts 3 --racks 1 --repeats 200 --planner-simulations 500 --seed 1 --threads 1 --json ${JSON}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cueball-planner-benchmark exited ${rc}:\n${out}\n${err}")
endif()
file(READ ${JSON} text)
foreach(key tool options noise single runout)
  string(JSON value ERROR_VARIABLE e GET "${text}" ${key})
  if(e)
    message(FATAL_ERROR "JSON lacks \"${key}\": ${e}")
  endif()
endforeach()
foreach(method planner ghost_ball exhaustive)
  foreach(key mean_success standard_error no_shot mean_simulations median_simulations median_cpu_seconds mean_cpu_seconds median_seconds mean_seconds)
    string(JSON value ERROR_VARIABLE e GET "${text}" single methods ${method} ${key})
    if(e)
      message(FATAL_ERROR "JSON lacks single.methods.${method}.${key}: ${e}")
    endif()
  endforeach()
endforeach()
foreach(key layouts planner_minus_exhaustive planner_minus_ghost_ball goals per_layout)
  string(JSON value ERROR_VARIABLE e GET "${text}" single ${key})
  if(e)
    message(FATAL_ERROR "JSON lacks single.${key}: ${e}")
  endif()
endforeach()
string(JSON n LENGTH "${text}" single per_layout)
if(NOT n EQUAL 3)
  message(FATAL_ERROR "single.per_layout has ${n} entries, not 3")
endif()
foreach(key racks run_out_fraction mean_balls_potted mean_potted_on_break median_decision_cpu_seconds median_decision_seconds ended_by per_rack)
  string(JSON value ERROR_VARIABLE e GET "${text}" runout ${key})
  if(e)
    message(FATAL_ERROR "JSON lacks runout.${key}: ${e}")
  endif()
endforeach()
# The run-outs played for position (--position), the cue ball in hand placed by the planner, kicks
# when nothing else pots.
execute_process(
  COMMAND ${TOOL} --suite runout --racks 1 --planner-simulations 500 --position 500 --in-hand planner --seed 1 --threads 1
          --fallback-kinds kick --json ${JSON}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cueball-planner-benchmark --position exited ${rc}:\n${out}\n${err}")
endif()
file(READ ${JSON} text)
string(JSON position GET "${text}" options position_simulations)
string(JSON racks GET "${text}" runout racks)
string(JSON in_hand GET "${text}" options in_hand)
string(JSON fallback GET "${text}" options fallback_kinds)
string(JSON planned GET "${text}" runout per_rack 0 planned)
if(NOT position EQUAL 500 OR NOT racks EQUAL 1 OR NOT in_hand STREQUAL "planner" OR NOT fallback STREQUAL "kick")
  message(FATAL_ERROR "--position 500 --racks 1 --in-hand planner --fallback-kinds kick gave options.position_simulations "
                      "${position}, runout.racks ${racks}, options.in_hand ${in_hand}, options.fallback_kinds ${fallback}")
endif()
# The single pots with the agents' kick (--fallback-kinds): seed 100's layout has no direct or bank
# pot, and a kick, planned with the budget again.
foreach(fallback "" "kick")
  set(flag "")
  if(fallback)
    set(flag --fallback-kinds ${fallback})
  endif()
  execute_process(
    COMMAND ${TOOL} --suite single --layouts 1 --seed 100 --repeats 50 --planner-simulations 500 --threads 1 ${flag}
            --json ${JSON}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cueball-planner-benchmark --suite single ${flag} exited ${rc}:\n${out}\n${err}")
  endif()
  file(READ ${JSON} text)
  string(JSON shot GET "${text}" single per_layout 0 planner shot)
  string(JSON runs GET "${text}" single per_layout 0 planner simulations)
  if(fallback AND (NOT shot MATCHES "^kick " OR NOT runs GREATER 500))
    message(FATAL_ERROR "--fallback-kinds kick on seed 100: the planner's shot is '${shot}' in ${runs} runs, not a kick in over 500")
  elseif(NOT fallback AND NOT shot MATCHES "^no feasible shot")
    message(FATAL_ERROR "seed 100 without --fallback-kinds: the planner's shot is '${shot}', not none")
  endif()
endforeach()
# A bad kind exits 2 naming the flag.
execute_process(COMMAND ${TOOL} --suite runout --racks 1 --fallback-kinds kik
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "--fallback-kinds")
  message(FATAL_ERROR "--fallback-kinds kik: exit ${rc}, stderr: ${err}")
endif()
message(STATUS "cueball-planner-benchmark: exit 0, JSON keys present")
