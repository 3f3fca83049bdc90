#pragma once
// How an error reaches the user: one line and an exit code, the same for a command that fails
// (main) and for one scene of a batch that fails (render).

#include <exception>
#include <functional>
#include <string>

namespace candela::app {

struct Failure {
    std::string message;  // one line
    int exitCode = 1;     // 2: bad input (UserError), 4: out of device memory, 1: anything else
};

// The line and exit code of `error`. Precondition: `error` is not null.
Failure describeFailure(const std::exception_ptr& error);

// Runs `command` and returns its exit code; an exception it throws is logged as its one line
// (log::error) and its exit code returned instead.
int exitCodeOf(const std::function<int()>& command);

}  // namespace candela::app
