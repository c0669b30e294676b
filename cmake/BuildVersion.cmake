# Run at every build (cmake -P): writes hil_build_version.hpp with the
# project version and the git commit the build came from, rewriting the file
# only when the text changes (no needless rebuilds). A tree without git says
# "unknown"; uncommitted changes add "-dirty".
execute_process(COMMAND git -C ${SOURCE_DIR} rev-parse --short=12 HEAD
                OUTPUT_VARIABLE hash OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE failed)
if(failed OR hash STREQUAL "")
  set(hash "unknown")
else()
  execute_process(COMMAND git -C ${SOURCE_DIR} status --porcelain --untracked-files=no
                  OUTPUT_VARIABLE changes OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(NOT changes STREQUAL "")
    set(hash "${hash}-dirty")
  endif()
endif()
set(text "#pragma once\n#define HIL_GIT_HASH \"${hash}\"\n#define HIL_PROJECT_VERSION \"${VERSION}\"\n")
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} old)
endif()
if(NOT old STREQUAL text)
  file(WRITE ${OUTPUT} "${text}")
endif()
