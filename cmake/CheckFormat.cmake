# ctest style.ClangFormat: fails listing the files that differ from .clang-format's style.
file(GLOB_RECURSE files ${SOURCE_DIR}/engine/*.cpp ${SOURCE_DIR}/engine/*.h ${SOURCE_DIR}/compute/*.cpp
     ${SOURCE_DIR}/compute/*.h ${SOURCE_DIR}/apps/*.cpp ${SOURCE_DIR}/apps/*.h ${SOURCE_DIR}/tests/*.cpp
     ${SOURCE_DIR}/tests/*.h ${SOURCE_DIR}/shaders/shared/*.h ${SOURCE_DIR}/examples/*.cpp
     ${SOURCE_DIR}/examples/*.h)
set(bad)
foreach(f IN LISTS files)
  execute_process(COMMAND ${CLANG_FORMAT} --dry-run --Werror ${f} RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
  if(NOT rc EQUAL 0)
    list(APPEND bad ${f})
  endif()
endforeach()
if(bad)
  list(JOIN bad "\n  " listing)
  message(FATAL_ERROR "not formatted (run 'make format'):\n  ${listing}")
endif()
