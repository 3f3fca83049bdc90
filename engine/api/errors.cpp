// The API's exceptions (candela/errors.h), its version, and the translation of Candela's internal
// errors into them (access.h).

#include "api/access.h"
#include "candela/errors.h"
#include "candela/version.h"
#include "vk/check.h"

#include <new>

namespace candela {

const char* version() noexcept { return CANDELA_VERSION_STRING; }

Error::Error(const std::string& message) : std::runtime_error(message) {}
Error::~Error() = default;
InputError::InputError(const std::string& file, const std::string& reason)
    : Error(file.empty() ? reason : file + ": " + reason), file_(file), reason_(reason) {}
InputError::~InputError() = default;
DeviceError::DeviceError(const std::string& message) : Error(message) {}
DeviceError::~DeviceError() = default;
DeviceLostError::DeviceLostError(const std::string& message) : DeviceError(message) {}
DeviceLostError::~DeviceLostError() = default;
OutOfMemoryError::OutOfMemoryError(const std::string& message) : DeviceError(message) {}
OutOfMemoryError::~OutOfMemoryError() = default;
CancelledError::CancelledError() : Error("the render was cancelled") {}
CancelledError::~CancelledError() = default;
InternalFailure::InternalFailure(const std::string& message) : Error(message) {}
InternalFailure::~InternalFailure() = default;

void translateErrors(const std::string& file, const std::function<void()>& call) {
    try {
        call();
    } catch (const Error&) {
        throw;
    } catch (const UserError& e) {
        const std::string message = e.what();
        if (!file.empty() && message.rfind(file + ": ", 0) == 0) throw InputError(file, message.substr(file.size() + 2));
        throw InputError("", message);
    } catch (const vk::OutOfDeviceMemory& e) {
        throw OutOfMemoryError(std::string("out of device memory: ") + e.what());
    } catch (const vk::VulkanError& e) {
        if (e.result() == VK_ERROR_DEVICE_LOST) throw DeviceLostError(e.what());
        if (e.result() == VK_ERROR_OUT_OF_HOST_MEMORY) throw OutOfMemoryError(e.what());
        throw DeviceError(e.what());
    } catch (const std::bad_alloc&) {
        throw OutOfMemoryError("out of host memory");
    } catch (const InternalError& e) {
        throw InternalFailure(std::string("internal error (a bug in Candela, please report it): ") + e.what());
    } catch (const std::exception& e) {
        throw InternalFailure(e.what());
    }
}

}  // namespace candela
