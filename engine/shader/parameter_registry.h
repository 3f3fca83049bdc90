#pragma once
// ParameterRegistry: the reflected shader parameters of the passes of recent frames, and the
// values the user set for them. Pure CPU; owned by the Renderer, edited by the viewer's panels.
//
// A pass that fills a parameter block — its push constants, or one element of a storage-buffer
// array such as a light or a material — calls apply() with the block's bytes and its reflected
// layout (shader::BlockMember, annotations included). The user's values for that (pass, block)
// are written over the bytes, and the result is kept so the panel shows what the GPU got. The
// panel is generated from blocks(): never from a hand-written list of parameters.

#include "shader/reflection.h"

#include <cstddef>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace candela::shader {

// Whether the UI can edit `member`: a scalar or vector of float, int, uint or bool (no matrices,
// arrays or structs) not annotated /*Ignore*/.
bool isEditable(const BlockMember& member);

class ParameterRegistry {
public:
    struct Block {
        std::string pass;                 // e.g. "tonemap"
        std::string name;                 // e.g. "Push", "Lights[2]"
        std::vector<BlockMember> members; // the editable members (offsets into `values`)
        std::vector<std::byte> values;    // the bytes the pass last used, user values applied
        uint64_t frame = 0;               // the frame of the last apply()
    };

    // Writes the user's values for (pass, block) over `bytes` (laid out as `members` say) and
    // records the result. Returns true if a user value changed any byte.
    bool apply(std::string_view pass, std::string_view block, std::span<const BlockMember> members,
               std::span<std::byte> bytes);
    template <class T>
    bool apply(std::string_view pass, std::string_view block, std::span<const BlockMember> members, T& value) {
        return apply(pass, block, members, std::as_writable_bytes(std::span(&value, 1)));
    }

    // Sets a member's value from the next apply() on. `value` must be member.size bytes; throws
    // std::invalid_argument otherwise or if the member is not editable.
    void set(std::string_view pass, std::string_view block, const BlockMember& member, std::span<const std::byte> value);
    // Forgets the user's value (the pass's own value applies again).
    void reset(std::string_view pass, std::string_view block, std::string_view member);
    void resetAll();
    bool isSet(std::string_view pass, std::string_view block, std::string_view member) const;

    // Marks the start of a frame; blocks record the frame of their last apply().
    void beginFrame() { ++mFrame; }
    uint64_t frame() const { return mFrame; }
    // Every block applied so far, in order of first appearance.
    const std::vector<Block>& blocks() const { return mBlocks; }
    const Block* find(std::string_view pass, std::string_view block) const;

private:
    static std::string key(std::string_view pass, std::string_view block);
    std::vector<Block> mBlocks;
    std::map<std::string, size_t, std::less<>> mIndex;  // key → mBlocks index
    // key → member name → (offset, bytes)
    std::map<std::string, std::map<std::string, std::pair<uint32_t, std::vector<std::byte>>>, std::less<>> mValues;
    uint64_t mFrame = 0;
};

}  // namespace candela::shader
