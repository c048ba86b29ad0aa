#include "spirv/bindings.h"

#include <algorithm>
#include <unordered_map>

namespace kiln::spirv {
namespace {

// SPIR-V opcodes and enums used here (from the SPIR-V specification).
constexpr uint32_t kOpName = 5, kOpTypeImage = 25, kOpTypeSampler = 26, kOpTypeSampledImage = 27,
                   kOpTypeArray = 28, kOpTypeRuntimeArray = 29, kOpTypeStruct = 30,
                   kOpTypePointer = 32, kOpVariable = 59, kOpDecorate = 71;
constexpr uint32_t kDecorationBinding = 33, kDecorationDescriptorSet = 34;
constexpr uint32_t kStorageUniformConstant = 0, kStorageStorageBuffer = 12;

struct ModuleInfo {
    std::unordered_map<uint32_t, std::string> names;
    std::unordered_map<uint32_t, uint32_t> opcode_of;      // type id -> defining opcode
    std::unordered_map<uint32_t, uint32_t> element_of;     // array type -> element type
    std::unordered_map<uint32_t, uint32_t> pointee_of;     // pointer type -> pointee
    std::vector<std::pair<uint32_t, uint32_t>> variables;  // (id, pointer type) with set/binding
    std::unordered_map<uint32_t, uint32_t> storage_of;     // variable -> storage class
    std::unordered_map<uint32_t, std::vector<size_t>> set_words,
        binding_words;  // decoration value positions
};

std::string LiteralString(const std::vector<uint32_t>& w, size_t begin, size_t end) {
    std::string s;
    for (size_t i = begin; i < end; ++i) {
        for (int b = 0; b < 4; ++b) {
            const char c = static_cast<char>((w[i] >> (8 * b)) & 0xff);
            if (c == 0)
                return s;
            s += c;
        }
    }
    return s;
}

ModuleInfo Scan(const std::vector<uint32_t>& w) {
    ModuleInfo m;
    for (size_t i = 5; i < w.size();) {
        const uint32_t count = w[i] >> 16, op = w[i] & 0xffff;
        if (count == 0 || i + count > w.size())
            break;
        if (op == kOpName && count >= 3)
            m.names[w[i + 1]] = LiteralString(w, i + 2, i + count);
        if ((op == kOpTypeImage || op == kOpTypeSampler || op == kOpTypeSampledImage ||
             op == kOpTypeStruct) &&
            count >= 2) {
            m.opcode_of[w[i + 1]] = op;
        }
        if ((op == kOpTypeArray || op == kOpTypeRuntimeArray) && count >= 3) {
            m.opcode_of[w[i + 1]] = op;
            m.element_of[w[i + 1]] = w[i + 2];
        }
        if (op == kOpTypePointer && count >= 4)
            m.pointee_of[w[i + 1]] = w[i + 3];
        if (op == kOpVariable && count >= 4)
            m.storage_of[w[i + 2]] = w[i + 3];
        if (op == kOpVariable && count >= 4)
            m.variables.push_back({w[i + 2], w[i + 1]});
        if (op == kOpDecorate && count >= 4) {
            if (w[i + 2] == kDecorationDescriptorSet)
                m.set_words[w[i + 1]].push_back(i + 3);
            if (w[i + 2] == kDecorationBinding)
                m.binding_words[w[i + 1]].push_back(i + 3);
        }
        i += count;
    }
    return m;
}

// Name and class of a descriptor variable.
std::optional<DescriptorVar> Describe(const ModuleInfo& m, uint32_t var, uint32_t ptr) {
    if (!m.set_words.count(var) && !m.binding_words.count(var))
        return std::nullopt;
    auto find = [](const auto& map, uint32_t key) -> uint32_t {
        auto it = map.find(key);
        return it == map.end() ? 0 : it->second;
    };
    uint32_t type = find(m.pointee_of, ptr);
    while (m.element_of.count(type))
        type = m.element_of.at(type);
    const uint32_t op = find(m.opcode_of, type);
    DescriptorVar d;
    auto name = m.names.find(var);
    d.name = name == m.names.end() ? "" : name->second;
    const uint32_t storage = find(m.storage_of, var);
    if (op == kOpTypeStruct) {
        d.cls =
            storage == kStorageStorageBuffer ? DescriptorClass::kStorage : DescriptorClass::kBlock;
        auto tn = m.names.find(type);
        if (d.name.empty() && tn != m.names.end())
            d.name = tn->second;
    } else if (op == kOpTypeSampledImage) {
        d.cls = DescriptorClass::kCombined;
    } else if (op == kOpTypeSampler) {
        d.cls = DescriptorClass::kSampler;
    } else {
        d.cls = storage == kStorageUniformConstant ? DescriptorClass::kTexture
                                                   : DescriptorClass::kStorage;
    }
    return d;
}

}  // namespace

std::optional<Binding> BuiltinBinding(const std::string& name) {
    static const std::map<std::string, uint32_t> kBuiltinBindings = {
        {"UnityPerCamera", 0},
        {"UnityPerFrame", 1},
        {"UnityLighting", 2},
        {"UnityShadows", 3},
        {"UnityFog", 4},
        {"UnityPerCameraRare", 5},
        {"UnityProbes", 6},
        {"_ShadowMapTexture", 8},
        {"_LightTexture0", 9},
        {"_LightTextureB0", 10},
        {"unity_SpecCube0", 11},
        {"_CameraGBufferTexture0", 12},
        {"_CameraGBufferTexture1", 13},
        {"_CameraGBufferTexture2", 14},
        {"_CameraGBufferTexture3", 15},
        {"_CameraDepthTexture", 16},
    };
    auto it = kBuiltinBindings.find(name);
    if (it != kBuiltinBindings.end())
        return Binding{kFrameSet, it->second};
    // A separate sampler of a built-in texture sits 16 bindings above it.
    if (name.rfind("sampler", 0) == 0) {
        auto tex = kBuiltinBindings.find(name.substr(7));
        if (tex != kBuiltinBindings.end() && tex->second >= 8) {
            return Binding{kFrameSet, tex->second + 16};
        }
    }
    return std::nullopt;
}

std::vector<DescriptorVar> ListDescriptorVars(const std::vector<uint32_t>& words) {
    const ModuleInfo m = Scan(words);
    std::vector<DescriptorVar> out;
    for (const auto& [var, ptr] : m.variables) {
        if (auto d = Describe(m, var, ptr))
            out.push_back(*d);
    }
    return out;
}

std::map<std::string, Binding> AssignBindings(const std::set<DescriptorVar>& used,
                                              const std::vector<std::string>& texture_properties) {
    std::map<std::string, Binding> table;
    std::set<std::string> blocks, textures, samplers;
    for (const DescriptorVar& d : used) {
        if (auto b = BuiltinBinding(d.name)) {
            table[d.name] = *b;
        } else if (d.cls == DescriptorClass::kBlock || d.cls == DescriptorClass::kStorage) {
            blocks.insert(d.name);
        } else if (d.cls == DescriptorClass::kSampler) {
            samplers.insert(d.name);
        } else {
            textures.insert(d.name);
        }
    }
    uint32_t next = 1;
    if (blocks.erase("$Global"))
        table["$Global"] = {kMaterialSet, 0};
    for (const std::string& b : blocks)
        table[b] = {kMaterialSet, next++};
    std::vector<std::string> ordered;
    for (const std::string& p : texture_properties) {
        if (textures.erase(p))
            ordered.push_back(p);
    }
    ordered.insert(ordered.end(), textures.begin(), textures.end());
    for (const std::string& t : ordered) {
        table[t] = {kMaterialSet, next++};
        if (samplers.erase("sampler" + t))
            table["sampler" + t] = {kMaterialSet, next++};
    }
    for (const std::string& s : samplers)
        table[s] = {kMaterialSet, next++};
    return table;
}

Status ApplyBindings(std::vector<uint32_t>& words, const std::map<std::string, Binding>& table) {
    const ModuleInfo m = Scan(words);
    for (const auto& [var, ptr] : m.variables) {
        const auto d = Describe(m, var, ptr);
        if (!d)
            continue;
        auto it = table.find(d->name);
        if (it == table.end() || !m.set_words.count(var) || !m.binding_words.count(var)) {
            return Error{DiagCode::kInternalError, "no binding for descriptor '" + d->name + "'"};
        }
        for (size_t pos : m.set_words.at(var))
            words[pos] = it->second.set;
        for (size_t pos : m.binding_words.at(var))
            words[pos] = it->second.binding;
    }
    return {};
}

}  // namespace kiln::spirv
