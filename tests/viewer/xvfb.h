#pragma once
// A private X server for the viewer tests: when DISPLAY is unset, starts `Xvfb -displayfd` (Debian
// package xvfb) for the test process and points DISPLAY at it; stops it at the end. With DISPLAY
// set (a desktop, or xvfb-run) it does nothing.

#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <string>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace candela::test {

class XvfbEnvironment : public ::testing::Environment {
public:
    void SetUp() override {
        if (const char* display = std::getenv("DISPLAY"); display && *display) return;
        int fds[2];
        ASSERT_EQ(pipe(fds), 0);
        mPid = fork();
        ASSERT_GE(mPid, 0);
        if (mPid == 0) {
            // Dies with the test process, even when that crashes (else ctest waits on it).
            prctl(PR_SET_PDEATHSIG, SIGTERM);
            close(fds[0]);
            const std::string fd = std::to_string(fds[1]);
            // -noreset: by default the server resets when its last client leaves, and a client that
            // connects meanwhile is refused ("Failed to open display"): one test runs several viewers
            // one after another.
            execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1920x1200x24", "-nolisten", "tcp", "-noreset",
                   static_cast<char*>(nullptr));
            _exit(127);
        }
        close(fds[1]);
        // Xvfb writes the display number and a newline once it accepts connections.
        std::string number;
        char c = 0;
        while (read(fds[0], &c, 1) == 1 && c != '\n') number += c;
        close(fds[0]);
        ASSERT_FALSE(number.empty()) << "Xvfb did not start (is the xvfb package installed?)";
        setenv("DISPLAY", (":" + number).c_str(), 1);
    }
    void TearDown() override {
        if (mPid <= 0) return;
        kill(mPid, SIGTERM);
        waitpid(mPid, nullptr, 0);
    }

private:
    pid_t mPid = -1;
};

}  // namespace candela::test
