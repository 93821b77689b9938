# Targets shared by tests/codegen and bench/codegen (included from both).
# hinf_codegen_lib: the code generator alone (these sources are also globbed into
# hinf_synth; never link both into one executable). hinf_codegen_cli: a stand-in
# for hinf-synth with only the `codegen` subcommand, so the codegen tests and the
# benchmark do not depend on the rest of the tool.
include_guard(GLOBAL)
find_package(CLI11 REQUIRED)
get_filename_component(_hinf_root ${CMAKE_CURRENT_LIST_DIR}/../../.. ABSOLUTE)
file(GLOB _hinf_codegen_sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/*.cpp)
add_library(hinf_codegen_lib STATIC ${_hinf_codegen_sources})
target_include_directories(hinf_codegen_lib PUBLIC ${_hinf_root}/synth/include)
target_link_libraries(hinf_codegen_lib PUBLIC Eigen3::Eigen hinf_runtime_yaml PRIVATE hinf_warnings)
target_compile_definitions(hinf_codegen_lib PRIVATE EIGEN_DONT_PARALLELIZE)

add_executable(hinf_codegen_cli ${_hinf_root}/tests/codegen/codegen_cli_main.cpp
                                ${_hinf_root}/synth/cli/cmd_codegen.cpp)
target_include_directories(hinf_codegen_cli PRIVATE ${_hinf_root}/synth/cli)
target_link_libraries(hinf_codegen_cli PRIVATE hinf_codegen_lib CLI11::CLI11 hinf_warnings)
target_compile_definitions(hinf_codegen_cli PRIVATE HINF_VERSION="${PROJECT_VERSION}")

# The paper's published gains: the shared config once it exists, else the test copy.
# (A cache variable: include_guard skips this file on the second include.)
if(EXISTS ${_hinf_root}/configs/paper-published-gains.yaml)
  set(HINF_CODEGEN_PAPER_GAINS ${_hinf_root}/configs/paper-published-gains.yaml CACHE INTERNAL "")
else()
  set(HINF_CODEGEN_PAPER_GAINS ${_hinf_root}/tests/codegen/data/paper_gains.yaml CACHE INTERNAL "")
endif()
