# `cmake --install` for hosts that embed Lagoon (docs/embedding.md): the static libraries, the headers under
# include/lagoon/ (same #include paths as in this tree), LagoonConfig.cmake with Lagoon:: targets and
# pkg-config files. Included at the very end of the top-level CMakeLists.txt, once every target exists.
#
# Two export sets, so a host can use the plain-C++ ocean without Vulkan being installed at all:
#   LagoonPlainTargets.cmake   the targets that reach no Vulkan: core, ocean, optics, fft_cpu, physics, io,
#                              scene, gltf, world, ...
#   LagoonVulkanTargets.cmake  the rest: vk, shaders, fft, ocean_gpu, render, ...
# The sets are computed (everything the roots below link, split with LagoonLayering's Vulkan search), so a
# module added to the graph is exported without editing this file.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(LAGOON_EXPORT_ROOTS lagoon_core lagoon_fft_cpu lagoon_ocean lagoon_optics lagoon_physics lagoon_world lagoon_render lagoon_dataset)
set(LAGOON_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/Lagoon)
set(LAGOON_INSTALL_INCLUDEDIR ${CMAKE_INSTALL_INCLUDEDIR}/lagoon)

# Helper targets that only make sense inside this build: their usage requirements must not reach a host.
#   lagoon_warnings: -Werror & co. for our own sources; compile-only, it contributes nothing to a link.
#   lagoon_codecs: libpng, libjpeg-turbo, libwebp and nettle, which the static io archive needs at the host's
#               link: installed consumers get Lagoon::codecs instead, which LagoonConfig.cmake defines from
#               the libraries it finds.
#   lagoon_stb: stb's headers (stb_easy_font in io, header-only; stb_image_write in the tests).
set(LAGOON_BUILD_ONLY_TARGETS lagoon_warnings lagoon_codecs lagoon_stb)
# Imported targets an exported interface may name: LagoonConfig.cmake finds each of them.
set(LAGOON_KNOWN_DEPENDENCIES Threads::Threads glm::glm Vulkan::Vulkan nlohmann_json::nlohmann_json PNG::PNG)

# Appends to `out_var` every lagoon target `target` links, transitively (INTERFACE_LINK_LIBRARIES holds a
# static library's PRIVATE links too, as $<LINK_ONLY:...>). Stops the configure on a dependency that
# LagoonConfig.cmake would not know how to find.
function(_lagoon_export_closure target out_var)
  set(found ${${out_var}})
  if(target IN_LIST found)
    return()
  endif()
  list(APPEND found ${target})
  get_target_property(libs ${target} INTERFACE_LINK_LIBRARIES)
  if(NOT libs)
    set(libs "")
  endif()
  foreach(lib IN LISTS libs)
    string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" lib "${lib}")
    if(lib IN_LIST LAGOON_BUILD_ONLY_TARGETS OR lib IN_LIST LAGOON_KNOWN_DEPENDENCIES)
      continue()
    elseif(lib MATCHES "^lagoon_" AND TARGET ${lib})
      _lagoon_export_closure(${lib} found)
    else()
      message(FATAL_ERROR "LagoonInstall: ${target} links '${lib}', which the installed LagoonConfig.cmake "
                          "cannot provide; find it there and add it to LAGOON_KNOWN_DEPENDENCIES (or to "
                          "LAGOON_BUILD_ONLY_TARGETS if it must not reach hosts) in cmake/LagoonInstall.cmake")
    endif()
  endforeach()
  set(${out_var} ${found} PARENT_SCOPE)
endfunction()

set(exported "")
foreach(root IN LISTS LAGOON_EXPORT_ROOTS)
  _lagoon_export_closure(${root} exported)
endforeach()
set(LAGOON_PLAIN_TARGETS "")
set(LAGOON_VULKAN_TARGETS "")
foreach(target IN LISTS exported)
  _lagoon_find_vulkan(${target} ${target} vulkan_path)  # cmake/LagoonLayering.cmake
  if(vulkan_path)
    list(APPEND LAGOON_VULKAN_TARGETS ${target})
  else()
    list(APPEND LAGOON_PLAIN_TARGETS ${target})
  endif()
endforeach()
foreach(target lagoon_ocean lagoon_optics lagoon_world)
  if(NOT target IN_LIST LAGOON_PLAIN_TARGETS)
    message(FATAL_ERROR "LagoonInstall: ${target} reaches Vulkan, but hosts must be able to use it without")
  endif()
endforeach()

