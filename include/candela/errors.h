#pragma once
// The exceptions the API throws, all derived from candela::Error (itself a std::runtime_error whose
// what() is one line). What each function throws is said where it is declared.

#include "candela/version.h"

#include <stdexcept>
#include <string>

namespace candela {

class CANDELA_API Error : public std::runtime_error {
public:
    explicit Error(const std::string& message);
    ~Error() override;
};

// Bad input: a malformed or missing file, a setting out of range. file() names the file ("" for a
// setting), reason() says what is wrong with it; what() is "FILE: REASON".
class CANDELA_API InputError : public Error {
public:
    InputError(const std::string& file, const std::string& reason);
    ~InputError() override;
    const std::string& file() const noexcept { return file_; }
    const std::string& reason() const noexcept { return reason_; }

private:
    std::string file_;
    std::string reason_;
};

// The device failed: no Vulkan 1.3 device, the device was lost, or a Vulkan call failed.
class CANDELA_API DeviceError : public Error {
public:
    explicit DeviceError(const std::string& message);
    ~DeviceError() override;
};

// The device was lost (a driver reset or a hang): the Device must be destroyed; a new one may work.
class CANDELA_API DeviceLostError : public DeviceError {
public:
    explicit DeviceLostError(const std::string& message);
    ~DeviceLostError() override;
};

// Device memory ran out (or DeviceOptions::memoryBudgetMib was reached). The Device stays usable:
// a smaller image or scene may fit.
class CANDELA_API OutOfMemoryError : public DeviceError {
public:
    explicit OutOfMemoryError(const std::string& message);
    ~OutOfMemoryError() override;
};

// A render was cancelled (Device::cancel, or a progress callback that returned false).
class CANDELA_API CancelledError : public Error {
public:
    CancelledError();
    ~CancelledError() override;
};

// A bug in Candela: please report it with what() and the input.
class CANDELA_API InternalFailure : public Error {
public:
    explicit InternalFailure(const std::string& message);
    ~InternalFailure() override;
};

}  // namespace candela
