# SPDX-License-Identifier: GPL-3.0-or-later
# The version and the commit the code is built from.
#
# include()d: medialaxis_source_commit(<var>) sets <var> to the commit's
# short hash, with "-modified" when tracked files differ from it, or
# "unknown" outside a git checkout.
# Run as a script (cmake -DSOURCE_DIR=... -DVERSION=... -DOUTPUT=... -P):
# writes the header OUTPUT with MEDIALAXIS_VERSION and MEDIALAXIS_COMMIT,
# touching it only when they change, so that a build after a commit
# recompiles only what reports them.
function(medialaxis_source_commit output source_dir)
  set(commit "unknown")
  find_program(MEDIALAXIS_GIT git)
  if (MEDIALAXIS_GIT)
    execute_process(COMMAND "${MEDIALAXIS_GIT}" -C "${source_dir}" rev-parse --short=12 HEAD
      OUTPUT_VARIABLE hash OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE failed
      ERROR_QUIET)
    if (NOT failed AND hash)
      set(commit "${hash}")
      execute_process(COMMAND "${MEDIALAXIS_GIT}" -C "${source_dir}" diff --quiet HEAD --
        RESULT_VARIABLE modified ERROR_QUIET)
      if (modified)
        string(APPEND commit "-modified")
      endif ()
    endif ()
  endif ()
  set(${output} "${commit}" PARENT_SCOPE)
endfunction()

if (CMAKE_SCRIPT_MODE_FILE AND OUTPUT)
  medialaxis_source_commit(MEDIALAXIS_COMMIT "${SOURCE_DIR}")
  set(MEDIALAXIS_VERSION "${VERSION}")
  configure_file("${CMAKE_CURRENT_LIST_DIR}/MedialAxisVersion.h.in" "${OUTPUT}" @ONLY)
endif ()
