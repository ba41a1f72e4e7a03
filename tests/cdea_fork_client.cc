// The tests' stand-in for the cdea executable (tests/cdea_forks.bash):
// `cdea_fork_client ARGS...` asks the fork server at $CDEA_FORK_SOCKET
// (tests/cdea_fork_server.cc) to run `cdea ARGS...` as this process would
// have after an exec: its open descriptors (SCM_RIGHTS), folder,
// environment (without CDEA_FORK_SOCKET), umask, limits, ignored and
// blocked signals. It forwards SIGINT, SIGTERM, SIGHUP and SIGQUIT to the
// command's process and ends as that process ended: the same exit code, or
// killed by the same signal. SIGKILL cannot be forwarded: the server kills
// the command when this client goes away, but a test that kills with
// SIGKILL and then reads the files keeps the real executable. Under an MPI
// launcher it execs the real executable ($CDEA_FORK_EXECUTABLE) instead.
// Libc only: it starts in about a millisecond.

#include "cdea_forks.h"

#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

extern char **environ;

namespace
{
  using cdea_forks::Request;

  const int forwarded[]          = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
  volatile pid_t command_process = 0;

  extern "C" void forward(const int signal)
  {
    if (command_process > 0)
      kill(command_process, signal);
  }

  [[noreturn]] void give_up(const char *what)
  {
    std::fprintf(stderr, "cdea_fork_client: %s: %s\n", what, std::strerror(errno));
    _exit(125);
  }

  /// Everything of this process that an exec of cdea would have kept.
  Request describe(const sigset_t &blocked, const std::string &text, const int argc)
  {
    Request request;
    for (int fd = 0; fd < cdea_forks::max_fds; ++fd)
      {
        const int flags = fcntl(fd, F_GETFD);
        if (flags >= 0 && !(flags & FD_CLOEXEC))
          request.fd_numbers[request.n_fds++] = fd;
      }
    request.umask = umask(0);
    umask(mode_t(request.umask));
    for (int s = 1; s < 65; ++s)
      {
        struct sigaction action = {};
        if (sigaction(s, nullptr, &action) == 0 && action.sa_handler == SIG_IGN)
          request.ignored_signals |= std::uint64_t(1) << (s - 1);
        if (sigismember(&blocked, s) == 1)
          request.blocked_signals |= std::uint64_t(1) << (s - 1);
      }
    for (int i = 0; i < cdea_forks::n_limits; ++i)
      {
        rlimit limit{};
        getrlimit(cdea_forks::limit_resources[i], &limit);
        request.limits[i][0] = limit.rlim_cur;
        request.limits[i][1] = limit.rlim_max;
      }
    request.argc       = std::uint32_t(argc);
    request.text_bytes = text.size();
    return request;
  }

  /// The working folder, the arguments (argv[0] included) and the
  /// environment, each ending in '\0'; sets @p envc.
  std::string words(char **argv, const int argc, std::uint32_t &envc)
  {
    std::vector<char> folder(4096);
    if (getcwd(folder.data(), folder.size()) == nullptr)
      give_up("getcwd");
    std::string text(folder.data());
    text += '\0';
    for (int i = 0; i < argc; ++i)
      text.append(argv[i]).push_back('\0');
    envc = 0;
    for (char **e = environ; *e != nullptr; ++e)
      if (std::strncmp(*e, "CDEA_FORK_SOCKET=", 17) != 0)
        {
          text.append(*e).push_back('\0');
          ++envc;
        }
    return text;
  }

  int connect_to(const char *path)
  {
    const int   fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    if (fd < 0 || std::strlen(path) >= sizeof address.sun_path)
      give_up("socket");
    std::strcpy(address.sun_path, path);
    if (connect(fd, reinterpret_cast<sockaddr *>(&address), sizeof address) != 0)
      give_up(path);
    return fd;
  }

