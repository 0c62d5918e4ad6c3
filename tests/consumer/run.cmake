# Configures, builds and runs the consumer project (tests/consumer) one way;
# the ctest tests consumer.<way> run it (cmake -D... -P run.cmake):
#   package       `cmake --install` dpgen's build into WORK_DIR/prefix (its
#                 already built tool), then find_package(dpgen) from there;
#   subdirectory  add_subdirectory(<dpgen's source>): dpgen builds its tool and
#                 runtime, nothing else;
#   fetchcontent  FetchContent from the local source tree, with the tool of
#                 dpgen's build tree (-DDPGEN_GENERATOR): the runtime only is
#                 built (one way builds the tool as a subproject, one not).
# Everything is written under WORK_DIR (in dpgen's build tree), cleared first.
# -D arguments: WAY, SOURCE_DIR, BUILD_DIR (dpgen's build tree), WORK_DIR,
# GENERATOR, CXX_COMPILER; TOOL (the built dpgen) for fetchcontent; optional
# C_COMPILER, MAKE_PROGRAM, LLVM_PREFIX (not for fetchcontent: no tool built).
cmake_minimum_required(VERSION 3.20)

foreach(var WAY SOURCE_DIR BUILD_DIR WORK_DIR GENERATOR CXX_COMPILER)
  if("${${var}}" STREQUAL "")
    message(FATAL_ERROR "run.cmake: -D${var}=... is missing")
  endif()
endforeach()
if(NOT WAY MATCHES "^(package|subdirectory|fetchcontent)$")
  message(FATAL_ERROR "run.cmake: WAY is '${WAY}': expected package, subdirectory or fetchcontent")
endif()

# Runs a command; on failure stops with its whole output.
function(step what)
  string(TIMESTAMP start "%s")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  string(TIMESTAMP end "%s")
  math(EXPR seconds "${end} - ${start}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "consumer.${WAY}: ${what} failed (${rc}):\n${out}")
  endif()
  message(STATUS "consumer.${WAY}: ${what}: ok (${seconds} s)")
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(build ${WORK_DIR}/build)
set(prefix ${WORK_DIR}/prefix)

set(configure -S ${SOURCE_DIR}/tests/consumer -B ${build} -G ${GENERATOR}
    -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DDPGEN_CONSUMER_WAY=${WAY}
    -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
set(passes C_COMPILER:CMAKE_C_COMPILER MAKE_PROGRAM:CMAKE_MAKE_PROGRAM)
if(NOT WAY STREQUAL "fetchcontent")
  list(APPEND passes LLVM_PREFIX:DPGEN_LLVM_PREFIX)
endif()
foreach(pass IN LISTS passes)
  string(REPLACE ":" ";" pass ${pass})
  list(GET pass 0 from)
  list(GET pass 1 to)
  if(NOT "${${from}}" STREQUAL "")
    list(APPEND configure -D${to}=${${from}})
  endif()
endforeach()

if(WAY STREQUAL "package")
  step("cmake --install into ${prefix}" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
  list(APPEND configure -DCMAKE_PREFIX_PATH=${prefix})
else()
  list(APPEND configure -DDPGEN_SOURCE_DIR=${SOURCE_DIR})
endif()
if(WAY STREQUAL "fetchcontent")
  if("${TOOL}" STREQUAL "")
    message(FATAL_ERROR "run.cmake: fetchcontent needs -DTOOL=<dpgen's built tool>")
  endif()
  list(APPEND configure -DDPGEN_GENERATOR=${TOOL})
endif()

step("configure" ${CMAKE_COMMAND} ${configure})
if(WAY STREQUAL "package")
  # The package must come from the prefix just installed, not from elsewhere.
  load_cache(${build} READ_WITH_PREFIX cache_ dpgen_DIR)
  file(REAL_PATH "${cache_dpgen_DIR}" found)
  file(REAL_PATH "${prefix}/lib/cmake/dpgen" expected)
  if(NOT found STREQUAL expected)
    message(FATAL_ERROR "consumer.package: dpgen found in '${cache_dpgen_DIR}', not in ${expected}")
  endif()
endif()

step("build" ${CMAKE_COMMAND} --build ${build} --parallel 2)
step("run" ${build}/consumer)
message(STATUS "${step_output}")
if(NOT step_output MATCHES "relative difference")
  message(FATAL_ERROR "consumer.${WAY}: unexpected output of the consumer:\n${step_output}")
endif()

if(WAY STREQUAL "package")
  # The installed tool, run by hand without -I, finds the installed annotate.hpp.
  step("installed dpgen by hand" ${prefix}/bin/dpgen -v ${SOURCE_DIR}/tests/consumer/smooth.cpp
       --out-dir ${WORK_DIR}/by_hand)
  file(REAL_PATH "${prefix}/include" include)
  string(FIND "${step_output}" "dpgen/annotate.hpp from ${include}\n" at)
  if(at EQUAL -1 OR NOT EXISTS ${WORK_DIR}/by_hand/smooth_adjoint.cpp)
    message(FATAL_ERROR "consumer.package: the installed dpgen did not use ${include}:\n"
                        "${step_output}")
  endif()
else()
  # As a subproject dpgen builds only its tool: every object file built is the
  # consumer's or the tool's (no tests, examples, benchmarks, shipped kernels);
  # given a tool (DPGEN_GENERATOR, fetchcontent), the consumer's only.
  file(GLOB_RECURSE objects ${build}/*.o ${build}/*.obj)
  list(FILTER objects EXCLUDE REGEX "/CMakeFiles/[0-9.]+/|/CMakeFiles/CMake(Tmp|Scratch)/")
  set(unexpected ${objects})
  if(WAY STREQUAL "fetchcontent")
    list(FILTER unexpected EXCLUDE REGEX "/CMakeFiles/(consumer|smooth_kernels)\\.dir/")
  else()
    list(FILTER unexpected EXCLUDE REGEX "/CMakeFiles/(consumer|smooth_kernels|dpgen|dpgen_core)\\.dir/")
  endif()
  list(LENGTH objects built)
  if(unexpected OR built EQUAL 0)
    string(REPLACE ";" "\n  " unexpected "${unexpected}")
    message(FATAL_ERROR "consumer.${WAY}: dpgen as a subproject built more than it should "
                        "(${built} object files):\n  ${unexpected}")
  endif()
  message(STATUS "consumer.${WAY}: ${built} object files, none of them unexpected")
endif()
