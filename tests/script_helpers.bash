# The common start of the test scripts (sourced; not a test itself): the
# program and the source folder from ctest's environment, a temporary working
# folder that is the current one and is removed at exit, and ok/fail lines
# with a count of the failures that finish() turns into the exit status.
set -u
exe="${CDEA_EXECUTABLE:?}"
src="${CDEA_SOURCE_DIR:?}"
PYTHON=${PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
ok() { echo "ok   $*"; }
finish() { echo "$failures failed"; [ $failures -eq 0 ]; }