  void send_request(const int fd, const Request &request, const std::string &text)
  {
    char control[CMSG_SPACE(sizeof(int) * cdea_forks::max_fds)] = {};
    iovec  io{const_cast<Request *>(&request), sizeof request};
    msghdr message{};
    message.msg_iov    = &io;
    message.msg_iovlen = 1;
    if (request.n_fds > 0)
      {
        message.msg_control    = control;
        message.msg_controllen = CMSG_SPACE(sizeof(int) * request.n_fds);
        cmsghdr *c             = CMSG_FIRSTHDR(&message);
        c->cmsg_level          = SOL_SOCKET;
        c->cmsg_type           = SCM_RIGHTS;
        c->cmsg_len            = CMSG_LEN(sizeof(int) * request.n_fds);
        std::memcpy(CMSG_DATA(c), request.fd_numbers, sizeof(int) * request.n_fds);
      }
    if (sendmsg(fd, &message, MSG_NOSIGNAL) != ssize_t(sizeof request))
      give_up("sendmsg");
    for (std::size_t sent = 0; sent < text.size();)
      {
        const ssize_t n = send(fd, text.data() + sent, text.size() - sent, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR)
          continue;
        if (n <= 0)
          give_up("send");
        sent += std::size_t(n);
      }
  }

  bool has_variable(const char *name)
  {
    const char *value = std::getenv(name);
    return value != nullptr && *value != '\0';
  }

  /// The test of mpi::launched_by_mpirun() (source/base/mpi_session.cc).
  bool launched_by_mpi()
  {
    return has_variable("OMPI_COMM_WORLD_SIZE") || has_variable("PMIX_RANK") ||
           has_variable("PMI_RANK") || (has_variable("SLURM_STEP_ID") && has_variable("SLURM_PROCID"));
  }

  bool read_int(const int fd, std::int32_t &value)
  {
    std::size_t got = 0;
    while (got < sizeof value)
      {
        const ssize_t n = read(fd, reinterpret_cast<char *>(&value) + got, sizeof value - got);
        if (n < 0 && errno == EINTR)
          continue;
        if (n <= 0)
          return false;
        got += std::size_t(n);
      }
    return true;
  }
} // namespace

int main(int argc, char **argv)
{
  if (launched_by_mpi())
    {
      // MPI stays off in the server's forks: under a launcher, the real
      // program (MPI starts in it, as mpi::launched_by_mpirun() says).
      const char *real = std::getenv("CDEA_FORK_EXECUTABLE");
      if (real == nullptr || *real == '\0')
        {
          std::fprintf(stderr, "cdea_fork_client: under mpirun, CDEA_FORK_EXECUTABLE must be set\n");
          return 125;
        }
      argv[0] = const_cast<char *>(real);
      execv(real, argv);
      give_up(real);
    }
  const char *path = std::getenv("CDEA_FORK_SOCKET");
  if (path == nullptr || *path == '\0')
    {
      std::fprintf(stderr, "cdea_fork_client: CDEA_FORK_SOCKET is not set\n");
      return 125;
    }
  // The forwarded signals wait until the command's pid is known.
  sigset_t forwarded_set, blocked;
  sigemptyset(&forwarded_set);
  for (const int s : forwarded)
    sigaddset(&forwarded_set, s);
  sigprocmask(SIG_BLOCK, &forwarded_set, &blocked);
  std::uint32_t     envc    = 0;
  const std::string text    = words(argv, argc, envc);
  Request           request = describe(blocked, text, argc);
  request.envc              = envc;
  const int connection      = connect_to(path);
  send_request(connection, request, text);
  std::int32_t pid = 0, status = 0;
  if (!read_int(connection, pid))
    give_up("no command process");
  command_process = pid;
  struct sigaction action = {};
  action.sa_handler       = forward;
  action.sa_flags         = SA_RESTART;
  sigemptyset(&action.sa_mask);
  for (const int s : forwarded)
    sigaction(s, &action, nullptr);
  sigprocmask(SIG_SETMASK, &blocked, nullptr);
  if (!read_int(connection, status))
    give_up("no status of the command");
  if (WIFEXITED(status))
    _exit(WEXITSTATUS(status));
  const int signal = WIFSIGNALED(status) ? WTERMSIG(status) : SIGKILL;
  std::signal(signal, SIG_DFL);
  sigset_t just;
  sigemptyset(&just);
  sigaddset(&just, signal);
  sigprocmask(SIG_UNBLOCK, &just, nullptr);
  raise(signal);
  _exit(128 + signal);
}
