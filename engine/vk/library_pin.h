#pragma once
// Keeps the shared libraries a Vulkan call loads — drivers, layers and what they link — loaded for
// the rest of the process, so that a process can create and destroy vk::Contexts again and again.
//
// Why: the Vulkan loader unloads a driver (dlclose) when the last instance is destroyed and loads
// it again (dlopen) for the next. NVIDIA's driver links libnvidia-tls, whose thread-local storage
// is static TLS; glibc does not give static TLS back on unload, so after about 30 cycles in one
// process (measured on an H200, driver 580) dlopen fails with "cannot allocate memory in static TLS
// block" and vkCreateInstance with VK_ERROR_INCOMPATIBLE_DRIVER. Pinned, the driver is loaded once
// (which also saves its start-up on every later Context).

#include <string>
#include <vector>

namespace candela::vk {

// The file names of the shared objects loaded in this process now (the executable left out).
std::vector<std::string> loadedLibraries();

// Notes the libraries loaded when it is constructed; pinNew() marks those loaded since
// (RTLD_NOLOAD | RTLD_NODELETE) so that no dlclose unloads them. Cheap: one walk of the loaded
// objects each.
class LibraryPin {
public:
    LibraryPin();
    void pinNew() const;

private:
    std::vector<std::string> mBefore;  // sorted
};

}  // namespace candela::vk
