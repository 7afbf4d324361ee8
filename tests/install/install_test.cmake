# The installed package as a host sees it (cmake/LagoonInstall.cmake, docs/embedding.md). Run by ctest
# (tests/CMakeLists.txt) after the build, as `cmake -DSTEP=... -P install_test.cmake`:
#   STEP=install     cmake --install the build into WORK_DIR/prefix (a fresh copy each run)
#   STEP=embed       configure and build examples/embed against that prefix with find_package(Lagoon),
#                    run embed_ocean and embed_render (the host's own device on DEVICE, validation on: any
#                    validation error fails) and compare its frame with `lagoon render`'s; link
#                    embed_render again from lagoon.pc's flags; build and run adopt_check/
#                    (Context::adopt's refusals and ownership)
#   STEP=no-vulkan   build embed_ocean and embed_world with only Lagoon::ocean and Lagoon::world, Vulkan's
#                    find module disabled and a
#                    vulkan/vulkan.h that #errors first on the include path, through CMake and through
#                    lagoon-ocean.pc; run it
# Build folders under WORK_DIR are kept between runs, so a rerun only rebuilds what changed.
# Inputs: BUILD_DIR SOURCE_DIR WORK_DIR GENERATOR CXX CONFIG DEVICE PKG_CONFIG SCENE LAGOON (the CLI).
cmake_minimum_required(VERSION 3.25)

set(prefix ${WORK_DIR}/prefix)
set(example ${SOURCE_DIR}/examples/embed)
set(poison ${SOURCE_DIR}/cmake/poison_vulkan)

# Runs a command; on failure stops with its output, so the ctest log says what broke.
function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT status EQUAL 0)
    list(JOIN ARGN " " command)
    message(FATAL_ERROR "${what} failed (${status}):\n${command}\n${out}")
  endif()
  message(STATUS "${what}: ok")
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

