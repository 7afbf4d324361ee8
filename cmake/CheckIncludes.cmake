# cmake -DFILES=a;b -DFORBIDDEN="render|dataset" -DWHY="..." -DSTAMP=file -P CheckIncludes.cmake
# Fails, naming the file and the line, when one of FILES includes a header under a FORBIDDEN folder
# (lagoon_forbid_includes in LagoonLayering.cmake); touches STAMP otherwise.
set(broken "")
foreach(file IN LISTS FILES)
  file(STRINGS "${file}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<](${FORBIDDEN})/")
  foreach(line IN LISTS lines)
    string(APPEND broken "\n  ${file}: ${line}")
  endforeach()
endforeach()
if(broken)
  message(FATAL_ERROR "layering: ${WHY}:${broken}\n(docs/architecture.md, Modules)")
endif()
file(TOUCH "${STAMP}")
