#include "spirv/reflect.h"

#include <algorithm>
#include <cctype>
#include <exception>
#include <tuple>

#include <spirv_cross/spirv_cross.hpp>

namespace kiln::spirv {
namespace {

using spirv_cross::SPIRType;

pack::BaseType BaseTypeOf(const SPIRType& t) {
    switch (t.basetype) {
        case SPIRType::Boolean:
            return pack::BaseType::kBool;
        case SPIRType::Int:
            return pack::BaseType::kInt;
        case SPIRType::UInt:
            return pack::BaseType::kUInt;
        case SPIRType::Float:
            return pack::BaseType::kFloat;
        case SPIRType::Half:
            return pack::BaseType::kHalf;
        case SPIRType::Double:
            return pack::BaseType::kDouble;
        case SPIRType::Struct:
            return pack::BaseType::kStruct;
        default:
            return pack::BaseType::kUnknown;
    }
}

pack::ImageDim DimOf(const SPIRType& t) {
    switch (t.image.dim) {
        case spv::Dim1D:
            return pack::ImageDim::k1D;
        case spv::Dim2D:
            return pack::ImageDim::k2D;
        case spv::Dim3D:
            return pack::ImageDim::k3D;
        case spv::DimCube:
            return pack::ImageDim::kCube;
        case spv::DimBuffer:
            return pack::ImageDim::kBuffer;
        default:
            return pack::ImageDim::kNone;
    }
}

std::string Upper(std::string s) {
    for (char& c : s)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

struct State {
    spirv_cross::Compiler& c;
    Reflection& out;

    std::string NameOf(const spirv_cross::Resource& r) {
        std::string name = c.get_name(r.id);
        if (name.empty())
            name = c.get_name(r.base_type_id);
        if (name.empty())
            name = r.name;
        return name;
    }

    void Interface(const spirv_cross::SmallVector<spirv_cross::Resource>& list, uint32_t dir) {
        for (const auto& r : list) {
            if (c.has_decoration(r.id, spv::DecorationBuiltIn))
                continue;
            const SPIRType& t = c.get_type(r.type_id);
            InterfaceVar v;
            v.name = c.get_name(r.id);
            v.semantic = Upper(c.get_decoration_string(r.id, spv::DecorationHlslSemanticGOOGLE));
            v.location = c.has_decoration(r.id, spv::DecorationLocation)
                             ? c.get_decoration(r.id, spv::DecorationLocation)
                             : ~0u;
            v.direction = dir;
            v.base_type = BaseTypeOf(t);
            v.vecsize = t.vecsize;
            out.interface.push_back(std::move(v));
        }
    }

    void Blocks(const spirv_cross::SmallVector<spirv_cross::Resource>& list, pack::BlockKind kind) {
        for (const auto& r : list) {
            const SPIRType& t = c.get_type(r.base_type_id);
            Block b;
            b.name = NameOf(r);
            b.kind = kind;
            if (kind == pack::BlockKind::kUniform) {
                b.set = c.get_decoration(r.id, spv::DecorationDescriptorSet);
                b.binding = c.get_decoration(r.id, spv::DecorationBinding);
            }
            b.size = static_cast<uint32_t>(c.get_declared_struct_size(t));
            for (uint32_t i = 0; i < t.member_types.size(); ++i) {
                const SPIRType& mt = c.get_type(t.member_types[i]);
                BlockMember m;
                m.name = c.get_member_name(r.base_type_id, i);
                m.offset = c.type_struct_member_offset(t, i);
                m.size = static_cast<uint32_t>(c.get_declared_struct_member_size(t, i));
                m.base_type = BaseTypeOf(mt);
                m.vecsize = mt.vecsize;
                m.columns = mt.columns;
                m.array_size = mt.array.empty() ? 0 : mt.array[0];
                b.members.push_back(std::move(m));
            }
            out.blocks.push_back(std::move(b));
        }
    }

    void Resources(const spirv_cross::SmallVector<spirv_cross::Resource>& list,
                   pack::ResourceKind kind) {
        for (const auto& r : list) {
            const SPIRType& t = c.get_type(r.type_id);
            Resource res;
            res.name = NameOf(r);
            res.kind = kind;
            res.set = c.get_decoration(r.id, spv::DecorationDescriptorSet);
            res.binding = c.get_decoration(r.id, spv::DecorationBinding);
            if (t.basetype == SPIRType::Image || t.basetype == SPIRType::SampledImage) {
                res.dim = DimOf(t);
                res.arrayed = t.image.arrayed;
            }
            res.array_size = t.array.empty() ? 1 : t.array[0];
            out.resources.push_back(std::move(res));
        }
    }
};

}  // namespace

Result<Reflection> Reflect(const std::vector<uint32_t>& words) {
    Reflection out;
    try {
        spirv_cross::Compiler compiler(words);
        const spirv_cross::ShaderResources res = compiler.get_shader_resources();
        State st{compiler, out};
        st.Interface(res.stage_inputs, 0);
        st.Interface(res.stage_outputs, 1);
        st.Blocks(res.uniform_buffers, pack::BlockKind::kUniform);
        st.Blocks(res.push_constant_buffers, pack::BlockKind::kPushConstant);
        st.Resources(res.sampled_images, pack::ResourceKind::kCombinedImageSampler);
        st.Resources(res.separate_images, pack::ResourceKind::kSeparateImage);
        st.Resources(res.separate_samplers, pack::ResourceKind::kSeparateSampler);
        st.Resources(res.storage_images, pack::ResourceKind::kStorageImage);
        st.Resources(res.storage_buffers, pack::ResourceKind::kStorageBuffer);
    } catch (const std::exception& e) {
        return Error{DiagCode::kInternalError, e.what()};
    }
    std::stable_sort(out.interface.begin(), out.interface.end(), [](const auto& a, const auto& b) {
        return std::tie(a.direction, a.location, a.name) <
               std::tie(b.direction, b.location, b.name);
    });
    std::stable_sort(out.blocks.begin(), out.blocks.end(), [](const auto& a, const auto& b) {
        return std::tie(a.kind, a.set, a.binding, a.name) <
               std::tie(b.kind, b.set, b.binding, b.name);
    });
    std::stable_sort(out.resources.begin(), out.resources.end(), [](const auto& a, const auto& b) {
        return std::tie(a.set, a.binding, a.name) < std::tie(b.set, b.binding, b.name);
    });
    return out;
}

}  // namespace kiln::spirv
