// processes.cpp — running executables for the reports: posix_spawn, output to /dev/null or
// read back through a pipe.
#include "processes.h"

#include <cerrno>
#include <chrono>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace mb {

std::string executablePath() {
    char self[4096];
    const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    return n > 0 ? std::string(self, size_t(n)) : std::string();
}

std::string besideExecutable(const std::string& name) {
    const std::string exe = executablePath();
    return exe.empty() ? exe : exe.substr(0, exe.rfind('/') + 1) + name;
}

namespace {

// Starts args[0] with args[1..], no shell, its standard output to `stdoutFd` (or /dev/null when
// -1) and its errors to /dev/null; the child's pid, or -1.
pid_t start(const std::vector<std::string>& args, int stdoutFd) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    if (stdoutFd < 0)
        posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    else posix_spawn_file_actions_adddup2(&files, stdoutFd, STDOUT_FILENO);
    posix_spawn_file_actions_addopen(&files, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    const int failed = posix_spawn(&pid, argv[0], &files, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&files);
    return failed == 0 ? pid : -1;
}

bool exitedWell(pid_t pid) {
    int status = 0;
    return pid > 0 && waitpid(pid, &status, 0) == pid && WIFEXITED(status) &&
           WEXITSTATUS(status) == 0;
}

}  // namespace

double timedRun(const std::vector<std::string>& args) {
    const auto begin = std::chrono::steady_clock::now();
    if (!exitedWell(start(args, -1))) return -1.0;
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}

bool runForOutput(const std::vector<std::string>& args, std::string* out) {
    int fds[2];  // close-on-exec: the child has only its dup2'd stdout, so the read sees its end
    if (pipe2(fds, O_CLOEXEC) != 0) return false;
    const pid_t pid = start(args, fds[1]);
    close(fds[1]);
    out->clear();
    char buf[4096];
    for (ssize_t got; (got = read(fds[0], buf, sizeof buf)) != 0;) {
        if (got > 0) out->append(buf, size_t(got));
        else if (errno != EINTR) break;
    }
    close(fds[0]);
    return exitedWell(pid);
}

}  // namespace mb
