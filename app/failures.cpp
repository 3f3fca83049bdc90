#include "failures.h"

#include "candela/errors.h"
#include "core/errors.h"
#include "core/log.h"
#include "vk/check.h"

namespace candela::app {

Failure describeFailure(const std::exception_ptr& error) {
    try {
        std::rethrow_exception(error);
    } catch (const UserError& e) {
        return {e.what(), 2};
    } catch (const candela::InputError& e) {
        return {e.what(), 2};
    } catch (const candela::OutOfMemoryError& e) {
        return {e.what(), 4};  // "out of device memory: ..." (engine/api/errors.cpp)
    } catch (const vk::OutOfDeviceMemory& e) {
        return {std::string("out of device memory: ") + e.what(), 4};
    } catch (const InternalError& e) {
        return {std::string("internal error (a bug in Candela, please report it): ") + e.what(), 1};
    } catch (const std::exception& e) {
        return {e.what(), 1};
    }
}

int exitCodeOf(const std::function<int()>& command) {
    try {
        return command();
    } catch (...) {
        const Failure failure = describeFailure(std::current_exception());
        log::error(failure.message);
        return failure.exitCode;
    }
}

}  // namespace candela::app
