#include "shader/specialize.h"

#include <spirv-tools/optimizer.hpp>

#include <optional>
#include <stdexcept>
#include <unordered_map>

namespace candela::shader {
namespace {

constexpr uint32_t kOpDecorate = 71, kDecorationSpecId = 1, kDecorationLocation = 30;
constexpr uint32_t kOpVariable = 59, kStorageClassOutput = 3;
constexpr uint32_t kOpConstantTrue = 41, kOpConstantFalse = 42, kOpConstant = 43;
constexpr uint32_t kOpSpecConstantTrue = 48, kOpSpecConstantFalse = 49, kOpSpecConstant = 50;

// `spirv` with the specialization constants in `frozen` turned into ordinary constants of those
// values (their SpecId decorations removed); the other specialization constants are left as they
// are. (SPIRV-Tools' freeze pass would freeze them all.)
std::vector<uint32_t> freezeConstants(std::span<const uint32_t> spirv, std::span<const FrozenConstant> frozen,
                                      const std::string& debugName) {
    constexpr size_t kHeader = 5;
    if (spirv.size() < kHeader) throw std::runtime_error(debugName + ": not SPIR-V");
    // Pass 1: the result ids of the frozen constants.
    std::unordered_map<uint32_t, uint32_t> valueOfId;
    for (size_t i = kHeader; i < spirv.size();) {
        const uint32_t words = spirv[i] >> 16, opcode = spirv[i] & 0xFFFFu;
        if (words == 0 || i + words > spirv.size()) throw std::runtime_error(debugName + ": malformed SPIR-V");
        if (opcode == kOpDecorate && words == 4 && spirv[i + 2] == kDecorationSpecId)
            for (const auto& [id, value] : frozen)
                if (spirv[i + 3] == id) valueOfId[spirv[i + 1]] = value;
        i += words;
    }
    // Pass 2: copy, dropping their SpecId decorations and rewriting their definitions.
    std::vector<uint32_t> out(spirv.begin(), spirv.begin() + kHeader);
    for (size_t i = kHeader; i < spirv.size();) {
        const uint32_t words = spirv[i] >> 16, opcode = spirv[i] & 0xFFFFu;
        const auto frozenValue = [&](uint32_t resultId) {
            const auto it = valueOfId.find(resultId);
            return it == valueOfId.end() ? std::optional<uint32_t>() : std::optional<uint32_t>(it->second);
        };
        if (opcode == kOpDecorate && words == 4 && spirv[i + 2] == kDecorationSpecId && valueOfId.count(spirv[i + 1])) {
            // dropped
        } else if ((opcode == kOpSpecConstantTrue || opcode == kOpSpecConstantFalse) && frozenValue(spirv[i + 2])) {
            out.push_back((3u << 16) | (*frozenValue(spirv[i + 2]) ? kOpConstantTrue : kOpConstantFalse));
            out.push_back(spirv[i + 1]);
            out.push_back(spirv[i + 2]);
        } else if (opcode == kOpSpecConstant && words == 4 && frozenValue(spirv[i + 2])) {
            out.push_back((4u << 16) | kOpConstant);
            out.push_back(spirv[i + 1]);
            out.push_back(spirv[i + 2]);
            out.push_back(*frozenValue(spirv[i + 2]));
        } else {
            out.insert(out.end(), spirv.begin() + i, spirv.begin() + i + words);
        }
        i += words;
    }
    return out;
}

}  // namespace

std::vector<uint32_t> specializeSpirv(std::span<const uint32_t> spirv, std::span<const FrozenConstant> frozen,
                                      const std::string& debugName) {
    std::string messages;
    spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_3);
    optimizer.SetMessageConsumer([&](spv_message_level_t level, const char*, const spv_position_t&, const char* text) {
        if (level <= SPV_MSG_ERROR) messages += std::string(text) + "; ";
    });
    // Expressions of the frozen constants folded (those of the others stay specialization
    // constant operations), then the optimizer's performance passes (spirv-opt -O: returns merged,
    // functions inlined, SSA, conditional constant propagation — a constant a function returns
    // reaches the branch that tests it — dead branches and code removed; no floating-point
    // reassociation), then the variables nothing reads any more. About half a second for the
    // layered forward program on this project's CPU.
    optimizer.RegisterPass(spvtools::CreateFoldSpecConstantOpAndCompositePass());
    optimizer.RegisterPerformancePasses();
    optimizer.RegisterPass(spvtools::CreateDeadVariableEliminationPass());
    optimizer.RegisterPass(spvtools::CreateEliminateDeadConstantPass());
    optimizer.RegisterPass(spvtools::CreateRemoveUnusedInterfaceVariablesPass());
    const std::vector<uint32_t> frozenSpirv = freezeConstants(spirv, frozen, debugName);
    std::vector<uint32_t> out;
    if (!optimizer.Run(frozenSpirv.data(), frozenSpirv.size(), &out))
        throw std::runtime_error("specializing " + debugName + " failed: " + messages);
    return out;
}

std::vector<uint32_t> remapOutputLocations(std::span<const uint32_t> spirv, std::span<const uint32_t> locations,
                                           const std::string& debugName) {
    constexpr size_t kHeader = 5;
    if (spirv.size() < kHeader) throw std::runtime_error(debugName + ": not SPIR-V");
    std::vector<uint32_t> out(spirv.begin(), spirv.end());
    std::unordered_map<uint32_t, bool> output;  // result id → an Output variable
    for (size_t i = kHeader; i < out.size();) {
        const uint32_t words = out[i] >> 16, opcode = out[i] & 0xFFFFu;
        if (words == 0 || i + words > out.size()) throw std::runtime_error(debugName + ": malformed SPIR-V");
        if (opcode == kOpVariable && words >= 4 && out[i + 3] == kStorageClassOutput) output[out[i + 2]] = true;
        i += words;
    }
    for (size_t i = kHeader; i < out.size(); i += out[i] >> 16) {
        const uint32_t words = out[i] >> 16, opcode = out[i] & 0xFFFFu;
        if (opcode == kOpDecorate && words == 4 && out[i + 2] == kDecorationLocation && output.count(out[i + 1]) &&
            out[i + 3] < locations.size())
            out[i + 3] = locations[out[i + 3]];
    }
    return out;
}

}  // namespace candela::shader
