# Which files are shipped synthesis configs, and which golden gains file belongs to each.
# Shared by tests/regression/CMakeLists.txt (configure time), golden_coverage.cmake
# (test time, cmake -P) and, in spirit, scripts/regenerate-golden (same rule in bash).
#
# A synthesis config is a top-level configs/*.yaml with a top-level `system:`, `hill:` or `controller:`
# key (docs/file-formats.md). Gains files kept in configs/ (format: hinf-gains/1, e.g.
# paper-published-gains.yaml) and the sim scenarios under configs/scenarios/ are not.
# Its golden file is tests/golden/<config-stem>.yaml.
include_guard(GLOBAL)

# hinf_synthesis_configs(<out-var> <config-dir>): sorted absolute paths.
function(hinf_synthesis_configs out dir)
  file(GLOB candidates LIST_DIRECTORIES false "${dir}/*.yaml")
  list(SORT candidates)
  set(result "")
  foreach(f IN LISTS candidates)
    file(STRINGS "${f}" top REGEX "^(system|hill|controller)[ \t]*:")
    if(top)
      list(APPEND result "${f}")
    endif()
  endforeach()
  set(${out} "${result}" PARENT_SCOPE)
endfunction()

# hinf_golden_for(<out-var> <config> <golden-dir>)
function(hinf_golden_for out config golden_dir)
  get_filename_component(name "${config}" NAME)
  string(REGEX REPLACE "\\.yaml$" "" stem "${name}")
  set(${out} "${golden_dir}/${stem}.yaml" PARENT_SCOPE)
endfunction()
