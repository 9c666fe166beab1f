# ctest long_numerics_listed: every name of long_numerics.cmake is a test of
# this build with its list's label (long_numerics, long_searches).
# cmake -DCTEST=<ctest> -DBUILD_DIR=<build> -DLIST=<long_numerics.cmake> -P long_numerics_check.cmake
include(${LIST})
foreach(label long_numerics long_searches)
  string(TOUPPER "CUEBALL_${label}" list_name)
  list(LENGTH ${list_name} listed)
  execute_process(COMMAND ${CTEST} --test-dir ${BUILD_DIR} -N -L "^${label}$"
                  OUTPUT_VARIABLE out RESULT_VARIABLE rc)
  string(REGEX MATCH "Total Tests: ([0-9]+)" _ "${out}")
  if(NOT rc EQUAL 0 OR NOT CMAKE_MATCH_1 EQUAL listed)
    message(FATAL_ERROR "long_numerics.cmake lists ${listed} tests in ${list_name} but ${CMAKE_MATCH_1} tests "
                        "carry the label ${label}: a listed name matches no test (renamed?)\n${out}")
  endif()
  message(STATUS "${label}: the ${listed} listed tests carry the label")
endforeach()
