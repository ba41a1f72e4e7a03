"""Docs as tests: the command blocks of README.md, doc/*.md and
postprocess/README.md run as written, in their order, and the numbers the
docs quote compared with what the commands print.

Conventions (doc/architecture.md, "Docs as tests"):
  ```sh                a block of shell commands to run from the repository
                       root, as written (bash, as if typed: every command runs;
                       one that ends with a status other than 0 fails the block,
                       but grep's 1, no line matched)
  ```pycon             a Python session: the first line starts the interpreter
                       (PYTHONPATH=build/python /usr/bin/python3), then
                       doctest examples (>>> lines and the output they print)
  any other block      (indented, ```text, ```prm, ...) is not run
  <!-- doc-test: expect TEXT -->     after a block: its output holds TEXT
                       (blanks compared as one, and each number of TEXT as the
                       printed one rounded to the digits TEXT quotes); every
                       number of TEXT must also stand in the doc's text or
                       output samples near the marker
  <!-- doc-test: quick 'Sub/Entry=value' ... -->   before a block: in the
                       quick mode (ctest) every `build/cdea` command of the
                       block that reads a parameter file gets these --set
                       overrides (a smaller case); its expects are checked in
                       the full mode only
  <!-- doc-test: allow-exit N,... --> before a block: its commands may end
                       with these statuses too (a run that stops at a fold: 2);
                       any other non-zero status of a command fails the block
  <!-- doc-test: by-hand REASON -->  before a block: not run in the quick
                       mode (only its shell syntax and the files it names
                       are checked), run in the full mode
  <!-- doc-test: never REASON -->    the same in both modes: set-up and the
                       whole test suite (scripts/setup.sh, ctest), which build
                       and test the repository itself

Each document runs in a scratch copy of the repository (prm/, postprocess/,
scripts/, doc/ copied or linked; build/ linked, with build/cdea a wrapper
that adds the quick overrides), so `results/` starts empty, as in a fresh
clone.

In the quick mode `build/cdea` runs in a fork of one loaded cdea program
(tests/cdea_forks.bash: the fork server and its client; under mpirun the
executable itself), and `/usr/bin/python3` in a block is a shell function that
hands the script to a Python process which has numpy, h5py, matplotlib and
the module cdea loaded already and forks for each script (the same
interpreter and modules, without their second of start-up each time); the
full mode starts the executable and the interpreter every time, as typed.

Usage: doc_commands.py SOURCE_DIR BUILD_DIR [--full] [--keep] [DOC.md ...]
(default: every document; --full: every block at its full size, and a
fresh interpreter per Python command; --keep: leave the scratch directories
for a look).
"""
import array
import json
import socket
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

MARKER = re.compile(r"<!--\s*doc-test:\s*(\w[\w-]*)\s*(.*?)\s*-->", re.S)
FENCE = re.compile(r"^( {0,3})```(\w*)\s*$")  # a fence may be indented (in a list item)
NUMBER = re.compile(r"(?<![\w.])[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?(?![\w])")
PYCON_START = "PYTHONPATH=build/python /usr/bin/python3"
NEAR = 40  # lines around an expect marker where its numbers must stand


class Block:
    def __init__(self, doc, line, kind, text):
        self.doc, self.line, self.kind, self.text = doc, line, kind, text
        self.quick = []      # --set overrides in the quick mode
        self.allowed = {0}   # exit statuses its commands may have
        self.by_hand = None  # why it runs in the full mode only
        self.never = None    # why it never runs
        self.expects = []    # (line, text)

    def where(self):
        return f"{self.doc}:{self.line}"


