// The tests' cdea fork server: `cdea_fork_server SOCKET` loads the program
// (deal.II and every library the cdea executable links) once, listens on the
// Unix socket SOCKET and, for each request of tests/cdea_fork_client.cc,
// forks a supervisor that forks the command's process. That process takes
// the client's descriptors, folder, arguments, environment, umask, limits
// and signal dispositions and calls cdea::run_program(), the entry point of
// the cdea executable (source/commands/main.cc), then exit() with its code,
// as main() returns it. The supervisor sends the client the command's pid
// (the client forwards signals to it) and, once it ends, its wait status; if
// the client goes away first (killed), the command is killed too. Each call
// then costs a fork instead of the 0.2-0.3 s of CPU of loading deal.II.
// SIGTERM, SIGINT or SIGHUP stop the server: it waits for every fork, so that
// their CPU time counts in the test's (tests/cdea_forks.bash).
// Test-only: no deal.II thread may run when it forks; it checks that it has
// one thread at start, and it starts none (MPI stays off, as in a cdea
// process that no MPI launcher started).

#include <cdea/commands/program.h>

#include "cdea_forks.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <set>
#include <string>
#include <vector>

extern char **environ;

namespace
{
  using cdea_forks::Request;

  volatile std::sig_atomic_t stop_requested = 0;

  extern "C" void request_stop(int) { stop_requested = 1; }

  [[noreturn]] void fail(const char *what)
  {
    std::fprintf(stderr, "cdea_fork_server: %s: %s\n", what, std::strerror(errno));
    _exit(126);
  }

  int count_threads()
  {
    int  n   = 0;
    DIR *dir = opendir("/proc/self/task");
    if (dir == nullptr)
      return -1;
    while (const dirent *entry = readdir(dir))
      if (entry->d_name[0] != '.')
        ++n;
    closedir(dir);
    return n;
  }

  bool read_all(const int fd, void *buffer, std::size_t n)
  {
    auto *p = static_cast<char *>(buffer);
    while (n > 0)
      {
        const ssize_t got = read(fd, p, n);
        if (got < 0 && errno == EINTR)
          continue;
        if (got <= 0)
          return false;
        p += got;
        n -= std::size_t(got);
      }
    return true;
  }

  bool write_int(const int fd, const std::int32_t value)
  {
    return send(fd, &value, sizeof value, MSG_NOSIGNAL) == ssize_t(sizeof value);
  }

