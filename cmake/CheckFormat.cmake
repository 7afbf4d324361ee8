# ctest style.ClangFormat: fails listing the files that differ from .clang-format's style. One clang-format
# process for every file (one per file took 28 s of the suite, one for all takes 5 s); its diagnostics
# ("<file>:<line>:<col>: error: code should be clang-formatted") name the files.
file(GLOB_RECURSE files ${SOURCE_DIR}/engine/*.cpp ${SOURCE_DIR}/engine/*.h ${SOURCE_DIR}/compute/*.cpp
     ${SOURCE_DIR}/compute/*.h ${SOURCE_DIR}/apps/*.cpp ${SOURCE_DIR}/apps/*.h ${SOURCE_DIR}/tests/*.cpp
     ${SOURCE_DIR}/tests/*.h ${SOURCE_DIR}/shaders/shared/*.h ${SOURCE_DIR}/examples/*.cpp
     ${SOURCE_DIR}/examples/*.h)
execute_process(COMMAND ${CLANG_FORMAT} --dry-run --Werror ${files} RESULT_VARIABLE rc OUTPUT_QUIET
                ERROR_VARIABLE diagnostics)
if(NOT rc EQUAL 0)
  string(REGEX MATCHALL "[^\n]+:[0-9]+:[0-9]+: error: code should be clang-formatted" lines "${diagnostics}")
  set(bad)
  foreach(line IN LISTS lines)
    string(REGEX REPLACE ":[0-9]+:[0-9]+: error: code should be clang-formatted$" "" file "${line}")
    list(APPEND bad ${file})
  endforeach()
  list(REMOVE_DUPLICATES bad)
  if(NOT bad)
    set(bad "clang-format failed (${rc}): ${diagnostics}")
  endif()
  list(JOIN bad "\n  " listing)
  message(FATAL_ERROR "not formatted (run 'make format'):\n  ${listing}")
endif()
