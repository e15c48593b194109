# Build step (cmake -P): writes OUT = the git revision of SRC as a C macro, and only when it
# changed, so a commit or an edit renames the revision in run directories and reports
# without rebuilding anything but apps/ppsynth/revision.cpp.
execute_process(COMMAND git -C ${SRC} describe --always --dirty
                OUTPUT_VARIABLE rev OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT rev)
  set(rev unknown)
endif()
set(content "#define PPSYNTH_REVISION \"${rev}\"\n")
set(old "")
if(EXISTS ${OUT})
  file(READ ${OUT} old)
endif()
if(NOT old STREQUAL content)
  file(WRITE ${OUT} "${content}")
endif()
