# ctest long_numerics_listed: every name of long_numerics.cmake is a test of
# this build with the label long_numerics.
# cmake -DCTEST=<ctest> -DBUILD_DIR=<build> -DLIST=<long_numerics.cmake> -P long_numerics_check.cmake
include(${LIST})
list(LENGTH CUEBALL_LONG_NUMERICS listed)
execute_process(COMMAND ${CTEST} --test-dir ${BUILD_DIR} -N -L "^long_numerics$"
                OUTPUT_VARIABLE out RESULT_VARIABLE rc)
string(REGEX MATCH "Total Tests: ([0-9]+)" _ "${out}")
if(NOT rc EQUAL 0 OR NOT CMAKE_MATCH_1 EQUAL listed)
  message(FATAL_ERROR "long_numerics.cmake lists ${listed} tests but ${CMAKE_MATCH_1} tests carry the label "
                      "long_numerics: a listed name matches no test (renamed?)\n${out}")
endif()
message(STATUS "long_numerics: the ${listed} listed tests carry the label")