  /// The request and its descriptors (received close-on-exec), then its text.
  bool receive(const int connection, Request &request, std::vector<int> &fds, std::string &text)
  {
    char   control[CMSG_SPACE(sizeof(int) * cdea_forks::max_fds)] = {};
    iovec  io{&request, sizeof request};
    msghdr message{};
    message.msg_iov        = &io;
    message.msg_iovlen     = 1;
    message.msg_control    = control;
    message.msg_controllen = sizeof control;
    ssize_t got;
    do
      got = recvmsg(connection, &message, MSG_WAITALL | MSG_CMSG_CLOEXEC);
    while (got < 0 && errno == EINTR);
    if (got != ssize_t(sizeof request) || request.magic != cdea_forks::magic)
      return false;
    for (cmsghdr *c = CMSG_FIRSTHDR(&message); c != nullptr; c = CMSG_NXTHDR(&message, c))
      if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SCM_RIGHTS)
        {
          const std::size_t n = (c->cmsg_len - CMSG_LEN(0)) / sizeof(int);
          fds.resize(n);
          std::memcpy(fds.data(), CMSG_DATA(c), n * sizeof(int));
        }
    if (fds.size() != request.n_fds || request.text_bytes > (std::uint64_t(1) << 30))
      return false;
    text.resize(request.text_bytes);
    return read_all(connection, text.data(), text.size());
  }

  /// The received descriptors at the client's numbers, every other one closed.
  void place_descriptors(const Request &request, const std::vector<int> &fds)
  {
    std::vector<int> moved(fds.size());
    for (std::size_t i = 0; i < fds.size(); ++i)
      if ((moved[i] = fcntl(fds[i], F_DUPFD_CLOEXEC, 1000)) < 0)
        fail("dup");
    std::vector<int> targets(request.fd_numbers, request.fd_numbers + request.n_fds);
    for (std::size_t i = 0; i < fds.size(); ++i)
      if (dup2(moved[i], targets[i]) < 0)
        fail("dup2");
    std::sort(targets.begin(), targets.end());
    unsigned int from = 0;
    for (const int target : targets)
      {
        if (unsigned(target) > from)
          close_range(from, unsigned(target) - 1, 0);
        from = unsigned(target) + 1;
      }
    close_range(from, ~0u, 0);
  }

  /// Dispositions as the client had them (ignored or default), then its mask.
  void set_signals(const Request &request)
  {
    for (int s = 1; s < 65; ++s)
      {
        if (s == SIGKILL || s == SIGSTOP)
          continue;
        struct sigaction action = {};
        action.sa_handler = (request.ignored_signals >> (s - 1)) & 1 ? SIG_IGN : SIG_DFL;
        sigemptyset(&action.sa_mask);
        sigaction(s, &action, nullptr);
      }
    sigset_t mask;
    sigemptyset(&mask);
    for (int s = 1; s < 65; ++s)
      if ((request.blocked_signals >> (s - 1)) & 1)
        sigaddset(&mask, s);
    sigprocmask(SIG_SETMASK, &mask, nullptr);
  }

  /// In the command's fork: becomes the client's command and runs it.
  [[noreturn]] void run_command(const Request &request, const std::vector<int> &fds,
                                const std::string &text, const pid_t supervisor)
  {
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != supervisor)
      _exit(137);
    place_descriptors(request, fds);
    std::string        &kept = *new std::string(text); // never freed, as the words below
    std::vector<char *> words;
    for (std::size_t at = 0; at < kept.size(); at += std::strlen(&kept[at]) + 1)
      words.push_back(&kept[at]);
    if (words.size() != 1 + request.argc + request.envc || chdir(words[0]) != 0)
      fail("the working folder");
    umask(mode_t(request.umask));
    for (int i = 0; i < cdea_forks::n_limits; ++i)
      {
        const rlimit limit{rlim_t(request.limits[i][0]), rlim_t(request.limits[i][1])};
        setrlimit(cdea_forks::limit_resources[i], &limit);
      }
    // Never freed: exit() below runs handlers that may still read environ.
    auto *argv = new std::vector<char *>(words.begin() + 1, words.begin() + 1 + request.argc);
    argv->push_back(nullptr);
    auto *environment = new std::vector<char *>(words.begin() + 1 + request.argc, words.end());
    environment->push_back(nullptr);
    environ = environment->data();
    prctl(PR_SET_NAME, "cdea");
    set_signals(request);
    std::exit(cdea::run_program(int(request.argc), argv->data()));
  }

  /// Waits until the command ends (its status to the client) or the client
  /// goes away (the command killed).
  int wait_for(const pid_t command, const int connection)
  {
    const int pidfd = int(syscall(SYS_pidfd_open, command, 0));
    pollfd    watched[2] = {{connection, POLLIN, 0}, {pidfd, POLLIN, 0}};
    for (;;)
      {
        if (poll(watched, pidfd >= 0 ? 2 : 1, pidfd >= 0 ? -1 : 10) < 0 && errno != EINTR)
          break;
        if (watched[0].revents != 0)
          {
            kill(command, SIGKILL);
            break;
          }
        siginfo_t ended{};
        if (pidfd >= 0 ? watched[1].revents != 0
                       : waitid(P_PID, id_t(command), &ended, WEXITED | WNOHANG | WNOWAIT) == 0 &&
                           ended.si_pid == command)
          break;
      }
    int status = 0;
    while (waitpid(command, &status, 0) < 0 && errno == EINTR)
      {
      }
    return status;
  }

  /// In the supervisor's fork: one request from its reading to the status.
  [[noreturn]] void serve(const int connection)
  {
    Request          request;
    std::vector<int> fds;
    std::string      text;
    if (!receive(connection, request, fds, text))
      _exit(1);
    // Signals stay blocked until the command's fork has the client's
    // dispositions: a signal forwarded early waits instead of being lost.
    sigset_t all, previous;
    sigfillset(&all);
    sigprocmask(SIG_BLOCK, &all, &previous);
    const pid_t supervisor = getpid();
    const pid_t command    = fork();
    if (command == 0)
      run_command(request, fds, text, supervisor);
    sigprocmask(SIG_SETMASK, &previous, nullptr);
    for (const int fd : fds)
      close(fd);
    if (command < 0 || !write_int(connection, command))
      _exit(1);
    write_int(connection, wait_for(command, connection));
    _exit(0);
  }

  /// The socket appears at PATH only once it listens (bound under another
  /// name, then renamed): whoever waits for PATH to exist may connect at once.
  int listen_on(const char *path)
  {
    const int         socket_fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    const std::string bound     = std::string(path) + ".new";
    sockaddr_un       address{};
    address.sun_family = AF_UNIX;
    if (socket_fd < 0 || bound.size() >= sizeof address.sun_path)
      fail("socket");
    std::strcpy(address.sun_path, bound.c_str());
    unlink(bound.c_str());
    if (bind(socket_fd, reinterpret_cast<sockaddr *>(&address), sizeof address) != 0 ||
        listen(socket_fd, 64) != 0 || rename(bound.c_str(), path) != 0)
      fail(path);
    return socket_fd;
  }

  void reap(std::set<pid_t> &children, const int options)
  {
    for (auto it = children.begin(); it != children.end();)
      it = waitpid(*it, nullptr, options) == *it ? children.erase(it) : std::next(it);
  }
} // namespace

int main(int argc, char **argv)
{
  if (argc != 2)
    {
      std::fprintf(stderr, "usage: cdea_fork_server SOCKET\n");
      return 2;
    }
  if (count_threads() != 1)
    {
      std::fprintf(stderr, "cdea_fork_server: %d threads at start; forks need one\n",
                   count_threads());
      return 1;
    }
  struct sigaction stop = {};
  stop.sa_handler       = request_stop;
  sigemptyset(&stop.sa_mask);
  for (const int s : {SIGTERM, SIGINT, SIGHUP})
    sigaction(s, &stop, nullptr);
  const int       listening = listen_on(argv[1]);
  std::set<pid_t> children;
  while (!stop_requested)
    {
      reap(children, WNOHANG);
      pollfd waiting{listening, POLLIN, 0};
      if (poll(&waiting, 1, 200) <= 0)
        continue;
      const int connection = accept4(listening, nullptr, nullptr, SOCK_CLOEXEC);
      if (connection < 0)
        continue;
      const pid_t child = fork();
      if (child == 0)
        {
          close(listening);
          serve(connection);
        }
      if (child > 0)
        children.insert(child);
      close(connection);
    }
  close(listening);
  unlink(argv[1]);
  reap(children, 0);
  return 0;
}
