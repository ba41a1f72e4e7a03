#!/usr/bin/env bash
# Safe in a shared results folder (issue 31, items 3 and 4): a symbolic link,
# a FIFO or a device node placed at any name a command creates (the results
# file, its .tmp, .lock, .journal, the checkpoint <stem>.partial.h5 and its
# .tmp, the ParaView collection, its folder and their partial names,
# _fit.prm, _optimum.prm) makes the command refuse with exit 1, naming it,
# before any work; the link's target, the FIFO and the device stay as they
# were. A hard link at the lock's name is refused too (it would be truncated);
# a leftover regular .tmp is cdea's own and is replaced. Every command's
# refusal is a fork of one loaded program (tests/cdea_forks.bash): seconds.
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/cdea_forks.bash"
cp -r "$src/prm" prm
mkdir victim-folder
echo "another user's file" > victim.txt
echo "another user's file" > victim-folder/kept.txt
victim=$(sha256sum victim.txt victim-folder/kept.txt)
quick=(--set 'Solver/Voltage increment (kV)=1')

# the commands and the names they create (relative to results/)
run_names="default.h5 default.h5.tmp default.h5.lock default.h5.journal default.partial.h5 default.partial.h5.tmp"
paraview_names="paraview.pvd paraview.pvd.tmp paraview.partial.pvd paraview.partial.pvd.tmp paraview_vtu paraview_vtu.partial paraview_vtu.older"
declare -A commands=(
  [run]="run prm/default.prm"
  [paraview]="run prm/paraview.prm"
  [sweep]="sweep prm/sweep-inner5.prm"
  [chart]="chart prm/default.prm"
  [response]="response prm/response.prm"
  [frequency-sweep]="frequency-sweep prm/frequency-sweep.prm"
  [fit]="fit prm/fit-example.prm prm/fit-example.csv"
  [optimize]="optimize prm/optimize-paper.prm"
)
declare -A names=(
  [run]="$run_names"
  [paraview]="$paraview_names"
  [sweep]="sweep-inner5_map.h5 sweep-inner5_map.h5.tmp sweep-inner5_map.h5.lock sweep-inner5_map.partial.h5"
  [chart]="default_chart.h5.tmp default_chart.h5.lock"
  [response]="response_response.h5 response_response.h5.tmp response_response.h5.lock"
  [frequency-sweep]="frequency-sweep_frequency_sweep.h5.tmp frequency-sweep_frequency_sweep.h5.lock"
  [fit]="fit-example_fit.h5.tmp fit-example_fit.prm fit-example_fit.prm.tmp fit-example_fit.partial.prm"
  [optimize]="optimize-paper_optimum.h5.lock optimize-paper_optimum.prm optimize-paper_optimum.prm.tmp"
)

# refused LABEL NAME COMMAND...: exit 1 within 60 s, the name in the message,
# nothing but the planted name in results/
refused() {
  local label=$1 name=$2; shift 2
  timeout 60 "$exe" "$@" "${quick[@]}" > out.txt 2> err.txt
  local rc=$? left
  left=$(ls -A results | grep -vx -- "$name")
  if [ $rc -eq 1 ] && grep -q -- "$name" err.txt && [ -z "$left" ]; then
    return 0
  fi
  fail "$label at results/$name: exit $rc, left [$left], $(head -c 300 err.txt)"
  return 1
}

# 1. Symbolic links at every name to a file of someone else's (and at the
#    folders' names and the results file to a folder).
for command in "${!commands[@]}"; do
  count=0
  for name in ${names[$command]}; do
    targets=../victim.txt
    [[ $name == *_vtu* || $name == default.h5 ]] && targets="../victim.txt ../victim-folder"
    for target in $targets; do
      rm -rf results && mkdir results && ln -s "$target" "results/$name"
      refused "$command: a link to $target" "$name" ${commands[$command]} || continue
      [ "$(readlink "results/$name")" = "$target" ] && count=$((count + 1)) \
        || fail "$command: the link results/$name was changed"
    done
  done
  [ "$(sha256sum victim.txt victim-folder/kept.txt)" = "$victim" ] \
    && ok "$command: a link at each of ${names[$command]// /, } refused (exit 1, named), the $count links and their targets untouched" \
    || fail "$command: a link target changed"
done
grep -h "symbolic link" err.txt > /dev/null && ok "the last message: $(head -c 160 err.txt)"

# 2. FIFOs and (as root) copies of /dev/null's device node at a name of each
#    kind (tests/test_results_file_limits.cc puts both at every side name of
#    the file layer).
for name in default.h5 default.h5.lock default.h5.journal default.partial.h5 paraview.pvd \
            fit-example_fit.prm optimize-paper_optimum.prm; do
  case $name in paraview*) command=paraview ;; fit*) command=fit ;; optimize*) command=optimize ;;
                *) command=run ;; esac
  rm -rf results && mkdir results && mkfifo "results/$name"
  refused "$command: a FIFO" "$name" ${commands[$command]} && [ -p "results/$name" ] \
    || fail "$command: the FIFO results/$name was changed"
  if [ "$(id -u)" = 0 ] && [[ $name == default.h5* ]]; then
    rm -rf results && mkdir results && mknod "results/$name" c 1 3
    refused "$command: a device" "$name" ${commands[$command]} \
      && [ "$(stat -c %t,%T "results/$name")" = "1,3" ] \
      || fail "$command: the device node results/$name was changed"
  fi
