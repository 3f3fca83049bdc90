#include "shader/parameter_registry.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace candela::shader {

bool isEditable(const BlockMember& member) {
    const bool scalarType = member.type == BaseType::Float || member.type == BaseType::Int ||
                            member.type == BaseType::UInt || member.type == BaseType::Bool;
    return scalarType && !member.annotation.ignore && member.columns == 1 && member.arraySize == 1 &&
           member.vectorSize >= 1 && member.vectorSize <= 4 && member.size == 4 * member.vectorSize;
}

std::string ParameterRegistry::key(std::string_view pass, std::string_view block) {
    return std::string(pass) + '\n' + std::string(block);
}

bool ParameterRegistry::apply(std::string_view pass, std::string_view block, std::span<const BlockMember> members,
                              std::span<std::byte> bytes) {
    const std::string k = key(pass, block);
    bool changed = false;
    if (const auto values = mValues.find(k); values != mValues.end())
        for (const auto& [name, value] : values->second) {
            const auto& [offset, data] = value;
            if (offset + data.size() > bytes.size()) continue;  // a layout from another shader version
            if (std::memcmp(bytes.data() + offset, data.data(), data.size()) != 0) {
                std::memcpy(bytes.data() + offset, data.data(), data.size());
                changed = true;
            }
        }
    auto it = mIndex.find(k);
    if (it == mIndex.end()) {
        Block b{.pass = std::string(pass), .name = std::string(block)};
        it = mIndex.emplace(k, mBlocks.size()).first;
        mBlocks.push_back(std::move(b));
    }
    Block& b = mBlocks[it->second];
    b.members.clear();
    for (const BlockMember& m : members)
        if (isEditable(m) && m.offset + m.size <= bytes.size()) b.members.push_back(m);
    b.values.assign(bytes.begin(), bytes.end());
    b.frame = mFrame;
    return changed;
}

void ParameterRegistry::set(std::string_view pass, std::string_view block, const BlockMember& member,
                            std::span<const std::byte> value) {
    if (!isEditable(member)) throw std::invalid_argument("parameter " + member.name + " is not editable");
    if (value.size() != member.size)
        throw std::invalid_argument("parameter " + member.name + ": expected " + std::to_string(member.size) + " bytes");
    mValues[key(pass, block)][member.name] = {member.offset, std::vector<std::byte>(value.begin(), value.end())};
}

void ParameterRegistry::reset(std::string_view pass, std::string_view block, std::string_view member) {
    if (const auto it = mValues.find(key(pass, block)); it != mValues.end()) it->second.erase(std::string(member));
}

void ParameterRegistry::resetAll() { mValues.clear(); }

bool ParameterRegistry::isSet(std::string_view pass, std::string_view block, std::string_view member) const {
    const auto it = mValues.find(key(pass, block));
    return it != mValues.end() && it->second.count(std::string(member)) > 0;
}

const ParameterRegistry::Block* ParameterRegistry::find(std::string_view pass, std::string_view block) const {
    const auto it = mIndex.find(key(pass, block));
    return it == mIndex.end() ? nullptr : &mBlocks[it->second];
}

}  // namespace candela::shader
