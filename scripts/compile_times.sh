#!/usr/bin/env bash
# CPU seconds per translation unit of a clean build (no compiler cache):
# configures a scratch build folder whose compiler launcher records the user
# + system time of every compiler call, builds TARGET (default: cdea) and
# prints the translation units, most expensive first, with the sum.
#
#   bash scripts/compile_times.sh [TARGET [TOP]]     (defaults: cdea 10)
#
# Environment: BUILD_DIR (default: a new temporary folder, removed at the
# end), JOBS (default 2). CPU time per unit is the figure to compare on a
# shared machine; the wall time of a -jN build is roughly the sum / N.
set -euo pipefail
cd "$(dirname "$0")/.."
target="${1:-cdea}"
top="${2:-10}"
jobs="${JOBS:-2}"
if [ -n "${BUILD_DIR:-}" ]; then
  build_dir="$BUILD_DIR"
  keep=1
else
  build_dir=$(mktemp -d /tmp/cdea-compile-times.XXXXXX)
  keep=0
fi
log="$build_dir/compile_times.log"
launcher="$build_dir/timed_compile.sh"
mkdir -p "$build_dir"
# The launcher: runs the compiler under /usr/bin/time and appends
# "user system object" to the log (the object follows -o).
cat > "$launcher" <<LAUNCHER
#!/usr/bin/env bash
object=unknown
previous=
for a in "\$@"; do
  [ "\$previous" = "-o" ] && object="\$a"
  previous="\$a"
done
exec /usr/bin/time -a -o "$log" -f "%U %S \$object" "\$@"
LAUNCHER
chmod +x "$launcher"
rm -f "$log"
export CCACHE_DISABLE=1
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_COMPILER_LAUNCHER="$launcher" > /dev/null
start=$(date +%s)
cmake --build "$build_dir" -j "$jobs" --target "$target" 2>&1 | grep -E "warning|error" || true
end=$(date +%s)
# One line per object (and precompiled header); link lines name no .o.
awk '$3 ~ /\.(o|gch|pch)$/ {
       name = $3; sub(/.*CMakeFiles\/[^\/]*\.dir\//, "", name); sub(/\.o$/, "", name)
       printf "%.2f %s\n", $1 + $2, name }' "$log" | sort -rn > "$log.sorted"
printf "%8s  %s\n" "CPU (s)" "translation unit"
head -n "$top" "$log.sorted" | awk '{ printf "%8.1f  %s\n", $1, $2 }'
awk -v wall=$((end - start)) '{ sum += $1; n++ }
  END { printf "%8.1f  sum of %d units (wall of the build: %d s)\n", sum, n, wall }' "$log.sorted"
[ "$keep" = 1 ] || rm -rf "$build_dir"
