#!/usr/bin/env bash
# The tests' cdea fork server and client (tests/cdea_forks.bash) stand in for
# the executable: the same output and exit code as the real program, stdout
# closed as in the program (exit 2), the caller's umask and environment, a signal
# forwarded, death by a signal passed on, the command killed when its client
# is, and the server single-threaded when it forks.
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/long_runs.bash"
source "$(dirname "$0")/cdea_forks.bash"

same() { # NAME COMMAND...: real and forked, the same stdout, stderr, exit code
  local name=$1; shift
  "$real_exe" "$@" > real.out 2> real.err; local real=$?
  "$exe" "$@" > fork.out 2> fork.err; local fork=$?
  if [ $real -eq $fork ] && cmp -s real.out fork.out && cmp -s real.err fork.err; then
    ok "$name: exit $fork, the same output"
  else fail "$name: exit $real against $fork; $(diff real.out fork.out) $(diff real.err fork.err)"; fi
}
same "--version" --version
same "a missing parameter file" run missing.prm

"$exe" --version >&- 2> fork.err; rc=$?
[ $rc -eq 2 ] && grep -q "cannot write to standard output: it was closed" fork.err \
  && ok "stdout closed: exit 2, $(head -c 80 fork.err)" || fail "stdout closed: exit $rc, $(cat fork.err)"

[ "$(ls /proc/$cdea_forks_server/task | wc -l)" -eq 1 ] \
  && ok "the server has one thread" || fail "the server has $(ls /proc/$cdea_forks_server/task | wc -l) threads"

# umask and environment: a results file under umask 077, no progress lines.
sed 's/set Directory           = results/set Directory           = masked/' "$src/prm/default.prm" > masked.prm
(umask 077; CDEA_PROGRESS=off "$exe" run masked.prm > masked.out 2> masked.err); rc=$?
mode=$(stat -c %a masked/default.h5 2> /dev/null)
[ $rc -eq 0 ] && [ "$mode" = 600 ] && ok "umask 077: exit 0, results file mode $mode" \
  || fail "umask 077: exit $rc, mode $mode, $(cat masked.err)"

# SIGTERM forwarded: the run stops at a step and says so (exit 2).
prm long.prm 0.0005
"$exe" run long.prm > term.out 2> term.err & pid=$!
wait_for_steps term.out 3; kill -TERM $pid; bounded_wait $pid; rc=$?
[ $rc -eq 2 ] && grep -q "interrupted by SIGTERM" term.err && ok "SIGTERM forwarded: exit 2, $(head -c 80 term.err)" \
  || fail "SIGTERM: exit $rc, $(cat term.err)"

# Death by a signal passed on: SIGQUIT (no handler in cdea) ends the client
# too (no core files: the limit goes to the command as well).
rm -rf out; (ulimit -c 0; exec "$exe" run long.prm) > quit.out 2> quit.err & pid=$!
wait_for_steps quit.out 3; kill -QUIT $pid; bounded_wait $pid 2> /dev/null; rc=$?
[ $rc -eq 131 ] && ok "SIGQUIT: the client ends killed by SIGQUIT (exit $rc)" || fail "SIGQUIT: exit $rc"

# The client killed (SIGKILL is not forwarded): the command dies with it.
rm -rf out; "$exe" run long.prm > kill.out 2> kill.err & pid=$!
wait_for_steps kill.out 3; command=$(cat out/long.h5.lock 2> /dev/null)
kill -KILL $pid; wait $pid 2> /dev/null
for _ in $(seq 100); do [ -e "/proc/$command" ] || break; sleep 0.02; done
[ -n "$command" ] && [ ! -e "/proc/$command" ] && ok "client killed: its command (pid $command) is gone" \
  || fail "client killed: the command (pid '$command') still runs"
finish
