#!/usr/bin/env bash
# The sample output in doc/usage.md is what the program prints: the indented
# block after "<!-- sample output of: cdea run prm/default.prm -->" must equal
# the output of that command line by line, but for the times on its last two
# lines ("..., 0.013 s", "(0 checkpoints, 0.000 s)") and that of the error
# estimate ("Estimated numerical error (0.0012 s; ...").
source "$(dirname "$0")/script_helpers.bash"
"$exe" run "$src/prm/default.prm" > printed.txt || { echo "FAIL cdea run exited with $?"; exit 1; }
"$PYTHON" - "$src/doc/usage.md" printed.txt <<'PY'
import re, sys
marker = "<!-- sample output of: cdea run prm/default.prm -->"
doc = open(sys.argv[1]).read().split("\n")
if marker not in doc:
    sys.exit(f"FAIL no line '{marker}' in doc/usage.md")
sample = []
for line in doc[doc.index(marker) + 1:]:
    if line.startswith("    ") or line == "":
        sample.append(line[4:])
    else:
        break
while sample and sample[-1] == "":
    sample.pop()
printed = open(sys.argv[2]).read().rstrip("\n").split("\n")
time = re.compile(r"(Newton iterations|checkpoints), [0-9.e+-]+ s(\)?)$")
estimate = re.compile(r"^Estimated numerical error \([0-9.e+-]+ s;")
def masked(line):
    return estimate.sub("Estimated numerical error (<time> s;", time.sub(r"\1, <time> s\2", line))
sample = [masked(l) for l in sample]
printed = [masked(l) for l in printed]
bad = [(k + 1, a, b) for k, (a, b) in enumerate(zip(sample, printed)) if a != b]
if len(sample) != len(printed) or bad:
    print(f"FAIL doc/usage.md shows {len(sample)} lines, the program prints {len(printed)}")
    for k, a, b in bad[:5]:
        print(f"  line {k}:\n    doc:     {a}\n    printed: {b}")
    sys.exit(1)
print(f"ok   the {len(sample)} lines of the sample in doc/usage.md are what cdea prints")
PY