def parse(path, name):
    """The runnable blocks of a document, with their markers."""
    lines = open(path, encoding="utf-8").read().split("\n")
    blocks, pending, prose = [], {}, []
    i = 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if m:
            indent, kind, start, body = len(m.group(1)), m.group(2), i + 1, []
            i += 1
            while i < len(lines) and not lines[i].lstrip(" ").startswith("```"):
                body.append(lines[i][indent:] if lines[i][:indent].isspace() else lines[i])
                i += 1
            if kind in ("sh", "pycon"):
                b = Block(name, start, kind, "\n".join(body) + "\n")
                b.quick = pending.get("quick", [])
                b.allowed = {0} | {int(x) for x in pending.get("allow-exit", "").split(",") if x}
                b.by_hand = pending.get("by-hand")
                b.never = pending.get("never")
                blocks.append(b)
            pending = {}
            i += 1
            continue
        # A marker is a line of its own (one quoted in the text is none).
        for m in [MARKER.fullmatch(lines[i].strip())] if lines[i].strip() else []:
            if m is None:
                continue
            key, value = m.group(1), m.group(2)
            if key == "expect":
                if not blocks:
                    raise SystemExit(f"{name}:{i + 1}: an expect marker before any block")
                blocks[-1].expects.append((i + 1, value))
            elif key == "quick":
                pending["quick"] = shlex.split(value)
            elif key in ("allow-exit", "by-hand", "never"):
                pending[key] = value
            else:
                raise SystemExit(f"{name}:{i + 1}: unknown doc-test marker '{key}'")
        i += 1
    return blocks, lines


def prose_numbers(lines, line):
    """Numbers the doc shows within NEAR lines of @p line: in its text and
    its output samples, not in the blocks that run nor in markers."""
    numbers, runnable = set(), None
    for k, text in enumerate(lines):
        fence = FENCE.match(text) if runnable is None else None
        if fence:
            runnable = fence.group(2) in ("sh", "pycon")
            continue
        if text.lstrip(" ").startswith("```"):
            runnable = None
            continue
        if runnable or abs(k + 1 - line) > NEAR:
            continue
        numbers.update(NUMBER.findall(MARKER.sub("", text)))
    return numbers


def scratch_copy(src, build, work):
    """A repository the commands can write into: copies of what they write
    (doc/), links to the rest, build/ with the cdea wrapper."""
    os.makedirs(work)
    for name in ("prm", "doc"):
        shutil.copytree(os.path.join(src, name), os.path.join(work, name))
    for name in ("postprocess", "scripts", "benchmarks", "tests", "include", "source",
                 "python", "CMakeLists.txt", "README.md"):
        if os.path.exists(os.path.join(src, name)):
            os.symlink(os.path.join(src, name), os.path.join(work, name))
    os.makedirs(os.path.join(work, "build"))
    for name in os.listdir(build):
        if name != "cdea":
            os.symlink(os.path.join(build, name), os.path.join(work, "build", name))
    wrapper = os.path.join(work, "build", "cdea")
    with open(wrapper, "w") as f:
        f.write(f"""#!/bin/bash
# doc test: cdea with the quick overrides of the block (CDEA_DOC_SET, one a line),
# in the quick mode through the fork server (CDEA_FORK_SOCKET; tests/cdea_forks.bash)
cdea={shlex.quote(os.path.join(build, 'cdea'))}
[ -n "${{CDEA_FORK_SOCKET:-}}" ] && cdea={shlex.quote(fork_program(build, 'client'))}
case "$1" in
  run|shoot|compare|sweep|response|frequency-sweep|optimize|fit|chart)
    extra=()
    while IFS= read -r item; do [ -n "$item" ] && extra+=(--set "$item"); done <<< "$CDEA_DOC_SET"
    exec "$cdea" "$@" "${{extra[@]}}" ;;
esac
exec "$cdea" "$@"
""")
    os.chmod(wrapper, 0o755)


PYTHON = "/usr/bin/python3"


def fork_program(build, which):
    """The cdea fork server or client (tests/cdea_fork_server.cc)."""
    return os.path.join(build, "tests", "cdea_fork_" + which)


