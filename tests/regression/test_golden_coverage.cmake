# cmake -DSOURCE_DIR=<repo> -DWORK_DIR=<scratch> -P test_golden_coverage.cmake
# Tests the rule "a new synthesis config without a golden file fails the suite":
# runs golden_coverage.cmake on copies of configs/ and tests/golden/ with
#   (a) nothing changed                      -> must pass,
#   (b) a new `system:` config, no golden     -> must fail and name the config,
#   (c) a new `hill:` config, no golden       -> must fail and name it,
#   (d) (b) plus its golden file              -> must pass,
#   (e) a golden file whose config is gone    -> must fail and name the golden file,
#   (f) a gains file dropped into configs/    -> not a config: must pass.
# It also re-runs CMake's configure-time list (hinf_synthesis_configs) on (b) and
# checks the new config is listed, i.e. it gets a (failing) golden_check_ test.
cmake_minimum_required(VERSION 3.16)  # script mode: policies (IN_LIST) as in the project
include(${CMAKE_CURRENT_LIST_DIR}/golden_configs.cmake)
set(coverage ${CMAKE_CURRENT_LIST_DIR}/golden_coverage.cmake)
set(cfg ${WORK_DIR}/configs)
set(gold ${WORK_DIR}/golden)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${cfg} ${gold})
file(GLOB shipped LIST_DIRECTORIES false ${SOURCE_DIR}/configs/*.yaml)
file(COPY ${shipped} DESTINATION ${cfg})
file(GLOB goldens LIST_DIRECTORIES false ${SOURCE_DIR}/tests/golden/*.yaml)
file(COPY ${goldens} DESTINATION ${gold})

set(failures "")
function(expect what should_pass must_mention)
  execute_process(COMMAND ${CMAKE_COMMAND} -DCONFIG_DIR=${cfg} -DGOLDEN_DIR=${gold} -P ${coverage}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(text "${out}${err}")
  if(should_pass AND NOT rc EQUAL 0)
    string(APPEND failures "${what}: expected pass, got exit ${rc}:\n${text}\n")
  elseif(NOT should_pass AND rc EQUAL 0)
    string(APPEND failures "${what}: expected failure, got exit 0:\n${text}\n")
  endif()
  if(NOT "${must_mention}" STREQUAL "")
    string(FIND "${text}" "${must_mention}" pos)
    if(pos EQUAL -1)
      string(APPEND failures "${what}: output does not mention '${must_mention}':\n${text}\n")
    endif()
  endif()
  set(failures "${failures}" PARENT_SCOPE)
  message(STATUS "${what}: exit ${rc}")
endfunction()

expect("(a) shipped configs and goldens" TRUE "")
file(WRITE ${cfg}/new-plant.yaml "system:\n  A: [[0.5]]\n  B: [[1]]\n  C: [[1]]\n  D: [[1]]\n  L: [[1]]\n")
expect("(b) new system config without golden" FALSE "new-plant.yaml")
hinf_synthesis_configs(listed ${cfg})
if(NOT "${cfg}/new-plant.yaml" IN_LIST listed)
  string(APPEND failures "(b) hinf_synthesis_configs does not list new-plant.yaml: ${listed}\n")
endif()
file(WRITE ${cfg}/new-hill.v2.yaml "# comment\nhill:\n  chaser_mass: 1\n")
expect("(c) new hill config (dotted name) without golden" FALSE "new-hill.v2.yaml")
file(REMOVE ${cfg}/new-hill.v2.yaml)
file(WRITE ${gold}/new-plant.yaml "format: hinf-gains/1\n")
expect("(d) new config with golden" TRUE "")
file(REMOVE ${cfg}/new-plant.yaml)
expect("(e) golden without config" FALSE "new-plant.yaml")
file(REMOVE ${gold}/new-plant.yaml)
file(WRITE ${cfg}/some-gains.yaml "format: hinf-gains/1\nfilter:\n  A_F: [[0.5]]\n  B_F: [[1]]\n  C_F: [[1]]\n")
expect("(f) gains file in configs/" TRUE "")

file(REMOVE_RECURSE ${WORK_DIR})
if(failures)
  message(FATAL_ERROR "${failures}")
endif()
