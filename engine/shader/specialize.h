#pragma once
// Specialization at load: SPIR-V with some specialization constants fixed to values and the code
// and resources those values leave unused removed (SPIRV-Tools' optimizer); a fragment stage's
// output locations moved. A program variant then
// declares only the descriptors it reads, so its layout fits per-stage limits a generic program
// would exceed (the layered forward program on devices with 16 samplers per stage).

#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace candela::shader {

// Sets specialization constant `id` (shared/specialization_ids.h) to `value` in `values` (indexed
// by constant_id), growing it with zeros to hold the id.
inline void setSpecialization(std::vector<uint32_t>& values, uint32_t id, uint32_t value) {
    if (values.size() <= id) values.resize(id + 1, 0);
    values[id] = value;
}
// Specialization values from (constant_id, value) pairs (unset ids 0).
inline std::vector<uint32_t> specializationValues(std::initializer_list<std::pair<uint32_t, uint32_t>> constants) {
    std::vector<uint32_t> out;
    for (const auto& [id, value] : constants) setSpecialization(out, id, value);
    return out;
}

// A specialization constant (constant_id) and its value as the 32 bits Vulkan's
// VkSpecializationInfo would pass (bool: 0 or 1).
using FrozenConstant = std::pair<uint32_t, uint32_t>;

// `spirv` with the constants in `frozen` fixed (constants `spirv` does not declare are ignored) and
// dead code, functions and variables removed. Throws std::runtime_error naming `debugName` if the
// optimizer fails. The other specialization constants stay specialization constants.
std::vector<uint32_t> specializeSpirv(std::span<const uint32_t> spirv, std::span<const FrozenConstant> frozen,
                                      const std::string& debugName);

// `spirv` with each Output variable decorated Location l moved to locations[l] (one beyond the
// table keeps its own): a fragment stage whose outputs are bound to other colour attachments than
// the ones it was compiled for (the aov pass: the targets a frame asks for, packed). Throws
// std::runtime_error naming `debugName` for malformed SPIR-V.
std::vector<uint32_t> remapOutputLocations(std::span<const uint32_t> spirv, std::span<const uint32_t> locations,
                                           const std::string& debugName);

}  // namespace candela::shader
