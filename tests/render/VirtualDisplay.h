#pragma once

// An Xvfb server of the test's own, so window tests need no display set up beforehand (the
// Debian package 'xvfb').

#include <catch2/catch.hpp>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

extern char** environ;

namespace render_test {

/// An Xvfb server on a free display number for the lifetime of the object; `screen` is Xvfb's
/// WxHxDEPTH (windows larger than the screen are clipped by the server).
class VirtualDisplay {
public:
    explicit VirtualDisplay(const char* screen = "640x480x24") {
        int fds[2];
        REQUIRE(pipe(fds) == 0);
        const std::string fd = std::to_string(fds[1]);
        const char* argv[] = {"Xvfb", "-displayfd", fd.c_str(), "-screen",  "0",
                              screen, "-nolisten",  "tcp",      "-noreset", nullptr};
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_addclose(&actions, fds[0]);
        const int rc =
            posix_spawnp(&pid_, "Xvfb", &actions, nullptr, const_cast<char* const*>(argv), environ);
        posix_spawn_file_actions_destroy(&actions);
        close(fds[1]);
        REQUIRE(rc == 0);  // install the Debian package 'xvfb'
        std::string number;
        char c;
        while (read(fds[0], &c, 1) == 1 && c != '\n') number += c;
        close(fds[0]);
        REQUIRE(!number.empty());
        previous_ = std::getenv("DISPLAY") ? std::getenv("DISPLAY") : "";
        setenv("DISPLAY", (":" + number).c_str(), 1);
    }
    ~VirtualDisplay() {
        if (previous_.empty())
            unsetenv("DISPLAY");
        else
            setenv("DISPLAY", previous_.c_str(), 1);
        if (pid_ > 0) {
            kill(pid_, SIGTERM);
            waitpid(pid_, nullptr, 0);
        }
    }

private:
    pid_t pid_ = -1;
    std::string previous_;
};

}  // namespace render_test
