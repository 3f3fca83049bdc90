#pragma once
// Helpers of the public API's GPU tests (api_test.cpp, api_camera_test.cpp): a validated device
// and its validation messages that count (with CANDELA_BEST_PRACTICES=1, as ctest runs the suite
// on lavapipe, less those that do not apply: gpu_test.h).

#include "gpu_test.h"
#include "api/access.h"
#include "candela/candela.h"

namespace candela::test {

// A device under validation, with no pipeline-cache file.
inline DeviceOptions validated() { return {.validation = true, .pipelineCache = "off"}; }

inline uint32_t messages(const vk::Context& context) {
    uint32_t count = 0;
    for (const vk::ValidationMessage& m : context.validationMessages()) count += bestPracticesNotApplicable(m.text) ? 0 : 1;
    return count;
}
inline uint32_t messages(Device& device) { return messages(Access::impl(device).context); }

}  // namespace candela::test
