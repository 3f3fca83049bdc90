#include "vk/library_pin.h"

#include <algorithm>

#include <dlfcn.h>
#include <link.h>

namespace candela::vk {

std::vector<std::string> loadedLibraries() {
    std::vector<std::string> names;
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void* data) {
            if (info->dlpi_name && *info->dlpi_name) static_cast<std::vector<std::string>*>(data)->emplace_back(info->dlpi_name);
            return 0;
        },
        &names);
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
    return names;
}

LibraryPin::LibraryPin() : mBefore(loadedLibraries()) {}

void LibraryPin::pinNew() const {
    for (const std::string& name : loadedLibraries()) {
        if (std::binary_search(mBefore.begin(), mBefore.end(), name)) continue;
        // Promotes the loaded object to NODELETE; takes a reference that is never given back.
        dlopen(name.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
    }
}

}  // namespace candela::vk
