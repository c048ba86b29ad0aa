#include "vk/spirv_check.h"

#include <xxhash.h>
#include <spirv-tools/libspirv.hpp>

#include <map>
#include <string>

namespace kiln::vk {
namespace {

constexpr uint32_t kSpirvMagic = 0x07230203;
constexpr uint32_t kMaxIdBound = 0x3FFFFF;  // SPIR-V's universal limit
constexpr uint32_t kOpEntryPoint = 15, kOpDecorate = 71;
constexpr uint32_t kDecorationBinding = 33, kDecorationDescriptorSet = 34;
constexpr uint32_t kModelVertex = 0, kModelTessControl = 1, kModelTessEval = 2, kModelGeometry = 3,
                   kModelFragment = 4;

Error Bad(const std::string& what) {
    return Error{DiagCode::kBadPack,
                 "the pack's SPIR-V is rejected before it reaches the driver: " + what};
}

Status Validate(std::span<const uint32_t> words) {
    spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_1);
    std::string first;
    tools.SetMessageConsumer(
        [&first](spv_message_level_t, const char*, const spv_position_t&, const char* m) {
            if (first.empty())
                first = m;
        });
    spvtools::ValidatorOptions options;
    options.SetScalarBlockLayout(false);
    if (!tools.Validate(words.data(), words.size(), options))
        return Bad("spirv-val: " + (first.empty() ? std::string("invalid module") : first));
    return {};
}

// The (set, binding) of every decorated variable and the entry points' execution models, read
// with every word bounds-checked.
struct Interface {
    std::map<uint32_t, std::pair<uint32_t, uint32_t>> bindings;  // id -> (set, binding)
    std::set<uint32_t> models;
};

Status ReadInterface(std::span<const uint32_t> words, Interface& out) {
    for (size_t i = 5; i < words.size();) {
        const uint32_t count = words[i] >> 16, opcode = words[i] & 0xFFFF;
        if (count == 0 || count > words.size() - i)
            return Bad("an instruction runs past the end of the module");
        if (opcode == kOpEntryPoint && count >= 2)
            out.models.insert(words[i + 1]);
        if (opcode == kOpDecorate && count >= 4) {
            const uint32_t id = words[i + 1], decoration = words[i + 2], value = words[i + 3];
            if (decoration == kDecorationDescriptorSet)
                out.bindings[id].first = value;
            if (decoration == kDecorationBinding)
                out.bindings[id].second = value;
        }
        i += count;
    }
    return {};
}

}  // namespace

Status ModuleChecker::Check(std::span<const uint32_t> words,
                            pack::Stage stage,
                            const std::set<std::pair<uint32_t, uint32_t>>& layout) {
    if (words.size() < 5 || words[0] != kSpirvMagic)
        return Bad("not a SPIR-V module");
    if (words[3] > kMaxIdBound) {
        return Bad("its id bound " + std::to_string(words[3]) + " is over SPIR-V's limit of " +
                   std::to_string(kMaxIdBound));
    }
    const uint64_t hash = XXH64(words.data(), words.size() * 4, 0);
    bool known = false;
    {
        std::lock_guard<std::mutex> lock(mu_);
        known = validated_.count(hash) > 0;
    }
    if (!known) {
        if (Status e = Validate(words); !e.ok())
            return e;
        std::lock_guard<std::mutex> lock(mu_);
        validated_.insert(hash);
    }
    Interface in;
    if (Status e = ReadInterface(words, in); !e.ok())
        return e;
    // SPIR-V's execution models, by pack::Stage.
    constexpr uint32_t kModels[pack::kStageCount] = {kModelVertex, kModelFragment, kModelGeometry,
                                                     kModelTessControl, kModelTessEval};
    const uint32_t model = kModels[static_cast<uint32_t>(stage)];
    if (in.models.size() != 1 || *in.models.begin() != model) {
        return Bad(std::string("the module is not one ") + pack::StageName(stage) + " entry point");
    }
    for (const auto& [id, sb] : in.bindings) {
        if (sb.first >= limits_.maxBoundDescriptorSets) {
            return Bad("descriptor set " + std::to_string(sb.first) + " is past the device's " +
                       std::to_string(limits_.maxBoundDescriptorSets));
        }
        if (!layout.count(sb)) {
            return Bad("it binds set " + std::to_string(sb.first) + " binding " +
                       std::to_string(sb.second) + ", which the variant's layout does not have");
        }
    }
    return {};
}

}  // namespace kiln::vk
