# Layering checks (docs/architecture.md, module graph). lagoon_plain_cxx(target) declares a module plain C++:
#  - at build time, <vulkan/vulkan.h> resolves to cmake/poison_vulkan/ first on its include path, which
#    stops the build with an #error wherever the module includes it, however indirectly;
#  - at generate time, nothing the module links (directly or through other targets) may be Vulkan::Vulkan.
set(LAGOON_POISON_VULKAN_DIR ${CMAKE_CURRENT_LIST_DIR}/poison_vulkan)

function(lagoon_plain_cxx target)
  target_include_directories(${target} BEFORE PRIVATE ${LAGOON_POISON_VULKAN_DIR})
  set_property(GLOBAL APPEND PROPERTY LAGOON_PLAIN_CXX_TARGETS ${target})
endfunction()

# Follows link libraries depth-first for one whose name matches `regex`; `chain` names the path for the
# message (empty when none is reached).
function(_lagoon_find_link target regex chain out)
  set(found "")
  if(TARGET ${target})
    get_target_property(type ${target} TYPE)
    set(libs "")
    get_target_property(iface ${target} INTERFACE_LINK_LIBRARIES)
    if(iface)
      list(APPEND libs ${iface})
    endif()
    if(NOT type STREQUAL "INTERFACE_LIBRARY")
      get_target_property(direct ${target} LINK_LIBRARIES)
      if(direct)
        list(APPEND libs ${direct})
      endif()
    endif()
    foreach(lib IN LISTS libs)
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" lib "${lib}")
      if(lib MATCHES "${regex}")
        set(found "${chain} -> ${lib}")
        break()
      endif()
      if(TARGET ${lib} AND NOT lib IN_LIST chain)
        _lagoon_find_link(${lib} "${regex}" "${chain} -> ${lib}" sub)
        if(sub)
          set(found "${sub}")
          break()
        endif()
      endif()
    endforeach()
  endif()
  set(${out} "${found}" PARENT_SCOPE)
endfunction()

function(_lagoon_find_vulkan target chain out)
  _lagoon_find_link(${target} "^Vulkan::Vulkan$|vulkan" "${chain}" found)
  set(${out} "${found}" PARENT_SCOPE)
endfunction()

# lagoon_forbid_link(target lib "why"): `target` must not reach `lib` through its links (checked once every
# target exists).
function(lagoon_forbid_link target lib why)
  set_property(GLOBAL APPEND PROPERTY LAGOON_FORBIDDEN_LINKS "${target}|${lib}|${why}")
endfunction()

# Called once every target exists (end of the top-level CMakeLists.txt).
function(lagoon_check_layering)
  get_property(targets GLOBAL PROPERTY LAGOON_PLAIN_CXX_TARGETS)
  foreach(t IN LISTS targets)
    _lagoon_find_vulkan(${t} ${t} path)
    if(path)
      message(FATAL_ERROR "layering: ${t} is plain C++ but links Vulkan: ${path} (docs/architecture.md)")
    endif()
  endforeach()
  get_property(rules GLOBAL PROPERTY LAGOON_FORBIDDEN_LINKS)
  foreach(rule IN LISTS rules)
    string(REPLACE "|" ";" parts "${rule}")
    list(GET parts 0 t)
    list(GET parts 1 lib)
    list(GET parts 2 why)
    _lagoon_find_link(${t} "^${lib}$" ${t} path)
    if(path)
      message(FATAL_ERROR "layering: ${why}, but ${t} links ${lib}: ${path} (docs/architecture.md)")
    endif()
  endforeach()
endfunction()

# Which way includes point between modules: lagoon_forbid_includes(target dir "render|dataset" "why") stops the
# build when a header or source under `dir` includes "render/..." or "dataset/..." (a module above it).
# Checked before the target compiles, and again whenever one of those files changes. Call it in the
# CMakeLists.txt that defines `target` (the check is a custom command among its sources).
set(LAGOON_CHECK_INCLUDES_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/CheckIncludes.cmake)
function(lagoon_forbid_includes target dir forbidden why)
  file(GLOB_RECURSE files CONFIGURE_DEPENDS ${dir}/*.h ${dir}/*.cpp)
  set(stamp ${CMAKE_CURRENT_BINARY_DIR}/layering/${target}.includes-checked)
  add_custom_command(
    OUTPUT ${stamp}
    COMMAND ${CMAKE_COMMAND} "-DFILES=${files}" "-DFORBIDDEN=${forbidden}" "-DWHY=${why}" -DSTAMP=${stamp}
            -P ${LAGOON_CHECK_INCLUDES_SCRIPT}
    DEPENDS ${files} ${LAGOON_CHECK_INCLUDES_SCRIPT}
    COMMENT "layering: ${target} includes nothing of ${forbidden}"
    VERBATIM)
  target_sources(${target} PRIVATE ${stamp})
endfunction()
