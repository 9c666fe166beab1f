# The layering check (ctest `layering`; docs/architecture.md):
#   1. a library file of layer L includes only headers of layers up to L:
#        core < physics < models < table < simulation < calibration < planning < games < agents < rl < io
#      (public "cueball/<layer>/..." and private "<layer>/..." alike; io, every
#      JSON reader and writer, may read every layer and no layer reads io);
#   2. nlohmann-json is included only in src/io/ (and by the tests, which
#      check JSON);
#   3. cli/, python/, bench/, stress/, fuzz/ and tools/ include public headers only
#      (no private "<layer>/..." header of src/, no src/ include directory).
# The forwarding headers at include/cueball/*.hpp (old paths, kept for one
# release) are exempt. KNOWN lists what is still to move, each with where it
# goes; the check fails when a listed file no longer breaks the rule, so the
# list can only shrink.
#
# cmake -DSOURCE_DIR=<repo> -P check_layering.cmake
# (-DNO_KNOWN=ON checks a tree without the KNOWN list: the check's own test.)

cmake_minimum_required(VERSION 3.25)
set(LAYERS core physics models table simulation calibration planning games agents rl io)
set(KNOWN
  # Empty: the last entry, the CLI's Report and the JSON that batch and
  # cushion-sweep built inline, moved into io/ (report.hpp, batch_json.hpp,
  # cushion_json.hpp; issue 24).
  )

if(NO_KNOWN)
  set(KNOWN "")
endif()
set(violations "")
set(seen_known "")

function(layer_rank name out)
  list(FIND LAYERS "${name}" i)
  set(${out} ${i} PARENT_SCOPE)
endfunction()

# Records a violation, or notes a known one.
macro(report kind file message)
  if("${kind}:${file}" IN_LIST KNOWN)
    list(APPEND seen_known "${kind}:${file}")
  else()
    list(APPEND violations "${file}: ${message}")
  endif()
endmacro()

# 1 and 2: the library.
foreach(root include/cueball src)
  file(GLOB_RECURSE files RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/${root}/*.hpp ${SOURCE_DIR}/${root}/*.cpp)
  foreach(file IN LISTS files)
    string(REGEX MATCH "^(include/cueball|src)/([a-z_]+)/" m "${file}")
    if(NOT m)
      continue()  # a forwarding header at the old flat path
    endif()
    set(own ${CMAKE_MATCH_2})
    file(READ ${SOURCE_DIR}/${file} head LIMIT 200)
    if(head MATCHES "forwarding header is kept")
      continue()  # a forwarding header at an old path (include/cueball/cushion/...)
    endif()
    layer_rank(${own} own_rank)
    if(own_rank EQUAL -1)
      string(REPLACE ";" ", " layer_names "${LAYERS}")
      list(APPEND violations "${file}: '${own}' is not a layer (${layer_names})")
      continue()
    endif()
    file(STRINGS ${SOURCE_DIR}/${file} includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
    foreach(line IN LISTS includes)
      string(REGEX MATCH "[<\"]([^>\"]+)[>\"]" _ "${line}")
      set(path ${CMAKE_MATCH_1})
      if(path MATCHES "^nlohmann/" AND NOT own STREQUAL "io")
        report(nlohmann ${file} "includes <${path}> outside io/")
      endif()
      set(other "")
      if(path MATCHES "^cueball/([a-z_]+)/")
        set(other ${CMAKE_MATCH_1})
      elseif(root STREQUAL "src" AND path MATCHES "^([a-z_]+)/[a-z_0-9]+\\.hpp$")
        set(other ${CMAKE_MATCH_1})
      endif()
      if(other)
        layer_rank(${other} other_rank)
        if(other_rank GREATER own_rank)
          report(layer ${file} "layer '${own}' includes \"${path}\" of the later layer '${other}'")
        endif()
      endif()
    endforeach()
  endforeach()
endforeach()

# 3: what is built on the library.
foreach(dir cli python/src bench stress fuzz tools)
  file(GLOB_RECURSE files RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/${dir}/*.hpp ${SOURCE_DIR}/${dir}/*.cpp)
  foreach(file IN LISTS files)
    file(STRINGS ${SOURCE_DIR}/${file} includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
    foreach(line IN LISTS includes)
      string(REGEX MATCH "[<\"]([^>\"]+)[>\"]" _ "${line}")
      set(path ${CMAKE_MATCH_1})
      string(REGEX MATCH "^([a-z_]+)/" m "${path}")
      if(m)
        list(FIND LAYERS "${CMAKE_MATCH_1}" i)
        if(NOT i EQUAL -1)
          report(private ${file} "includes the library's private header \"${path}\" (src/)")
        endif()
      endif()
      if(path MATCHES "^nlohmann/")
        report(nlohmann ${file} "includes <${path}> outside io/")
      endif()
    endforeach()
  endforeach()
endforeach()
foreach(file CMakeLists.txt python/CMakeLists.txt bench/CMakeLists.txt stress/CMakeLists.txt fuzz/CMakeLists.txt
             tests/CMakeLists.txt)
  if(NOT EXISTS ${SOURCE_DIR}/${file})
    continue()
  endif()
  file(STRINGS ${SOURCE_DIR}/${file} lines REGEX "target_include_directories\\((cueball_[a-z_]+|[a-z_-]+)[ \t]+PRIVATE[^)]*PROJECT_SOURCE_DIR}/src")
  foreach(line IN LISTS lines)
    if(NOT line MATCHES "target_include_directories\\(cueball[ \t]")
      report(src_dir ${file} "gives a target outside the library src/ as an include directory: ${line}")
    endif()
  endforeach()
endforeach()

foreach(k IN LISTS KNOWN)
  if(NOT k IN_LIST seen_known)
    list(APPEND violations "check_layering.cmake: '${k}' is listed as still to move but no longer breaks the rule: take it off KNOWN")
  endif()
endforeach()

list(LENGTH KNOWN known_count)
if(violations)
  list(JOIN violations "\n  " text)
  message(FATAL_ERROR "layering: violations:\n  ${text}")
endif()
message(STATUS "layering: every include follows the layers (${known_count} known exceptions still to move, listed in check_layering.cmake)")