# Optionally every module above in one shared library, liblagoon.so (Lagoon::shared), built from the static
# modules' own objects, so nothing is compiled twice; they are then compiled as position-independent code.
# A host links either Lagoon::shared or the static targets, never both (every symbol would be twice).
option(LAGOON_BUILD_SHARED "Also build and install liblagoon.so (Lagoon::shared): every module in one library" OFF)
if(LAGOON_BUILD_SHARED)
  set(objects "")
  set(header_targets "")
  foreach(target IN LISTS exported)
    get_target_property(type ${target} TYPE)
    if(type STREQUAL "STATIC_LIBRARY")
      set_property(TARGET ${target} PROPERTY POSITION_INDEPENDENT_CODE ON)
      list(APPEND objects $<TARGET_OBJECTS:${target}>)
    elseif(type STREQUAL "INTERFACE_LIBRARY")
      list(APPEND header_targets ${target})  # core, vk_headers, ...: include paths and definitions
    endif()
  endforeach()
  add_library(lagoon_shared SHARED ${objects})
  set_target_properties(lagoon_shared PROPERTIES OUTPUT_NAME lagoon LINKER_LANGUAGE CXX
                        VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
  # What the objects call (private: resolved inside liblagoon.so) and what its headers need (interface).
  target_link_libraries(lagoon_shared PRIVATE lagoon_codecs Vulkan::Vulkan Threads::Threads
                        INTERFACE ${header_targets} glm::glm nlohmann_json::nlohmann_json Threads::Threads)
  list(APPEND LAGOON_VULKAN_TARGETS lagoon_shared)
endif()

# Rewrites a target's interface so it can be exported: include directories in the source or build tree
# become $<BUILD_INTERFACE:...> plus include/lagoon once installed, and build-only helpers (a static
# library's PRIVATE links arrive here as $<LINK_ONLY:...>) are kept for this build only. The build itself
# sees exactly the same requirements as before.
function(_lagoon_prepare_export target)
  get_target_property(dirs ${target} INTERFACE_INCLUDE_DIRECTORIES)
  if(dirs)
    set(rewritten "")
    foreach(dir IN LISTS dirs)
      if(dir MATCHES "^\\$<")
        list(APPEND rewritten "${dir}")
      else()
        list(APPEND rewritten "$<BUILD_INTERFACE:${dir}>")
      endif()
    endforeach()
    list(APPEND rewritten "$<INSTALL_INTERFACE:${LAGOON_INSTALL_INCLUDEDIR}>")
    set_property(TARGET ${target} PROPERTY INTERFACE_INCLUDE_DIRECTORIES "${rewritten}")
  endif()

  get_target_property(libs ${target} INTERFACE_LINK_LIBRARIES)
  if(libs)
    set(rewritten "")
    foreach(lib IN LISTS libs)
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" name "${lib}")
      if(name IN_LIST LAGOON_BUILD_ONLY_TARGETS)
        list(APPEND rewritten "$<BUILD_INTERFACE:${lib}>")
        if(name STREQUAL "lagoon_codecs")
          list(APPEND rewritten "$<INSTALL_INTERFACE:$<LINK_ONLY:Lagoon::codecs>>")
        endif()
      else()
        list(APPEND rewritten "${lib}")
      endif()
    endforeach()
    set_property(TARGET ${target} PROPERTY INTERFACE_LINK_LIBRARIES "${rewritten}")
  endif()

  # Lagoon::ocean rather than Lagoon::lagoon_ocean.
  string(REGEX REPLACE "^lagoon_" "" export_name ${target})
  set_property(TARGET ${target} PROPERTY EXPORT_NAME ${export_name})
endfunction()

foreach(target IN LISTS LAGOON_PLAIN_TARGETS LAGOON_VULKAN_TARGETS)
  _lagoon_prepare_export(${target})
endforeach()

foreach(set_name Plain Vulkan)
  string(TOUPPER ${set_name} upper)
  install(TARGETS ${LAGOON_${upper}_TARGETS}
          EXPORT Lagoon${set_name}Targets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(EXPORT Lagoon${set_name}Targets
          NAMESPACE Lagoon::
          FILE Lagoon${set_name}Targets.cmake
          DESTINATION ${LAGOON_INSTALL_CMAKEDIR})
endforeach()

# Headers, laid out as the include roots of this tree (engine/, compute/, shaders/) so the same #include
# lines work: "vk/context.h", "ocean/wave_query.h", "shared/ocean.h". engine/window is the demo's.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/engine/ ${PROJECT_SOURCE_DIR}/compute/
        DESTINATION ${LAGOON_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.h"
        PATTERN "window" EXCLUDE
        PATTERN "data" EXCLUDE)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/shaders/shared DESTINATION ${LAGOON_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.h")
# The generated declarations of the embedded shaders (lagoon_shaders/shaders.h), for hosts that build their
# own pipelines from them. No installed header includes it.
get_target_property(shader_dirs lagoon_shaders INTERFACE_INCLUDE_DIRECTORIES)
foreach(dir IN LISTS shader_dirs)
  string(REGEX REPLACE "^\\$<BUILD_INTERFACE:(.*)>$" "\\1" dir "${dir}")
  if(EXISTS "${dir}/lagoon_shaders/shaders.h")
    install(FILES ${dir}/lagoon_shaders/shaders.h DESTINATION ${LAGOON_INSTALL_INCLUDEDIR}/lagoon_shaders)
  endif()
endforeach()

# The codec libraries' directory at build time: a hint for LagoonConfig.cmake's search.
list(GET JPEG_LINK_LIBRARIES 0 jpeg_library)
get_filename_component(LAGOON_CODECS_LIBRARY_DIR "${jpeg_library}" DIRECTORY)

# Component names (export names) for LagoonConfig.cmake.
set(LAGOON_PLAIN_COMPONENTS "")
set(LAGOON_VULKAN_COMPONENTS "")
foreach(set_name PLAIN VULKAN)
  foreach(target IN LISTS LAGOON_${set_name}_TARGETS)
    get_target_property(name ${target} EXPORT_NAME)
    list(APPEND LAGOON_${set_name}_COMPONENTS ${name})
  endforeach()
  list(JOIN LAGOON_${set_name}_COMPONENTS " " LAGOON_${set_name}_COMPONENTS)
endforeach()

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/LagoonConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/LagoonConfig.cmake
                              INSTALL_DESTINATION ${LAGOON_INSTALL_CMAKEDIR})
# 0.x: a minor version may break the API, so only 0.1.y satisfies find_package(Lagoon 0.1).
write_basic_package_version_file(${PROJECT_BINARY_DIR}/LagoonConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION}
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/LagoonConfig.cmake ${PROJECT_BINARY_DIR}/LagoonConfigVersion.cmake
        DESTINATION ${LAGOON_INSTALL_CMAKEDIR})

# pkg-config (docs/embedding.md): lagoon-ocean, lagoon-optics and lagoon-physics need no Vulkan; lagoon is everything. The
# libraries are static, so each file lists its archives in link order (users before what they use) and the
# system libraries they pull in. The prefix is found from the .pc file's own place, so
# `cmake --install --prefix` anywhere gives working files.
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}" OR IS_ABSOLUTE "${CMAKE_INSTALL_INCLUDEDIR}")
  # Absolute directories (-DCMAKE_INSTALL_LIBDIR=/...) cannot move with the prefix.
  set(LAGOON_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
  set(LAGOON_PC_LIBDIR "${CMAKE_INSTALL_FULL_LIBDIR}")
  set(LAGOON_PC_INCLUDEDIR "${CMAKE_INSTALL_FULL_INCLUDEDIR}")
else()
  file(RELATIVE_PATH up "/root/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/root")
  string(REGEX REPLACE "/$" "" up "${up}")
  set(LAGOON_PC_PREFIX "\${pcfiledir}/${up}")
  set(LAGOON_PC_LIBDIR "\${prefix}/${CMAKE_INSTALL_LIBDIR}")
  set(LAGOON_PC_INCLUDEDIR "\${prefix}/${CMAKE_INSTALL_INCLUDEDIR}")
endif()
get_target_property(core_definitions lagoon_core INTERFACE_COMPILE_DEFINITIONS)
set(LAGOON_PC_CFLAGS "-I\${includedir}/lagoon")
foreach(definition IN LISTS core_definitions)
  string(APPEND LAGOON_PC_CFLAGS " -D${definition}")
endforeach()

function(_lagoon_pkg_config file description requires libs)
  set(LAGOON_PC_NAME ${file})
  set(LAGOON_PC_DESCRIPTION "${description}")
  set(LAGOON_PC_REQUIRES "${requires}")
  set(LAGOON_PC_LIBS "${libs}")
  configure_file(${PROJECT_SOURCE_DIR}/cmake/lagoon.pc.in ${PROJECT_BINARY_DIR}/pkgconfig/${file}.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/pkgconfig/${file}.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
endfunction()

_lagoon_pkg_config(lagoon-ocean "Lagoon's FFT ocean and WaveQuery, plain C++ (no Vulkan)" "glm"
                   "-llagoon_ocean -llagoon_fft_cpu -pthread")
_lagoon_pkg_config(lagoon-optics "Lagoon's spectral water-colour model, plain C++ (no Vulkan)" "glm"
                   "-llagoon_optics")
_lagoon_pkg_config(lagoon-physics "Lagoon's floating bodies, plain C++ (no Vulkan)" "glm" "-llagoon_physics")
_lagoon_pkg_config(lagoon "Lagoon: ocean simulation and rendering on Vulkan (every module)"
                   "lagoon-ocean lagoon-optics lagoon-physics vulkan nlohmann_json libpng libjpeg libwebp nettle"
                   "-llagoon_dataset -llagoon_render -llagoon_world -llagoon_ocean_gpu -llagoon_fft -llagoon_gltf -llagoon_scene -llagoon_io -llagoon_shaders -llagoon_vk -pthread")