def python_server(path, build):
    """The Python of the quick mode: loads the heavy modules once, then per
    request (argv, cwd, environment, the caller's stdin/stdout/stderr)
    forks, runs the script or -c code in the child and answers its status."""
    import runpy
    import traceback
    os.environ["MPLBACKEND"] = "Agg"
    import h5py  # noqa: F401 -- loaded for the children
    import matplotlib.pyplot  # noqa: F401
    import numpy  # noqa: F401
    sys.path.insert(0, os.path.join(build, "python"))
    import cdea  # noqa: F401
    server = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    server.bind(path)
    server.listen(4)
    while True:
        connection, _ = server.accept()
        message, fds, _, _ = socket.recv_fds(connection, 1 << 20, 3)
        request = json.loads(message.decode())
        child = os.fork()
        if child == 0:
            for k, fd in enumerate(fds):
                os.dup2(fd, k)
            os.chdir(request["cwd"])
            os.environ.clear()
            os.environ.update(request["env"])
            extra = [os.path.abspath(p) for p in request["env"].get("PYTHONPATH", "").split(":") if p]
            argv, status = request["argv"], 0
            try:
                if argv and argv[0] == "-c":
                    sys.argv = ["-c"] + argv[2:]
                    sys.path[:0] = [""] + extra
                    exec(compile(argv[1], "<string>", "exec"), {"__name__": "__main__"})
                elif argv and argv[0] == "-":  # the script on stdin
                    sys.argv = argv
                    sys.path[:0] = [""] + extra
                    exec(compile(sys.stdin.read(), "<stdin>", "exec"), {"__name__": "__main__"})
                else:
                    sys.argv = argv
                    sys.path[:0] = [os.path.dirname(os.path.abspath(argv[0]))] + extra
                    runpy.run_path(argv[0], run_name="__main__")
            except SystemExit as e:
                status = e.code if isinstance(e.code, int) else (0 if e.code is None else 1)
                if not isinstance(e.code, int) and e.code is not None:
                    print(e.code, file=sys.stderr)
            except BaseException:  # noqa: BLE001 -- as the interpreter reports it
                traceback.print_exc()
                status = 1
            sys.stdout.flush()
            sys.stderr.flush()
            os._exit(status)
        for fd in fds:
            os.close(fd)
        _, code = os.waitpid(child, 0)
        connection.sendall(str(os.waitstatus_to_exitcode(code)).encode())
        connection.close()


CLIENT = """import json, os, socket, sys, time
s = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
for attempt in range(600):  # the server may still be loading its modules
    try:
        s.connect(os.environ["DOC_TEST_PYTHON"])
        break
    except OSError:
        time.sleep(0.05)
request = {"argv": sys.argv[1:], "cwd": os.getcwd(), "env": dict(os.environ)}
socket.send_fds(s, [json.dumps(request).encode()], [0, 1, 2])
sys.exit(int(s.recv(64).decode() or 1))
"""


def shell_python(work):
    """The shell function that sends `/usr/bin/python3 ...` to the server."""
    client = os.path.join(work, ".doc-test-client.py")
    with open(client, "w") as f:
        f.write(CLIENT)
    return (f"{PYTHON}() {{ if [ $# -gt 0 ]; then command {PYTHON} -S -E "
            f"{shlex.quote(client)} \"$@\"; else command {PYTHON}; fi; }}\n")


def run_sh(block, work, full, server=None, cdea_forks=None):
    env = dict(os.environ, **(cdea_forks or {}))
    if server:
        env["DOC_TEST_PYTHON"] = server
    env["CDEA_DOC_SET"] = "" if full else "\n".join(block.quick)
    env.setdefault("MPLBACKEND", "Agg")
    if os.geteuid() == 0:  # an MPI launcher refuses root without these
        env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    # Every command runs, as typed into a shell; the ERR trap notes each that
    # ends with a non-zero status.
    statuses = os.path.join(work, ".doc-test-statuses")
    script = ("set -E -o pipefail\nexec 3> %s\n" % shlex.quote(statuses) +
              (shell_python(work) if server else "") +
              "trap 'echo \"$? $BASH_COMMAND\" >&3' ERR\n" + block.text)
    done = subprocess.run(["bash", "-c", script], cwd=work, env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, timeout=3600)
    # grep's status 1 says that no line matched, which a doc shows, not an error.
    failed = [line for line in open(statuses).read().splitlines()
              if int(line.split(" ", 1)[0]) not in block.allowed
              and not re.match(r"1 grep ", line)]
    os.remove(statuses)
    output = done.stdout.decode(errors="replace")
    if failed:
        return 1, output + "\n" + "\n".join("status " + f for f in failed)
    return 0, output


