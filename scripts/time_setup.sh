#!/usr/bin/env bash
# Times the two commands of README.md ("Set up, build and run the default
# case" and "... the whole test suite") each on its own clean clone of this
# repository's HEAD, as a new user types them, and prints the wall time of
# each and of its build part (scripts/setup.sh). Packages already installed
# are not reinstalled; nothing is cached between the clones (no compiler
# cache is configured by scripts/setup.sh).
#
#   bash scripts/time_setup.sh [run|test|both]     (default: both)
#
# The clones go to a temporary folder that is removed at the end.
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$(pwd)
which="${1:-both}"
case "$which" in
  run|test|both) ;;
  *) echo "time_setup: unknown argument '$which' (allowed: run, test, both)" >&2; exit 1 ;;
esac

# The README's commands, read from the file itself so that they cannot drift.
run_command=$(grep -m1 '^bash scripts/setup.sh.*build/cdea run' README.md)
test_command=$(grep -m1 '^bash scripts/setup.sh.*ctest' README.md)
[ -n "$run_command" ] && [ -n "$test_command" ] || {
  echo "time_setup: README.md has no run or test command starting with 'bash scripts/setup.sh'" >&2
  exit 1
}

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { s = b - a; printf "%d min %04.1f s (%.1f s)", s / 60, s - 60 * int(s / 60), s }'; }

time_command() {
  local name=$1 command=$2 clone="$scratch/$1"
  git clone -q "$repo" "$clone"
  echo "== $name: $command"
  local setup=${command%% && *} rest=${command#* && }
  local t0 t1 t2
  t0=$(now)
  (cd "$clone" && bash -c "$setup") > "$scratch/$name.log" 2>&1 || {
    tail -20 "$scratch/$name.log"; echo "time_setup: $name: set-up failed" >&2; exit 1; }
  t1=$(now)
  (cd "$clone" && bash -c "$rest") >> "$scratch/$name.log" 2>&1 || {
    tail -20 "$scratch/$name.log"; echo "time_setup: $name: the command failed" >&2; exit 1; }
  t2=$(now)
  echo "   set-up and build: $(elapsed "$t0" "$t1")"
  echo "   then the rest:    $(elapsed "$t1" "$t2")"
  echo "   in all:           $(elapsed "$t0" "$t2")"
}

echo "time_setup: $(nproc) cores, HEAD $(git rev-parse --short HEAD)"
[ "$which" = test ] || time_command run "$run_command"
[ "$which" = run ] || time_command test "$test_command"
