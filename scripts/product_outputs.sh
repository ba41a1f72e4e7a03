#!/usr/bin/env bash
# Every product of every prm/ example, as a build of cdea makes it: each
# command on each example it serves, its results files, its printed output and
# its exit code in a folder per case, and the Python module's results of the
# same cases (scripts/python_products.py). Two such folders, made by two builds,
# are compared by scripts/compare_products.py (doc/architecture.md, "One table
# of quantities, one product per study").
#
#   bash scripts/product_outputs.sh BUILD_DIR OUT_DIR [CASE ...]
#
# BUILD_DIR holds the program `cdea` and the module in python/; OUT_DIR is made
# (an existing one is refused). CASE names (such as run-default) pick cases;
# none runs them all. The time runs and the design studies are shortened
# with --set where the example would take minutes (the same settings for
# every build), so that the whole set takes a few minutes.
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "usage: bash scripts/product_outputs.sh BUILD_DIR OUT_DIR [CASE ...]" >&2
  exit 1
fi
src="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "$1" && pwd)"
out="$2"
shift 2
if [ -e "$out" ]; then
  echo "product_outputs: '$out' exists; name a new folder" >&2
  exit 1
fi
mkdir -p "$out"
out="$(cd "$out" && pwd)"
python="${PYTHON:-/usr/bin/python3}"

# One case a line: name | command | prm (relative to prm/) | data file or - | --set words
cases() {
  cat <<'EOF'
run-default|run|default.prm|-|
run-partitioned-rv1.7|run|partitioned-rv1.7.prm|-|
run-fold-full|run|fold-full.prm|-|
run-fold-rv1.7|run|fold-rv1.7.prm|-|
run-relaxed-full|run|relaxed-full.prm|-|
run-relaxed-rv1.7|run|relaxed-rv1.7.prm|-|
run-relaxed-low-prestretch|run|relaxed-low-prestretch.prm|-|
run-pump|run|pump.prm|-|
run-paraview|run|paraview.prm|-|
run-staircase-full|run|staircase-full.prm|-|--set Time/Time step (s)=1
run-staircase-rv1.7|run|staircase-rv1.7.prm|-|--set Time/Time step (s)=1
run-shear-thinning|run|shear-thinning.prm|-|--set Time/Time step (s)=1
run-pump-time|run|pump-time.prm|-|--set Time/Cycles=1
run-spectrum|run|spectrum.prm|-|--set Time/Cycles=1
run-response|run|response.prm|-|
shoot-default|shoot|default.prm|-|
shoot-partitioned-rv1.7|shoot|partitioned-rv1.7.prm|-|
shoot-fold-full|shoot|fold-full.prm|-|
shoot-pump|shoot|pump.prm|-|
shoot-relaxed-rv1.7|shoot|relaxed-rv1.7.prm|-|
compare-default|compare|default.prm|-|
compare-partitioned-rv1.7|compare|partitioned-rv1.7.prm|-|
compare-pump|compare|pump.prm|-|
sweep-inner5|sweep|sweep-inner5.prm|-|
sweep-inner5.5|sweep|sweep-inner5.5.prm|-|
sweep-refined-inner5|sweep|sweep-refined-inner5.prm|-|
optimize-paper|optimize|optimize-paper.prm|-|
optimize-rings|optimize|optimize-rings.prm|-|--set Optimization/Starts=2
optimize-field|optimize|optimize-field.prm|-|--set Optimization/Starts=2
fit-example|fit|fit-example.prm|fit-example.csv|
fit-creep|fit|fit-creep.prm|fit-creep.csv|
fit-dma|fit|fit-dma.prm|fit-dma.csv|
chart-default|chart|default.prm|-|
chart-response|chart|response.prm|-|
chart-spectrum|chart|spectrum.prm|-|
chart-shear-thinning|chart|shear-thinning.prm|-|
response-response|response|response.prm|-|
frequency-sweep|frequency-sweep|frequency-sweep.prm|-|
recover-fold-rv1.7|recover|fold-rv1.7.prm|-|
EOF
}

wanted() {
  [ $# -eq 0 ] && return 0
  local c
  for c in "$@"; do [ "$c" = "$name" ] && return 0; done
  return 1
}

# What differs between any two runs of the same build is masked: wall times
# (and a frequency sweep's seconds per frequency before its "k/N"), and the
# number of checkpoints, which are taken by the clock.
mask_times() {
  sed -E -e '/( ms| s|wall time|[0-9] s on |left\)?$| s in all| s$)/ s/[0-9]+(\.[0-9]+)?(e[-+]?[0-9]+)? ?(ms|s)\b/<time>/g' \
         -e 's/[0-9.]+( +[0-9]+\/[0-9]+, )/<time>\1/' \
         -e 's/[0-9]+ checkpoints/<n> checkpoints/'
}

cases | while IFS='|' read -r name command prm data sets; do
  wanted "$@" || continue
  dir="$out/$name"
  mkdir -p "$dir"
  args=("$command" "prm/$prm")
  [ "$data" != - ] && args+=("prm/$data")
  extra=()
  if [ -n "$sets" ]; then
    extra=(--set "${sets#--set }")
  fi
  output=(--set "Output/Directory=$dir/files")
  if [ "$command" = recover ]; then
    # A run of the example killed after its 50th step (its journal cut
    # there, the same for every build), then `cdea recover` of its file.
    results="$dir/files/${prm%.prm}.h5"
    (cd "$src" && CDEA_CHECKPOINT_SECONDS=1e9 "$python" scripts/killed_run_journal.py \
       "$build/cdea" "prm/$prm" 50 "$results" "$results.journal" \
       --set "Output/Directory=$dir/files") || echo "$name: no journal to recover"
    args=(recover "$results")
    output=()
  fi
  start=$(date +%s.%N)
  set +e
  # From the source folder, as the examples' relative table files expect.
  (cd "$src" && "$build/cdea" "${args[@]}" "${extra[@]}" "${output[@]}" \
      > "$dir/stdout.raw" 2> "$dir/stderr.raw")
  rc=$?
  set -e
  end=$(date +%s.%N)
  mask_times < "$dir/stdout.raw" > "$dir/stdout.txt"
  mask_times < "$dir/stderr.raw" | sed "s|$dir|<case>|g; s|$src|<src>|g" > "$dir/stderr.txt"
  sed -i "s|$dir|<case>|g; s|$src|<src>|g" "$dir/stdout.txt"
  rm -f "$dir/stdout.raw" "$dir/stderr.raw"
  echo "$rc" > "$dir/exit_code"
  printf '%-28s exit %s  %6.1f s\n' "$name" "$rc" "$(echo "$end - $start" | bc)"
  PYTHONPATH="$build/python" "$python" "$src/scripts/python_products.py" \
    "$command" "prm/$prm" "$data" "$sets" "$dir/python.pickle" "$src" \
    > "$dir/python.txt" 2>&1 || echo "python: see $dir/python.txt"
done
