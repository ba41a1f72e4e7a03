# The cdea executable without its start-up at every call (sourced by a test
# script after script_helpers.bash and, if it uses them, long_runs.bash and
# python_forks.bash; not a test itself): one fork server
# (tests/cdea_fork_server.cc) loads what the executable is made of once, and
# "$exe" becomes its client (tests/cdea_fork_client.cc), which has each call
# run in a fork of the server with the caller's arguments, folder,
# environment, descriptors, limits and signal dispositions, forwards
# SIGINT/SIGTERM/SIGHUP/SIGQUIT and ends as the command ended. A call then
# costs a fork instead of the 0.2-0.3 s of CPU of loading deal.II.
# "$real_exe" stays the executable itself, for what must be the real process:
# a kill -KILL (not forwarded), its pid, its start. Under mpirun the client
# execs the real executable itself.
real_exe=$exe
cdea_forks=$(mktemp -d)
# Every symbol bound once in the server (LD_BIND_NOW), not again by the
# dynamic loader's lazy lookups in each fork (about 6 % of a fork's CPU time
# and a tenth of its page faults, measured on fuzz_prm).
LD_BIND_NOW=1 "${CDEA_FORK_SERVER:?}" "$cdea_forks/socket" > /dev/null &
cdea_forks_server=$!
# (every job waited for, the server too, so that its CPU time and its
# forks' count in the test's)
trap 'kill $(jobs -p) 2> /dev/null; wait 2> /dev/null; rm -rf "$work" "$cdea_forks" ${python_forks:+"$python_forks"}' EXIT
for _ in $(seq 1200); do
  [ -S "$cdea_forks/socket" ] || ! kill -0 $cdea_forks_server 2> /dev/null && break
  sleep 0.05
done
[ -S "$cdea_forks/socket" ] || { echo "FAIL the cdea fork server did not start"; exit 1; }
export CDEA_FORK_SOCKET="$cdea_forks/socket" CDEA_FORK_EXECUTABLE="$real_exe"
exe=${CDEA_FORK_CLIENT:?}
