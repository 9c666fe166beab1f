# The layering check's own test: a tree breaking each rule once must fail
# with that rule's message, and a tree that follows the rules must pass.
# cmake -DCHECK=<check_layering.cmake> -DWORK=<scratch dir> -P check_detects.cmake

function(tree name)
  file(REMOVE_RECURSE ${WORK}/${name})
  set(files ${ARGN})
  list(LENGTH files n)
  math(EXPR last "${n} - 1")
  foreach(i RANGE 0 ${last} 2)
    math(EXPR j "${i} + 1")
    list(GET files ${i} path)
    list(GET files ${j} text)
    file(WRITE ${WORK}/${name}/${path} "${text}\n")
  endforeach()
endfunction()

function(expect name want)
  execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${WORK}/${name} -DNO_KNOWN=ON -P ${CHECK}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(want STREQUAL "pass")
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "${name}: the check failed on a good tree:\n${out}${err}")
    endif()
  elseif(rc EQUAL 0 OR NOT err MATCHES "${want}")
    message(FATAL_ERROR "${name}: expected a failure matching '${want}', got exit ${rc}:\n${out}${err}")
  endif()
endfunction()

tree(good
  include/cueball/table/t.hpp "#include \"cueball/core/vec.hpp\""
  src/planning/p.cpp "#include \"cueball/table/t.hpp\"\n#include \"planning/search.hpp\""
  src/io/j.cpp "#include <nlohmann/json.hpp>\n#include \"cueball/planning/p.hpp\""
  cli/c.cpp "#include \"cueball/io/j.hpp\"\n#include \"common.hpp\"")
expect(good pass)

tree(later_layer include/cueball/table/t.hpp "#include \"cueball/planning/shot_planner.hpp\"")
expect(later_layer "layer 'table' includes \"cueball/planning/shot_planner.hpp\" of the later layer 'planning'")

tree(private_later src/simulation/s.cpp "#include \"planning/shot_search.hpp\"")
expect(private_later "layer 'simulation' includes \"planning/shot_search.hpp\" of the later layer 'planning'")

tree(reads_io src/simulation/s.cpp "#include \"cueball/io/scenario_json.hpp\"")
expect(reads_io "of the later layer 'io'")

tree(nlohmann src/table/t.cpp "#include <nlohmann/json.hpp>")
expect(nlohmann "src/table/t.cpp: includes <nlohmann/json.hpp> outside io/")

tree(cli_private bench/b.cpp "#include \"io/json_input.hpp\"")
expect(cli_private "bench/b.cpp: includes the library's private header \"io/json_input.hpp\"")

tree(cli_src_dir CMakeLists.txt "target_include_directories(cueball_cli PRIVATE \${PROJECT_SOURCE_DIR}/src)")
expect(cli_src_dir "gives a target outside the library src/ as an include directory")

tree(no_layer src/widgets/w.cpp "int x;")
expect(no_layer "'widgets' is not a layer")
