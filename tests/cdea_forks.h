#pragma once
// The request of the tests' cdea fork client (tests/cdea_fork_client.cc) to
// the fork server (tests/cdea_fork_server.cc) over a Unix socket, and what a
// fork of the server needs to become the process that `exec cdea ...` from
// the client would have been: the client's open descriptors (passed with
// SCM_RIGHTS), working folder, arguments, environment, umask, resource limits,
// ignored and blocked signals. The server answers with the pid of the fork
// that runs the command, then with its wait status (both as int32).
// No deal.II here: the client must start in a millisecond.

#include <sys/resource.h>

#include <cstdint>

namespace cdea_forks
{
  constexpr std::uint32_t magic = 0xcdea0f0f;

  /// Descriptors 0 .. max_fds - 1 without FD_CLOEXEC are passed on (an exec
  /// would keep them).
  constexpr int max_fds = 16;

  /// The limits that a shell's `ulimit` sets and that an exec keeps.
  constexpr int limit_resources[] = {RLIMIT_FSIZE, RLIMIT_CPU,   RLIMIT_AS,    RLIMIT_DATA,
                                     RLIMIT_CORE,  RLIMIT_NOFILE, RLIMIT_STACK, RLIMIT_NPROC};
  constexpr int n_limits          = sizeof(limit_resources) / sizeof(limit_resources[0]);

  struct Request
  {
    std::uint32_t magic = cdea_forks::magic;
    std::uint32_t n_fds = 0;
    std::int32_t  fd_numbers[max_fds] = {}; ///< where each passed descriptor goes
    std::uint32_t umask               = 0;
    std::uint64_t ignored_signals     = 0; ///< bit s - 1: signal s is SIG_IGN
    std::uint64_t blocked_signals     = 0; ///< bit s - 1: signal s is blocked
    std::uint64_t limits[n_limits][2] = {}; ///< soft, hard
    std::uint32_t argc                = 0;
    std::uint32_t envc                = 0;
    /// Bytes that follow the request: the working folder, the argc
    /// arguments and the envc environment entries, each ending in '\0'.
    std::uint64_t text_bytes = 0;
  };
} // namespace cdea_forks
