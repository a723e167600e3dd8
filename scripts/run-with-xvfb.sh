#!/bin/sh
# Runs a command under an X server of its own: Debian's VTK and ParaView render only through X.
#
#   sh scripts/run-with-xvfb.sh COMMAND [ARGUMENT...]
#
# Like `xvfb-run -a`, without its race: xvfb-run picks the first display number whose lock file
# is absent from /tmp (:99 nearly always) and starts Xvfb there, so two runs in containers that
# share a network namespace (each its own /tmp, one abstract socket namespace) both take :99, and
# the client may reach the other's server ("bad X server connection"). Here Xvfb itself picks a
# display with -displayfd: one whose lock file and every socket, the abstract one included, it
# could take, and it tells the number only once it accepts connections. -noreset: by default the
# server resets each time its last client disconnects, and a client that connects during the reset
# is dropped; pvbatch opens and closes several connections in a row (its capability probes), so its
# next XOpenDisplay failed ("bad X server connection", 13 of 20 runs of TestFeaturePointsPlugin
# with three busy loops beside it; none of 20 with -noreset). The exit code is the command's; 1
# when the server does not start.
set -u
if [ "$#" -eq 0 ]; then
  echo "usage: sh $0 COMMAND [ARGUMENT...]" >&2
  exit 2
fi
if ! command -v Xvfb >/dev/null 2>&1; then
  echo "run-with-xvfb: Xvfb not found (Debian package xvfb)" >&2
  exit 1
fi
dir=$(mktemp -d "${TMPDIR:-/tmp}/run-with-xvfb.XXXXXX") || exit 1
# The file exists before the server starts: the shell opens it for Xvfb in the background.
: >"$dir/display"
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp -noreset 3>"$dir/display" >"$dir/log" 2>&1 &
server=$!
cleanup() {
  kill "$server" 2>/dev/null
  wait "$server" 2>/dev/null
  rm -rf "$dir"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# The number comes as one line once the server listens; wait up to 60 s for it.
tries=600
while [ "$(wc -l <"$dir/display")" -lt 1 ]; do
  if ! kill -0 "$server" 2>/dev/null || [ "$tries" -le 0 ]; then
    echo "run-with-xvfb: Xvfb did not start; its output:" >&2
    cat "$dir/log" >&2
    exit 1
  fi
  tries=$((tries - 1))
  sleep 0.1
done
display=$(head -n 1 "$dir/display")
case "$display" in
  '' | *[!0-9]*)
    echo "run-with-xvfb: Xvfb gave no display number ('$display')" >&2
    exit 1
    ;;
esac

DISPLAY=":$display" "$@"
status=$?
if [ "$status" -ne 0 ] && ! kill -0 "$server" 2>/dev/null; then
  echo "run-with-xvfb: Xvfb on :$display exited while the command ran; its output:" >&2
  cat "$dir/log" >&2
fi
exit "$status"