def run_pycon(block, work):
    first, _, session = block.text.partition("\n")
    if first.strip() != PYCON_START:
        return 1, f"a pycon block must start with '{PYCON_START}', not '{first}'"
    runner = (
        "import doctest, sys\n"
        "text = sys.stdin.read()\n"
        "test = doctest.DocTestParser().get_doctest(text, {}, 'block', 'doc', 0)\n"
        "flags = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE\n"
        "runner = doctest.DocTestRunner(optionflags=flags)\n"
        "runner.run(test)\n"
        "sys.exit(1 if runner.failures else 0)\n")
    env = dict(os.environ, PYTHONPATH="build/python", MPLBACKEND="Agg")
    done = subprocess.run(["/usr/bin/python3", "-c", runner], cwd=work, env=env,
                          input=session.encode(), stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, timeout=600)
    return done.returncode, done.stdout.decode(errors="replace")


def syntax_only(block, work):
    """A by-hand block in the quick mode: bash -n, and every repository file
    it names (prm/..., postprocess/..., scripts/..., benchmarks/...) exists."""
    done = subprocess.run(["bash", "-n", "-c", block.text], stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT)
    if done.returncode:
        return done.returncode, done.stdout.decode(errors="replace")
    for path in re.findall(r"(?<![\w/.])((?:prm|postprocess|scripts|benchmarks)/[\w./-]+)",
                           block.text):
        if not os.path.exists(os.path.join(work, path)):
            return 1, f"the block names {path}, which does not exist"
    return 0, ""


def normalized(text):
    return " ".join(text.split())


def rounds_to(printed, quoted):
    """Whether the printed number, rounded to the digits of the quoted one,
    is the quoted one (2.0 quotes 2, 6.6309 quotes 6.63091)."""
    decimals = len(quoted.split("e")[0].split(".")[1]) if "." in quoted.split("e")[0] else 0
    try:
        a, b = float(printed), float(quoted)
    except ValueError:
        return False
    if "e" in quoted.lower():
        return abs(a - b) <= 0.5 * 10.0 ** (-decimals) * abs(b) * 1.000001 + 1e-300
    return abs(a - b) <= 0.5 * 10.0 ** (-decimals) * 1.000001


def quotes(shown, number):
    """Whether the doc's number @p shown is the expect's @p number: equal, or
    one of them the other rounded to its digits (a quoted 4.26 for 4.2618)."""
    try:
        if float(shown) == float(number):
            return True
    except ValueError:
        return False
    return ("." in number and rounds_to(shown, number)) or ("." in shown and rounds_to(number, shown))


def found(expect, output):
    """Whether the output holds the expect's text, blanks compared as one and
    each number as the output's rounded to the digits the expect quotes."""
    parts, pattern, quoted = NUMBER.split(normalized(expect)), "", NUMBER.findall(normalized(expect))
    for k, part in enumerate(parts):
        pattern += re.escape(part)
        if k < len(quoted):
            pattern += r"([-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?)"
    for m in re.finditer(pattern, normalized(output)):
        if all(rounds_to(p, q) for p, q in zip(m.groups(), quoted)):
            return True
    return False


def check_expects(block, lines, output, full):
    problems = []
    for line, text in block.expects:
        shown = prose_numbers(lines, line)
        missing = [n for n in NUMBER.findall(text) if not any(quotes(p, n) for p in shown)]
        if missing:
            problems.append(f"{block.doc}:{line}: the expect's numbers {missing} stand nowhere "
                            f"in the text within {NEAR} lines")
        if (block.quick or block.by_hand) and not full or block.never:
            continue
        if not found(text, output):
            problems.append(f"{block.doc}:{line}: the output lacks '{text}'")
    return problems


