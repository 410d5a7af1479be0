#include "Isolated.h"

#include "geom/exchange/ExchangeError.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <new>

namespace geom::exchange {

namespace {

/// The child's report: a status byte ('R' result, 'E' error) and its text.
void report(int fd, char status, const std::string& text) {
    std::string message = status + text;
    const char* data = message.data();
    std::size_t left = message.size();
    while (left > 0) {
        const ssize_t n = write(fd, data, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) _exit(3);
        data += n;
        left -= std::size_t(n);
    }
}

/// Limits the address space to what the process maps now plus `bytes`.
void limitMemory(std::size_t bytes) {
    std::size_t pages = 0;
    std::ifstream("/proc/self/statm") >> pages;
    const rlim_t limit = rlim_t(pages) * rlim_t(sysconf(_SC_PAGESIZE)) + rlim_t(bytes);
    const rlimit r{limit, limit};
    setrlimit(RLIMIT_AS, &r);
}

[[noreturn]] void child(const std::function<std::string()>& work, int fd, std::size_t memoryBytes,
                        int seconds) {
    // A crash ends the child quietly: the handlers it inherited (a test framework's, a
    // sanitizer's) would report it as the parent's.
    for (const int s : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) signal(s, SIG_DFL);
    alarm(unsigned(seconds) + 5);  // a second guard: the parent kills it first
    limitMemory(memoryBytes);
    try {
        report(fd, 'R', work());
    } catch (const ExchangeError& e) {
        report(fd, 'E', e.reason());
    } catch (const std::bad_alloc&) {
        report(fd, 'E', "reading it needs more than " + std::to_string(memoryBytes >> 20) + " MiB of memory");
    } catch (const std::exception& e) {
        report(fd, 'E', e.what());
    } catch (...) {
        report(fd, 'E', "reading it failed with an unknown exception");
    }
    close(fd);
    _exit(0);  // no destructors or exit handlers of the parent's state
}

/// Reads the child's report until it closes the pipe or the time is up.
bool collect(int fd, std::string& text, std::chrono::steady_clock::time_point deadline) {
    char buffer[65536];
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) return false;
        pollfd p{fd, POLLIN, 0};
        const int ready = poll(&p, 1, int(std::min<long long>(left.count(), 1000)));
        if (ready < 0 && errno != EINTR) return false;
        if (ready <= 0) continue;
        const ssize_t n = read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return true;
        text.append(buffer, std::size_t(n));
    }
}

}  // namespace

std::string runIsolated(const std::function<std::string()>& work, const std::string& file,
                        std::size_t memoryBytes, int seconds) {
    // The child inherits the stdio buffers: flushed now, what the caller printed is not printed
    // again when the reader writes and flushes its own messages.
    std::fflush(nullptr);
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0)
        throw ExchangeError(file, std::string("cannot start its reader: ") + std::strerror(errno));
    const pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        throw ExchangeError(file, std::string("cannot start its reader: ") + std::strerror(errno));
    }
    if (pid == 0) {
        close(fds[0]);
        child(work, fds[1], memoryBytes, seconds);
    }
    close(fds[1]);
    std::string text;
    const bool finished =
        collect(fds[0], text, std::chrono::steady_clock::now() + std::chrono::seconds(seconds));
    close(fds[0]);
    if (!finished) kill(pid, SIGKILL);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (!finished)
        throw ExchangeError(file, "reading it took longer than " + std::to_string(seconds) + " s: stopped");
    if (WIFSIGNALED(status))
        throw ExchangeError(file, std::string("OpenCASCADE's reader crashed on it (") +
                                      strsignal(WTERMSIG(status)) + "): the file is corrupt");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || text.empty())
        throw ExchangeError(file, "its reader stopped without an answer: the file is corrupt");
    if (text[0] == 'E') throw ExchangeError(file, text.substr(1));
    return text.substr(1);
}

}  // namespace geom::exchange
