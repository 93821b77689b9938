# ctest driver (cmake -P): install the runtime component of HINF_BUILD_DIR into a fresh
# prefix, build the external consumer project against it with find_package(hinfRuntime),
# and run it.
foreach(v HINF_BUILD_DIR CONSUMER_SOURCE_DIR WORK_DIR CXX_COMPILER EXPECT_YAML)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "install_consumer_test.cmake: ${v} not set")
  endif()
endforeach()

function(run)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " cmd "${ARGV}")
    message(FATAL_ERROR "failed (${rc}): ${cmd}\n${out}\n${err}")
  endif()
  message(STATUS "${out}")
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)

if(EXPECT_YAML)
  # the static library must exist before it can be installed
  run(${CMAKE_COMMAND} --build ${HINF_BUILD_DIR} --target hinf_runtime_yaml)
endif()
run(${CMAKE_COMMAND} --install ${HINF_BUILD_DIR} --prefix ${prefix} --component runtime)

if(NOT EXISTS ${prefix}/include/hinf/runtime/lti_filter.hpp)
  message(FATAL_ERROR "headers not installed under ${prefix}/include")
endif()
file(GLOB_RECURSE cfg ${prefix}/*/hinfRuntimeConfig.cmake)
if(NOT cfg)
  message(FATAL_ERROR "hinfRuntimeConfig.cmake not installed under ${prefix}")
endif()

run(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${WORK_DIR}/build
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
    -DCONSUMER_EXPECT_YAML=${EXPECT_YAML} -DCONSUMER_EXPECTED_PREFIX=${prefix})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${WORK_DIR}/build/consumer)

# docs/runtime.md's example application against the same prefix, flying a gains file
if(DEFINED EXAMPLE_SOURCE_DIR AND EXPECT_YAML)
  run(${CMAKE_COMMAND} -S ${EXAMPLE_SOURCE_DIR} -B ${WORK_DIR}/example
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
      -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
  run(${CMAKE_COMMAND} --build ${WORK_DIR}/example)
  execute_process(COMMAND ${WORK_DIR}/example/fly_gains ${EXAMPLE_GAINS} 100 RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "n = 6, gamma = 0\\.3587237128899835[0-9]*, z_F\\(99\\) = [-+0-9.e]+ [-+0-9.e]+ [-+0-9.e]+ [-+0-9.e]+ [-+0-9.e]+ [-+0-9.e]+")
    message(FATAL_ERROR "fly_gains ${EXAMPLE_GAINS}: exit ${rc}\n${out}\n${err}")
  endif()
  message(STATUS "${out}")
endif()