# Configures (first run) and builds the project in `source` in WORK_DIR/<dir> against the prefix.
function(build_against_prefix source dir)
  run_step("configure ${dir}"
           ${CMAKE_COMMAND} -S ${source} -B ${WORK_DIR}/${dir} -G ${GENERATOR} -DCMAKE_BUILD_TYPE=${CONFIG}
           -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF ${ARGN})
  # The package must come from this prefix, not from a Lagoon installed elsewhere on the machine.
  file(STRINGS ${WORK_DIR}/${dir}/CMakeCache.txt lagoon_dir REGEX "^Lagoon_DIR:")
  string(FIND "${lagoon_dir}" "${prefix}/" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${source} found Lagoon outside ${prefix}: ${lagoon_dir}")
  endif()
  run_step("build ${dir}" ${CMAKE_COMMAND} --build ${WORK_DIR}/${dir} --parallel 2)
endfunction()

# The pkg-config directory of the prefix (lib/ or lib/<multiarch>/, as GNUInstallDirs chose).
function(find_pc_dir out)
  file(GLOB_RECURSE pc_files ${prefix}/*/lagoon-ocean.pc)
  if(NOT pc_files)
    message(FATAL_ERROR "no lagoon-ocean.pc under ${prefix}")
  endif()
  list(GET pc_files 0 pc)
  get_filename_component(dir ${pc} DIRECTORY)
  set(${out} ${dir} PARENT_SCOPE)
endfunction()

# `pkg-config --cflags --libs <module>` as a list of arguments.
function(pkg_config_flags module out)
  find_pc_dir(pc_dir)
  set(ENV{PKG_CONFIG_PATH} ${pc_dir})
  run_step("pkg-config ${module}" ${PKG_CONFIG} --cflags --libs ${module})
  string(STRIP "${step_output}" flags)
  separate_arguments(flags UNIX_COMMAND "${flags}")
  set(${out} ${flags} PARENT_SCOPE)
endfunction()

if(STEP STREQUAL "install")
  file(REMOVE_RECURSE ${prefix})  # a fresh prefix: files removed from the tree must not linger there
  run_step("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --config ${CONFIG} --prefix ${prefix})
  foreach(f include/lagoon/ocean/wave_query.h include/lagoon/vk/context.h include/lagoon/render/ocean_renderer.h
            include/lagoon/shared/ocean.h)
    if(NOT EXISTS ${prefix}/${f})
      message(FATAL_ERROR "cmake --install did not install ${f}")
    endif()
  endforeach()
  file(GLOB_RECURSE configs ${prefix}/*/LagoonConfig.cmake)
  if(NOT configs)
    message(FATAL_ERROR "cmake --install did not install LagoonConfig.cmake")
  endif()
  # The Python module, when built, lands in the interpreter's packages under the prefix and imports from there.
  if(PYTHON)
    set(ENV{PYTHONPATH} ${prefix}/${PYTHON_DIR})
    run_step("import the installed lagoon module" ${PYTHON} -c
             "import lagoon, os; assert os.path.dirname(lagoon.__file__) == os.environ['PYTHONPATH'], lagoon.__file__")
  endif()

elseif(STEP STREQUAL "embed")
  if(NOT EXISTS "${LAGOON}")
    message(FATAL_ERROR "${LAGOON} is missing: build the whole tree (cmake --build) before ctest")
  endif()
  build_against_prefix(${example} embed)
  build_against_prefix(${CMAKE_CURRENT_LIST_DIR}/adopt_check adopt-check)
  run_step("embed_ocean" ${WORK_DIR}/embed/embed_ocean)
  message(STATUS "${step_output}")
  # The suite's environment (tests/support/test_main.cpp): validation on, the test device unless
  # LAGOON_DEVICE says otherwise, caches inside the build tree.
  set(ENV{LAGOON_VALIDATION} 1)
  if(NOT DEFINED ENV{LAGOON_DEVICE})
    set(ENV{LAGOON_DEVICE} ${DEVICE})
  endif()
  if(NOT DEFINED ENV{LAGOON_PIPELINE_CACHE})
    set(ENV{LAGOON_PIPELINE_CACHE} ${BUILD_DIR}/test-artifacts/pipeline-cache)
  endif()
  file(MAKE_DIRECTORY $ENV{LAGOON_PIPELINE_CACHE})  # Mesa's shader cache stays where Mesa keeps it
  run_step("adopt_check on $ENV{LAGOON_DEVICE} with validation" ${WORK_DIR}/adopt-check/adopt_check)
  message(STATUS "${step_output}")
  file(REMOVE ${WORK_DIR}/embed.png)
  run_step("embed_render on $ENV{LAGOON_DEVICE} with validation"
           ${WORK_DIR}/embed/embed_render ${SCENE} ${WORK_DIR}/embed.png 320 180)
  message(STATUS "${step_output}")
  if(NOT EXISTS ${WORK_DIR}/embed.png)
    message(FATAL_ERROR "embed_render exited 0 but wrote no ${WORK_DIR}/embed.png")
  endif()
  # Drawn into the host's images, the frame must be the one Lagoon draws into its own (`lagoon render`, same
  # scene, size and time), within the golden tests' tolerance.
  run_step("lagoon render" ${LAGOON} render --scene ${SCENE} --out ${WORK_DIR}/lagoon.png --width 320 --height 180)
  run_step("embed.png matches lagoon render's frame" ${LAGOON} compare-images ${WORK_DIR}/embed.png
           ${WORK_DIR}/lagoon.png --diff ${WORK_DIR}/embed-diff.png)
  message(STATUS "${step_output}")
  # lagoon.pc must list every archive and system library, in an order a static link accepts: link the
  # object CMake compiled with those flags alone.
  pkg_config_flags(lagoon lagoon_flags)
  run_step("link embed_render from lagoon.pc"
           ${CXX} ${WORK_DIR}/embed/CMakeFiles/embed_render.dir/embed_render.cpp.o -o ${WORK_DIR}/embed_render_pc
           ${lagoon_flags})

elseif(STEP STREQUAL "no-vulkan")
  # CMAKE_DISABLE_FIND_PACKAGE_Vulkan: the configure fails if LagoonConfig.cmake looks for Vulkan at all.
  build_against_prefix(${example} ocean-only -DEMBED_OCEAN_ONLY=ON -DCMAKE_DISABLE_FIND_PACKAGE_Vulkan=ON
                -DEMBED_POISON_INCLUDE_DIR=${poison})
  run_step("embed_ocean (CMake, no Vulkan)" ${WORK_DIR}/ocean-only/embed_ocean)
  # Lagoon::world steps the harbour's bodies and vehicles (glTF hulls, the floor, the wakes they feel).
  run_step("embed_world (CMake, no Vulkan)" ${WORK_DIR}/ocean-only/embed_world ${SOURCE_DIR}/scenes/harbour.json)
  foreach(name buoy boat auv)
    if(NOT step_output MATCHES "\"${name}\"")
      message(FATAL_ERROR "embed_world printed no pose of '${name}':\n${step_output}")
    endif()
  endforeach()
  pkg_config_flags(lagoon-ocean ocean_flags)
  if(ocean_flags MATCHES "vulkan")
    message(FATAL_ERROR "lagoon-ocean.pc brings in Vulkan: ${ocean_flags}")
  endif()
  run_step("compile embed_ocean from lagoon-ocean.pc (no Vulkan)"
           ${CXX} -std=c++20 -O1 -I${poison} ${example}/ocean_query.cpp -o ${WORK_DIR}/embed_ocean_pc ${ocean_flags})
  run_step("embed_ocean (pkg-config, no Vulkan)" ${WORK_DIR}/embed_ocean_pc)

else()
  message(FATAL_ERROR "install_test.cmake: STEP must be install, embed or no-vulkan (got '${STEP}')")
endif()
