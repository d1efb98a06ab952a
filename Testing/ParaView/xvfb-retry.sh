#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs a command (xvfb-run ...) again, up to three times, when it could not
# connect to its X server: a fresh Xvfb now and then refuses the first client
# on this kind of machine (about one run in six, with ParaView's own sphere
# source as well). Any other failure is reported at once.
status=1
for attempt in 1 2 3; do
  output=$("$@" 2>&1)
  status=$?
  printf '%s\n' "$output"
  case "$output" in
    *"bad X server connection"*) echo "(no X server connection, attempt $attempt of 3)" ;;
    *) exit $status ;;
  esac
done
exit $status
