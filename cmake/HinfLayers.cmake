# The layers of the tree, enforced at configure time (docs/design.md "Layers").
#
# HINF_LAYER_<target> lists the project libraries a target may reach through its link
# closure (direct or transitive, PUBLIC, PRIVATE or INTERFACE). hinf_check_layers() walks
# every listed target's closure and stops the configure with FATAL_ERROR on anything else:
# e.g. `target_link_libraries(hinf_certify PRIVATE hinf_lmi)` fails, because the
# certificate must not use the LMI layer or the solver whose results it checks.
# Third-party targets (Eigen3::Eigen, yaml-cpp, PkgConfig::IPOPT, …) are listed apart:
# HINF_EXTERNAL_<target> names the third-party libraries a layer may reach.
include_guard(GLOBAL)

set(HINF_LAYER_hinf_common        "")
set(HINF_LAYER_hinf_models        "")
set(HINF_LAYER_hinf_runtime       hinf_models)
set(HINF_LAYER_hinf_runtime_yaml  hinf_runtime hinf_models hinf_common)
set(HINF_LAYER_hinf_lmi           hinf_common)
set(HINF_LAYER_hinf_sdp           hinf_lmi hinf_common)
set(HINF_LAYER_hinf_certify       hinf_models hinf_common)
set(HINF_LAYER_hinf_synth         hinf_certify hinf_sdp hinf_lmi hinf_common hinf_models
                                  hinf_runtime_yaml hinf_runtime)
set(HINF_LAYER_hinf_codegen       hinf_runtime_yaml hinf_runtime hinf_models hinf_common)
set(HINF_LAYER_hinf_matfile      hinf_common)
set(HINF_LAYER_hinf_sim           hinf_runtime hinf_runtime_yaml hinf_synth hinf_certify hinf_sdp
                                  hinf_lmi hinf_common hinf_models)

# Third-party libraries per layer; anything with '::' or a plain library name not listed
# here is refused too (Ipopt only in the solver, LAPACK only in the certificate).
set(HINF_EXTERNAL_hinf_common     Eigen3::Eigen yaml-cpp)
set(HINF_EXTERNAL_hinf_runtime_yaml Eigen3::Eigen yaml-cpp)
set(HINF_EXTERNAL_hinf_models     Eigen3::Eigen)
set(HINF_EXTERNAL_hinf_runtime    Eigen3::Eigen)
set(HINF_EXTERNAL_hinf_lmi        Eigen3::Eigen yaml-cpp)
set(HINF_EXTERNAL_hinf_sdp        Eigen3::Eigen yaml-cpp PkgConfig::IPOPT)
set(HINF_EXTERNAL_hinf_certify    Eigen3::Eigen yaml-cpp LAPACK)
set(HINF_EXTERNAL_hinf_synth      Eigen3::Eigen yaml-cpp PkgConfig::IPOPT PkgConfig::NETTLE LAPACK
                                  nlohmann_json::nlohmann_json)
set(HINF_EXTERNAL_hinf_matfile   Eigen3::Eigen yaml-cpp nlohmann_json::nlohmann_json PkgConfig::MATIO)
set(HINF_EXTERNAL_hinf_sim        Eigen3::Eigen yaml-cpp PkgConfig::IPOPT PkgConfig::NETTLE LAPACK
                                  Threads::Threads nlohmann_json::nlohmann_json Boost::headers)

# _hinf_closure(<target> <out-var>): the link closure of a target (target names only;
# generator expressions such as $<LINK_ONLY:x> are unwrapped).
function(_hinf_closure target out)
  set(seen "")
  set(todo ${target})
  while(todo)
    list(POP_FRONT todo t)
    if(t IN_LIST seen OR NOT TARGET ${t})
      continue()
    endif()
    list(APPEND seen ${t})
    get_target_property(type ${t} TYPE)
    set(libs "")
    if(NOT type STREQUAL "INTERFACE_LIBRARY")
      get_target_property(direct ${t} LINK_LIBRARIES)
      if(direct)
        list(APPEND libs ${direct})
      endif()
    endif()
    get_target_property(iface ${t} INTERFACE_LINK_LIBRARIES)
    if(iface)
      list(APPEND libs ${iface})
    endif()
    foreach(l IN LISTS libs)
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" l "${l}")
      if(l MATCHES "^\\$<" OR l STREQUAL "hinf_warnings")
        continue()
      endif()
      list(APPEND todo ${l})
      if(NOT TARGET ${l})
        list(APPEND seen ${l})  # a plain library (e.g. from LAPACK_LIBRARIES)
      endif()
    endforeach()
  endwhile()
  list(REMOVE_ITEM seen ${target})
  set(${out} ${seen} PARENT_SCOPE)
endfunction()

function(hinf_check_layers)
  get_cmake_property(vars VARIABLES)
  foreach(v IN LISTS vars)
    if(NOT v MATCHES "^HINF_LAYER_(.+)$")
      continue()
    endif()
    set(layer ${CMAKE_MATCH_1})
    if(NOT TARGET ${layer})
      continue()
    endif()
    _hinf_closure(${layer} closure)
    foreach(dep IN LISTS closure)
      if(dep MATCHES "^hinf_")
        if(NOT dep IN_LIST HINF_LAYER_${layer})
          message(FATAL_ERROR "layer rule: ${layer} must not link ${dep} "
                              "(allowed: ${HINF_LAYER_${layer}}; cmake/HinfLayers.cmake)")
        endif()
      elseif(DEFINED HINF_EXTERNAL_${layer})
        set(ok FALSE)
        foreach(allowed IN LISTS HINF_EXTERNAL_${layer})
          if(dep STREQUAL allowed)
            set(ok TRUE)
          elseif(allowed STREQUAL "LAPACK" AND dep IN_LIST LAPACK_LIBRARIES)
            set(ok TRUE)
          elseif(allowed STREQUAL "LAPACK" AND (dep MATCHES "lapack|blas|gfortran" OR dep STREQUAL "LAPACK::LAPACK" OR dep STREQUAL "BLAS::BLAS"))
            set(ok TRUE)
          endif()
        endforeach()
        if(NOT ok)
          message(FATAL_ERROR "layer rule: ${layer} must not link ${dep} "
                              "(third-party allowed: ${HINF_EXTERNAL_${layer}}; cmake/HinfLayers.cmake)")
        endif()
      endif()
    endforeach()
  endforeach()
endfunction()