done
ok "FIFOs (and, as root, device nodes) at the results file, lock, journal, checkpoint, ParaView collection, _fit.prm and _optimum.prm: refused, untouched: $(head -c 140 err.txt)"

# 3. A hard link at the lock's name (it would be truncated to a pid).
rm -rf results && mkdir results && ln victim.txt results/default.h5.lock
refused "run: a hard link" default.h5.lock ${commands[run]} \
  && grep -q "a hard link to another file" err.txt \
  && [ "$(sha256sum victim.txt victim-folder/kept.txt)" = "$victim" ] \
  && ok "a hard link at the lock refused: $(head -c 140 err.txt)"

# 4. A leftover regular temporary file is cdea's own: replaced, the run works.
rm -rf results && mkdir results && echo leftover > results/default.h5.tmp
"$exe" run prm/default.prm "${quick[@]}" > out.txt 2> err.txt
rc=$?
[ $rc -eq 0 ] && [ -s results/default.h5 ] && [ "$(ls results)" = default.h5 ] \
  && ok "a leftover regular default.h5.tmp: replaced, exit 0, nothing else left" \
  || fail "leftover tmp: exit $rc, $(ls results), $(cat err.txt)"

# 5. A link placed at the lock while a run holds it (the lock's own name is
#    checked by inode when it is released): the run ends, the link stays.
rm -rf results
sed 's/set Directory           = results/set Directory = held/' prm/default.prm > held.prm
"$real_exe" run held.prm --set 'Solver/Voltage increment (kV)=0.01' > held.out 2>&1 &
pid=$!
for _ in $(seq 600); do [ -e held/default.h5.lock ] && break; sleep 0.05; done
mv held/default.h5.lock held/moved.lock && ln -s ../victim.txt held/default.h5.lock
wait $pid
[ -L held/default.h5.lock ] && [ "$(sha256sum victim.txt victim-folder/kept.txt)" = "$victim" ] \
  && [ -s held/default.h5 ] \
  && ok "a link put in place of a held lock: the run wrote its file, the link and its target stay" \
  || fail "a link at a held lock: $(ls -l held), $(tail -2 held.out)"

# 6. The Python module's write() (item 4): an empty name, a FIFO, a copy of
#    /dev/full's device node (as root) and links at the file, its .tmp and
#    its .lock refused with an OSError naming what is there; nothing left in
#    the working folder (no .journal), each planted name as it was.
rm -rf py && mkdir py
PYTHONPATH="$(dirname "$real_exe")/python" "$PYTHON" - "$src/prm/default.prm" <<'PY' > py.txt 2>&1
import os, stat, sys
import cdea
r = cdea.run(sys.argv[1], overrides={"Solver/Voltage increment (kV)": 1})
os.chdir("py")
problems = []
def refused(path, words):
    try:
        r.write(path)
    except OSError as e:
        if words not in str(e):
            problems.append(f"{path!r}: {e}")
        else:
            print(f"write({path!r}): {e}")
        return
    problems.append(f"{path!r} was written")
refused("", "names no file")
os.mkfifo("fifo.h5")
refused("fifo.h5", "it is a FIFO")
if os.geteuid() == 0:
    os.mknod("full.h5", 0o644 | stat.S_IFCHR, os.makedev(1, 7))
    refused("full.h5", "it is a device")
with open("../victim.txt") as f:
    before = f.read()
for name in ("link.h5", "tmp.h5.tmp", "lock.h5.lock"):
    os.symlink("../victim.txt", name)
refused("link.h5", "it is a symbolic link")
refused("tmp.h5", "tmp.h5.tmp")
refused("lock.h5", "lock.h5.lock")
with open("../victim.txt") as f:
    if f.read() != before:
        problems.append("a link's target changed")
planted = {"fifo.h5": stat.S_ISFIFO, "link.h5": stat.S_ISLNK, "tmp.h5.tmp": stat.S_ISLNK,
           "lock.h5.lock": stat.S_ISLNK}
if os.geteuid() == 0:
    planted["full.h5"] = stat.S_ISCHR
for name, kind in planted.items():
    if not kind(os.lstat(name).st_mode):
        problems.append(f"{name} changed")
left = sorted(set(os.listdir(".")) - set(planted))
if left:
    problems.append(f"left behind: {left}")
if problems:
    print("\n".join(problems))
    sys.exit(1)
PY
[ $? -eq 0 ] && ok "write(): '', a FIFO, a device (as root) and links at the file, .tmp, .lock refused, nothing left: $(head -c 200 py.txt | tr '\n' ' ')" \
  || fail "write() on hostile names: $(cat py.txt)"

finish
