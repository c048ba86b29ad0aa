// kiln show --reflect: the reflection records a pack keeps for one module, as text or JSON.
#include "kiln/show.h"

#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

namespace kiln {

namespace {

using pack::BaseType;

std::string TypeName(uint32_t base, uint32_t vecsize, uint32_t columns) {
    std::string name;
    switch (BaseType(base)) {
        case BaseType::kBool:
            name = "bool";
            break;
        case BaseType::kInt:
            name = "int";
            break;
        case BaseType::kUInt:
            name = "uint";
            break;
        case BaseType::kFloat:
            name = "float";
            break;
        case BaseType::kHalf:
            name = "half";
            break;
        case BaseType::kDouble:
            name = "double";
            break;
        case BaseType::kStruct:
            return "struct";
        case BaseType::kUnknown:
            return "unknown";
    }
    if (vecsize > 1)
        name += std::to_string(vecsize);
    if (columns > 1)
        name += "x" + std::to_string(columns);
    return name;
}

const char* ResourceKindName(uint32_t kind) {
    switch (pack::ResourceKind(kind)) {
        case pack::ResourceKind::kCombinedImageSampler:
            return "combined image sampler";
        case pack::ResourceKind::kSeparateImage:
            return "image";
        case pack::ResourceKind::kSeparateSampler:
            return "sampler";
        case pack::ResourceKind::kStorageImage:
            return "storage image";
        case pack::ResourceKind::kStorageBuffer:
            return "storage buffer";
    }
    return "unknown";
}

const char* DimName(uint32_t dim) {
    static const char* const kNames[] = {"", "1D", "2D", "3D", "Cube", "Buffer"};
    return dim < std::size(kNames) ? kNames[dim] : "unknown";
}

// The module's records as JSON (the text form is printed from it, so both say the same).
nlohmann::ordered_json ReflectionJson(const pack::Pack& pack, const pack::ModuleRec& m) {
    using pack::SectionTag;
    nlohmann::ordered_json j;
    j["stage"] = m.stage < pack::kStageCount ? pack::StageName(pack::Stage(m.stage)) : "?";
    j["inputs"] = nlohmann::ordered_json::array();
    j["outputs"] = nlohmann::ordered_json::array();
    for (uint32_t i = 0; i < m.interface_count; ++i) {
        const auto v =
            pack.Get<pack::InterfaceVarRec>(SectionTag::kInterface, m.first_interface + i);
        if (!v)
            break;
        const pack::InterfaceVarRec& r = v.value();
        nlohmann::ordered_json e = {{"name", pack.String(r.name)},
                                    {"semantic", pack.String(r.semantic)},
                                    {"type", TypeName(r.base_type, r.vecsize, 1)}};
        if (r.location != ~0u)
            e["location"] = r.location;
        j[r.direction == 0 ? "inputs" : "outputs"].push_back(std::move(e));
    }
    j["blocks"] = nlohmann::ordered_json::array();
    for (uint32_t i = 0; i < m.block_count; ++i) {
        const auto b = pack.Get<pack::BlockRec>(SectionTag::kBlocks, m.first_block + i);
        if (!b)
            break;
        const pack::BlockRec& r = b.value();
        const bool push = r.kind == uint32_t(pack::BlockKind::kPushConstant);
        nlohmann::ordered_json e = {{"name", pack.String(r.name)},
                                    {"kind", push ? "push_constant" : "uniform"}};
        if (!push) {
            e["set"] = r.set;
            e["binding"] = r.binding;
        }
        e["size"] = r.size;
        e["members"] = nlohmann::ordered_json::array();
        for (uint32_t k = 0; k < r.member_count; ++k) {
            const auto mem = pack.Get<pack::MemberRec>(SectionTag::kMembers, r.first_member + k);
            if (!mem)
                break;
            const pack::MemberRec& mr = mem.value();
            nlohmann::ordered_json me = {{"name", pack.String(mr.name)},
                                         {"type", TypeName(mr.base_type, mr.vecsize, mr.columns)},
                                         {"offset", mr.offset},
                                         {"size", mr.size}};
            if (mr.array_size > 0)
                me["array_size"] = mr.array_size;
            e["members"].push_back(std::move(me));
        }
        j["blocks"].push_back(std::move(e));
    }
    j["resources"] = nlohmann::ordered_json::array();
    for (uint32_t i = 0; i < m.resource_count; ++i) {
        const auto res = pack.Get<pack::ResourceRec>(SectionTag::kResources, m.first_resource + i);
        if (!res)
            break;
        const pack::ResourceRec& r = res.value();
        nlohmann::ordered_json e = {{"name", pack.String(r.name)},
                                    {"kind", ResourceKindName(r.kind)},
                                    {"set", r.set},
                                    {"binding", r.binding}};
        if (r.dim != 0)
            e["dim"] = std::string(DimName(r.dim)) + (r.arrayed ? "Array" : "");
        if (r.array_size > 1)
            e["array_size"] = r.array_size;
        j["resources"].push_back(std::move(e));
    }
    return j;
}

std::string Line(const char* format, auto... args) {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, format, args...);
    return buffer;
}

std::string Text(const nlohmann::ordered_json& j) {
    std::string out = "stage " + j["stage"].get<std::string>() + "\n";
    for (const char* dir : {"inputs", "outputs"}) {
        out += std::string(dir) + ":" + (j[dir].empty() ? " none" : "") + "\n";
        for (const auto& v : j[dir]) {
            const std::string where = v.contains("location")
                                          ? "location " + std::to_string(v["location"].get<int>())
                                          : "built-in";
            out += Line("  %-12s %-8s %s", where.c_str(), v["type"].get<std::string>().c_str(),
                        v["name"].get<std::string>().c_str());
            const std::string semantic = v["semantic"].get<std::string>();
            out += semantic.empty() ? "\n" : " : " + semantic + "\n";
        }
    }
    out += std::string("blocks:") + (j["blocks"].empty() ? " none" : "") + "\n";
    for (const auto& b : j["blocks"]) {
        const std::string where = b["kind"] == "push_constant"
                                      ? "push constant"
                                      : "set " + std::to_string(b["set"].get<int>()) + " binding " +
                                            std::to_string(b["binding"].get<int>());
        out += Line("  %-20s %s, %d bytes\n", where.c_str(), b["name"].get<std::string>().c_str(),
                    b["size"].get<int>());
        for (const auto& m : b["members"]) {
            std::string name = m["name"].get<std::string>();
            if (m.contains("array_size"))
                name += "[" + std::to_string(m["array_size"].get<int>()) + "]";
            out += Line("    %4d  %-10s %s\n", m["offset"].get<int>(),
                        m["type"].get<std::string>().c_str(), name.c_str());
        }
    }
    out += std::string("resources:") + (j["resources"].empty() ? " none" : "") + "\n";
    for (const auto& r : j["resources"]) {
        const std::string where = "set " + std::to_string(r["set"].get<int>()) + " binding " +
                                  std::to_string(r["binding"].get<int>());
        std::string kind = r["kind"].get<std::string>();
        if (r.contains("dim"))
            kind += " " + r["dim"].get<std::string>();
        out += Line("  %-20s %-26s %s\n", where.c_str(), kind.c_str(),
                    r["name"].get<std::string>().c_str());
    }
    return out;
}

}  // namespace

std::string ReflectionText(const pack::Pack& pack, const pack::ModuleRec& module, bool json) {
    const nlohmann::ordered_json j = ReflectionJson(pack, module);
    return json ? j.dump(2) + "\n" : Text(j);
}

}  // namespace kiln
