#!/usr/bin/env bash
# doc/architecture.md names every file of source/, include/, python/ and
# benchmarks/ (in backquotes; `dir/name.{h,cc}` names both), and marks with
# "(deal.II)" the line of every source file that includes deal.II, so that the
# list cannot fall behind the code.
source "$(dirname "$0")/script_helpers.bash"
"$PYTHON" - "$src" <<'PY'
import os, re, sys
root = sys.argv[1]
doc = open(os.path.join(root, "doc", "architecture.md")).read().split("\n")

def expand(token):
    m = re.search(r"\{([^{}]*)\}", token)
    if not m:
        return [token]
    out = []
    for part in m.group(1).split(","):
        out += expand(token[:m.start()] + part.strip() + token[m.end():])
    return out

named = {}  # name -> the doc lines naming it
for number, line in enumerate(doc):
    for token in re.findall(r"`([^`]+)`", line):
        for name in expand(token):
            named.setdefault(name, []).append(number)

def doc_name(path):
    if path.startswith("source/"):
        return path[len("source/"):]
    if path.startswith("include/cdea/"):
        return path[len("include/cdea/"):]
    return path

failures = 0
checked = 0
for top in ("source", "include", "python", "benchmarks"):
    for folder, _, files in os.walk(os.path.join(root, top)):
        for f in sorted(files):
            path = os.path.relpath(os.path.join(folder, f), root)
            if f == "CMakeLists.txt" or "__pycache__" in path:
                continue
            checked += 1
            name = doc_name(path)
            if name not in named:
                print(f"FAIL {path}: not named in doc/architecture.md (as `{name}`)")
                failures += 1
                continue
            text = open(os.path.join(root, path), errors="replace").read()
            if top in ("source", "include") and "#include <deal.II/" in text:
                if not any("(deal.II)" in doc[n] for n in named[name]):
                    print(f"FAIL {path} includes deal.II: its line lacks the mark (deal.II)")
                    failures += 1
print(f"{checked} files checked, {failures} problems")
sys.exit(1 if failures else 0)
PY
status=$?
[ $status -eq 0 ] && ok "doc/architecture.md names every file" || fail "doc/architecture.md is behind the code"
finish
