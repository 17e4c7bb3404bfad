#!/bin/sh
# Runs a test command under its own Xvfb (xvfb-run -a) for the tests that render with X: the
# executor of metrofit_add_test(... XVFB) and screenshots_test's `metrofit --screenshots` runs.
#
# ctest runs several of them at once. The display search starts at a number derived from this
# process (xvfb-run -a -n N) so parallel runs rarely race for the same display, and when xvfb-run
# itself fails (its own "xvfb-run: error: ..." line, e.g. "problem while cleaning up temporary
# directory", seen once on a fresh-clone CI run) the command runs once more: that is the wrapper's
# environment, not the behaviour under test. The command's stderr is passed on after it ends.
err=$(mktemp) || exit 1
attempt=1
while :; do
  xvfb-run -a -n $((200 + ($$ % 400) * 2 + attempt)) -s "-screen 0 1280x1024x24" "$@" 2>"$err"
  rc=$?
  if [ "$attempt" -ge 2 ] || ! grep -q '^xvfb-run: error:' "$err"; then
    cat "$err" >&2
    rm -f "$err"
    exit "$rc"
  fi
  attempt=$((attempt + 1))
done
