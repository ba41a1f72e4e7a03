"""pytest's set-up of the Python tests (tests/test_*.py): when ctest names
the cdea fork server and client (CDEA_FORK_SERVER, CDEA_FORK_CLIENT; see
tests/cdea_forks.bash), the tests' `CDEA_EXECUTABLE` calls run in forks of one
loaded program: the server starts before the test files are read, and
CDEA_EXECUTABLE becomes its client (the executable stays in
CDEA_FORK_EXECUTABLE, which the client execs under mpirun). At the end the
server is stopped and waited for, so that its forks' CPU time counts here."""
import os
import shutil
import subprocess
import tempfile
import time


def pytest_configure(config):
    server, client = os.environ.get("CDEA_FORK_SERVER"), os.environ.get("CDEA_FORK_CLIENT")
    exe = os.environ.get("CDEA_EXECUTABLE")
    if not (server and client and exe):
        return
    folder = tempfile.mkdtemp(prefix="cdea-forks-")
    path = os.path.join(folder, "socket")
    process = subprocess.Popen([server, path], stdout=subprocess.DEVNULL)
    for _ in range(1200):
        if os.path.exists(path) or process.poll() is not None:
            break
        time.sleep(0.05)
    if not os.path.exists(path):
        raise RuntimeError("the cdea fork server did not start")
    os.environ.update(CDEA_FORK_SOCKET=path, CDEA_FORK_EXECUTABLE=exe, CDEA_EXECUTABLE=client)
    config.cdea_forks = (process, folder)


def pytest_unconfigure(config):
    process, folder = getattr(config, "cdea_forks", (None, None))
    if process is not None:
        process.terminate()
        process.wait()
        shutil.rmtree(folder, ignore_errors=True)
