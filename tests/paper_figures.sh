#!/usr/bin/env bash
# postprocess/paper_figures.py --quick: runs cdea for every figure, writes the
# seven PNGs, and prints the comparison with the paper's experiments. The two
# measured increases are computed from the red line, which cdea sweep locates
# by root finding (independent of the map's grid), so the numbers must equal
# the independent values of bench_failure_modes (doc/validation.md, section
# 5): +54.01 % at r_v/a = 1.4 over both rings at 5.0 kV, +19.44 % at 1.7 over
# both at 5.5 kV, stroke 5.5448 mm at 5 kV; the displacement including the sag
# rises by +12.59 % and +5.56 %; the pump's levels of figure 11 (30.6 and
# 42.1 mm, doc/pump.md). Also: bad --only, a bad CSV and a CSV naming a figure
# no points are drawn on give exit 1 and a message, and write nothing.
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/python_forks.bash"
source "$(dirname "$0")/cdea_forks.bash"

script="$src/postprocess/paper_figures.py"
if "$PYTHON" "$script" --quick --cdea "$exe" --work "$work/runs" --out "$work/figs" \
     --measured "$src/postprocess/paper_measured.csv" > "$work/out.txt" 2> "$work/err.txt"; then
  ok "paper_figures.py --quick exits 0"
else
  fail "paper_figures.py exit status"; cat "$work/err.txt"
fi
for n in 3 4 6 7 8 9 11; do
  f="$work/figs/paper-fig$n.png"
  [ -s "$f" ] && [ "$(head -c 4 "$f" | tail -c 3)" = "PNG" ] && ok "paper-fig$n.png written" ||
    fail "paper-fig$n.png missing or not a PNG"
done
grep -q "both rings at 5.0 kV: 5.5448 mm" "$work/out.txt" &&
  ok "stroke with both rings at 5 kV: 5.5448 mm" || fail "stroke at 5 kV: $(grep 'both rings' "$work/out.txt")"
line=$(grep "measured (paper, section 4)" "$work/out.txt")
case "$line" in
  *"over both at 5.0 kV -> cdea +54.01 %"*"over both at 5.5 kV -> cdea +19.44 %"*)
    ok "experiments: $line" ;;
  *) fail "experiments line: '$line'" ;;
esac
grep -q "sag under the weight: +12.59 % at r_v/a = 1.4 over both at 5.0 kV, +5.56 % at 1.7" \
  "$work/out.txt" && ok "displacement with the sag: +12.59 %, +5.56 %" ||
  fail "sag line: '$(grep 'sag under' "$work/out.txt")'"
grep -q "inner 4.0 kV, outer 4.0 kV: 30.6 mm" "$work/out.txt" &&
  grep -q "inner 4.0 kV, outer 5.0 kV: 42.1 mm" "$work/out.txt" &&
  ok "figure 11 levels: 30.6 and 42.1 mm" || fail "figure 11 levels: $(grep -A3 'Figure 11' "$work/out.txt")"
grep -A2 "Figure 9:" "$work/out.txt" | grep -q "inner 5 kV: .* mm at r_v/a = " &&
  ok "figure 9 maxima printed" || fail "figure 9 lines: $(grep -A2 'Figure 9' "$work/out.txt")"

"$PYTHON" "$script" --only 5 --cdea "$exe" --work "$work/r2" --out "$work/f2" > /dev/null 2> "$work/e2.txt" &&
  fail "--only 5 exits 0" || { grep -q "no figure 5" "$work/e2.txt" && ok "--only 5 rejected" || fail "message: $(cat "$work/e2.txt")"; }
printf 'figure,series,x,y\n11,bad,four,24\n' > "$work/bad.csv"
"$PYTHON" "$script" --only 11 --measured "$work/bad.csv" --cdea "$exe" --work "$work/r3" --out "$work/f3" \
  > /dev/null 2> "$work/e3.txt" &&
  fail "a bad CSV exits 0" || { grep -q "data line 1" "$work/e3.txt" && ok "bad CSV rejected: $(cat "$work/e3.txt")" || fail "message: $(cat "$work/e3.txt")"; }

printf 'figure,series,x,y\n11,ok,4,24\n5,unknown figure,1,2\n' > "$work/key.csv"
"$PYTHON" "$script" --only 11 --measured "$work/key.csv" --cdea "$exe" --work "$work/r4" --out "$work/f4" \
  > /dev/null 2> "$work/e4.txt" &&
  fail "an unknown figure in the CSV exits 0" ||
  { grep -q "data line 2: figure '5' is not a panel .*3a, 3b, 4a, 4b, 6a, 6b, 7a, 7b, 7c, 7d, 8a, 8b, 9, 11" "$work/e4.txt" &&
    [ ! -e "$work/r4" ] && [ ! -e "$work/f4" ] &&
    ok "unknown figure in the CSV rejected: $(cat "$work/e4.txt")" || fail "message: $(cat "$work/e4.txt")"; }

finish