def start_server(build, work, blocks):
    """The Python server, if a block of the document runs Python (the client
    waits for it to listen)."""
    if not any(b.kind == "sh" and PYTHON in b.text and not b.never for b in blocks):
        return None, None
    path = os.path.join(os.path.dirname(work), "python.socket")
    server = subprocess.Popen([PYTHON, os.path.abspath(__file__), "--python-server", path, build])
    return server, path


def start_cdea_server(build, work, blocks):
    """The cdea fork server of the quick mode, if a block runs (the full
    mode runs the executable itself): its process and what the wrapper
    build/cdea and the client need in their environment."""
    if not any(b.kind == "sh" and not b.never and not b.by_hand for b in blocks):
        return None, None
    path = os.path.join(os.path.dirname(work), "cdea.socket")
    server = subprocess.Popen([fork_program(build, "server"), path], stdout=subprocess.DEVNULL)
    for _ in range(1200):
        if os.path.exists(path) or server.poll() is not None:
            break
        time.sleep(0.05)
    if not os.path.exists(path):
        sys.exit("the cdea fork server did not start")
    return server, {"CDEA_FORK_SOCKET": path,
                    "CDEA_FORK_EXECUTABLE": os.path.join(build, "cdea")}


def run_document(src, build, name, full, keep):
    blocks, lines = parse(os.path.join(src, name), name)
    work = os.path.join(tempfile.mkdtemp(prefix="cdea-doc-"), "repo")
    scratch_copy(src, build, work)
    server, socket_path = (None, None) if full else start_server(build, work, blocks)
    cdea_server, cdea_forks = (None, None) if full else start_cdea_server(build, work, blocks)
    failures = 0
    for b in blocks:
        start = time.time()
        if b.never or (b.by_hand and not full):
            rc, out = syntax_only(b, work)
            label = "syntax (%s)" % (b.never or "by hand: " + b.by_hand)
        elif b.kind == "pycon":
            rc, out = run_pycon(b, work)
            label = "pycon"
        else:
            rc, out = run_sh(b, work, full, socket_path, cdea_forks)
            label = "quick" if b.quick and not full else "as written"
        problems = [] if rc == 0 else [f"{b.where()}: a command failed (see the status lines "
                                       "at the end of the output)" if b.kind == "sh" and
                                       not (b.by_hand and not full) else
                                       f"{b.where()}: exit {rc}"]
        problems += check_expects(b, lines, out, full)
        if problems:
            failures += 1
            print(f"FAIL {b.where()} ({label}, {time.time() - start:.1f} s)")
            for p in problems:
                print("     " + p)
            print("     output: " + out[-3000:].replace("\n", "\n     "))
        else:
            print(f"ok   {b.where()} ({label}, {time.time() - start:.1f} s"
                  f"{', %d expects' % len(b.expects) if b.expects else ''})")
    if server:
        server.kill()
        server.wait()
    if cdea_server:
        cdea_server.terminate()  # it waits for its forks: their CPU time counts here
        cdea_server.wait()
    if keep:
        print(f"     scratch copy: {work}")
    else:
        shutil.rmtree(os.path.dirname(work), ignore_errors=True)
    return failures, len(blocks)


def main(argv):
    args = [a for a in argv if not a.startswith("--")]
    src, build, docs = os.path.abspath(args[0]), os.path.abspath(args[1]), args[2:]
    if not docs:
        docs = ["README.md"] + sorted("doc/" + d for d in os.listdir(os.path.join(src, "doc"))
                                      if d.endswith(".md")) + ["postprocess/README.md"]
    failures = total = 0
    for name in docs:
        f, n = run_document(src, build, name, "--full" in argv, "--keep" in argv)
        failures, total = failures + f, total + n
    print(f"{failures} of {total} blocks failed")
    return 1 if failures else 0


if __name__ == "__main__":
    if sys.argv[1] == "--python-server":
        python_server(sys.argv[2], sys.argv[3])
    else:
        sys.exit(main(sys.argv[1:]))
