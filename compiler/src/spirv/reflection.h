// Reflection of one optimized SPIR-V module: what the runtime needs to build pipeline layouts and
// vertex input state and to fill uniform blocks by name.
#ifndef KILN_SPIRV_REFLECTION_H_
#define KILN_SPIRV_REFLECTION_H_

#include <cstdint>
#include <string>
#include <vector>

#include "kiln/pack/format.h"

namespace kiln::spirv {

struct InterfaceVar {
    std::string name;
    std::string semantic;  // upper-case HLSL semantic; empty for built-ins
    uint32_t location = ~0u;
    uint32_t direction = 0;  // 0 input, 1 output
    pack::BaseType base_type = pack::BaseType::kUnknown;
    uint32_t vecsize = 0;

    friend bool operator==(const InterfaceVar&, const InterfaceVar&) = default;
};

struct BlockMember {
    std::string name;
    uint32_t offset = 0, size = 0;
    pack::BaseType base_type = pack::BaseType::kUnknown;
    uint32_t vecsize = 0, columns = 0, array_size = 0;

    friend bool operator==(const BlockMember&, const BlockMember&) = default;
};

struct Block {
    std::string name;
    pack::BlockKind kind = pack::BlockKind::kUniform;
    uint32_t set = 0, binding = 0, size = 0;
    std::vector<BlockMember> members;

    friend bool operator==(const Block&, const Block&) = default;
};

struct Resource {
    std::string name;
    pack::ResourceKind kind = pack::ResourceKind::kCombinedImageSampler;
    uint32_t set = 0, binding = 0;
    pack::ImageDim dim = pack::ImageDim::kNone;
    bool arrayed = false;
    uint32_t array_size = 1;

    friend bool operator==(const Resource&, const Resource&) = default;
};

struct Reflection {
    std::vector<InterfaceVar> interface;  // inputs then outputs, each sorted by location
    std::vector<Block> blocks;            // sorted by (kind, set, binding)
    std::vector<Resource> resources;      // sorted by (set, binding)

    friend bool operator==(const Reflection&, const Reflection&) = default;
};

}  // namespace kiln::spirv

#endif  // KILN_SPIRV_REFLECTION_H_
