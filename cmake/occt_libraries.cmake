# OpenCASCADE's libraries by name, for the optional peer benchmarks (bench/peers, bench/step_check):
# Debian's CMake config of OCCT 7.6 also demands libtbb-dev and other optional components' files,
# which these programs do not use. occt_libraries(OUT TK...) sets OUT to the toolkits' paths.
function(occt_libraries out)
  set(paths)
  foreach(tk ${ARGN})
    find_library(OCCT_${tk} NAMES ${tk} REQUIRED)
    list(APPEND paths ${OCCT_${tk}})
  endforeach()
  set(${out} ${paths} PARENT_SCOPE)
endfunction()
