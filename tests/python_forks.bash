# Python without its start-up at every call (sourced by a test script after
# script_helpers.bash and long_runs.bash; not a test itself): one interpreter
# loads numpy, h5py, matplotlib and the module cdea once
# (tests/doc_commands.py --python-server) and forks for each "$PYTHON"
# command, which runs in the fork with the caller's arguments, working
# folder, environment, stdin, stdout and stderr and ends with its status;
# `$PYTHON script.py ...`, `$PYTHON -c CODE ...` and `$PYTHON - ... <<EOF`.
# Each call then costs a small client's start instead of the imports' second.
python_forks=$(mktemp -d)
/usr/bin/python3 "$src/tests/doc_commands.py" --python-server "$python_forks/socket" \
  "$(dirname "$exe")" > /dev/null 2>&1 &
python_forks_server=$!
# (waited for, so that its CPU time and its forks' count in the test's)
trap 'kill $(jobs -p) 2> /dev/null; wait $python_forks_server 2> /dev/null; rm -rf "$work" "$python_forks"' EXIT
python_forks_client=$(/usr/bin/python3 -S -E -c 'import sys
sys.path.insert(0, sys.argv[1])
import doc_commands
print(doc_commands.CLIENT)' "$src/tests")
python_fork() {
  DOC_TEST_PYTHON="$python_forks/socket" /usr/bin/python3 -S -E -c "$python_forks_client" "$@"
}
PYTHON=python_fork
