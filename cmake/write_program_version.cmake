# Writes OUTPUT (program_version.cpp) from TEMPLATE with the source tree's
# `git describe` as it is now. Run by the build at every build (the target
# ffp_program_version), not by the configure step: a commit or an edit after
# configuring changes the version string the program reports. configure_file
# rewrites OUTPUT only when its text changes, so an unchanged tree recompiles
# nothing.
execute_process(COMMAND git describe --always --dirty --tags
                WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE FFP_GIT_DESCRIBE OUTPUT_STRIP_TRAILING_WHITESPACE
                ERROR_QUIET)
if(NOT FFP_GIT_DESCRIBE)
  set(FFP_GIT_DESCRIBE "unknown")
endif()
configure_file(${TEMPLATE} ${OUTPUT} @ONLY)
