# Writes BuildInfo.cpp with the current git revision at every build (cmake -P). Inputs:
# SOURCE_DIR, TEMPLATE, OUTPUT, PROJECT_VERSION. The file is replaced only when its text
# changes, so an unchanged revision rebuilds nothing.
execute_process(COMMAND git -C ${SOURCE_DIR} describe --always --dirty
                OUTPUT_VARIABLE MPMFOAM_GIT OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT MPMFOAM_GIT)
  set(MPMFOAM_GIT "unknown")
endif()
configure_file(${TEMPLATE} ${OUTPUT}.tmp @ONLY)
file(COPY_FILE ${OUTPUT}.tmp ${OUTPUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUTPUT}.tmp)
