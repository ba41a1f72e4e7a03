# Helpers of the test scripts that start long runs in the background and stop
# them (sourced after script_helpers.bash; not a test itself): background jobs
# are killed at exit, prm files of the default scene with a small voltage
# increment, waiting for printed steps, and a wait with a time limit.

trap 'kill $(jobs -p) 2> /dev/null; rm -rf "$work"' EXIT

# prm NAME INCREMENT [MASS] [EXTRA]: the default scene into out/long.h5, with
# EXTRA (printf %b text) appended
prm() {
  sed -e 's/set Directory           = results/set Directory           = out/' \
      -e 's/set Base name           = default/set Base name           = long/' \
      -e "s/set Mass (g)            = 280/set Mass (g)            = ${3:-280}/" \
      "$src/prm/default.prm" > "$1"
  printf 'subsection Solver\n  set Voltage increment (kV) = %s\nend\n%b' "$2" "${4:-}" >> "$1"
}

# with_sigint COMMAND...: COMMAND with SIGINT's default action; a background job
# of a script starts with SIGINT ignored, and cdea keeps an ignored signal
# ignored (as under nohup), so that `kill -INT` would not stop it. Use as
# `( with_sigint "$exe" run ... ) > out &`.
with_sigint() { trap - INT; exec "$@"; }

steps_printed() { grep -cE '^ +[0-9]+ +(pre-stretch|dead load|voltage) ' "$1"; }

wait_for_steps() { # FILE N: until N step lines are printed (at most 60 s)
  for _ in $(seq 600); do [ "$(steps_printed "$1")" -ge "$2" ] && return 0; sleep 0.1; done
  return 1
}

# bounded_wait PID: its exit code; killed (exit 137) if it runs over 300 s.
# The state comes from /proc (procps' ps is not on every Debian system).
bounded_wait() {
  local state
  for _ in $(seq 3000); do
    state=$(sed 's/.*) //' "/proc/$1/stat" 2> /dev/null | cut -d' ' -f1)
    case "$state" in "" | Z) break ;; esac # ended (a zombie until waited for)
    sleep 0.1
  done
  kill -KILL "$1" 2> /dev/null
  wait "$1"
}
