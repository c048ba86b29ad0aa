#include "kiln/show.h"

#include <exception>
#include <memory>
#include <vector>

#include <spirv-tools/libspirv.hpp>
#include <spirv_cross/spirv_glsl.hpp>
#include <spirv_cross/spirv_hlsl.hpp>
#include <spirv_cross/spirv_msl.hpp>

namespace kiln {

namespace {

constexpr spv_target_env kEnv = SPV_ENV_VULKAN_1_1;  // what Kiln compiles for (spirv/optimize)

Error ShowError(std::string message) {
    return Error{DiagCode::kCannotShowModule, std::move(message)};
}

// spirv-val's verdict on the module: empty when valid.
std::string Validate(std::span<const uint32_t> words) {
    spvtools::SpirvTools tools(kEnv);
    std::string message;
    tools.SetMessageConsumer(
        [&](spv_message_level_t, const char*, const spv_position_t&, const char* m) {
            if (message.empty())
                message = m;
        });
    if (tools.Validate(words.data(), words.size()))
        return "";
    return message.empty() ? "the module is not valid SPIR-V" : message;
}

Result<std::string> Disassemble(std::span<const uint32_t> words) {
    spvtools::SpirvTools tools(kEnv);
    std::string text;
    const uint32_t options = SPV_BINARY_TO_TEXT_OPTION_FRIENDLY_NAMES |
                             SPV_BINARY_TO_TEXT_OPTION_INDENT | SPV_BINARY_TO_TEXT_OPTION_COMMENT;
    if (!tools.Disassemble(words.data(), words.size(), &text, options))
        return ShowError("the SPIR-V disassembler cannot read the module");
    return text;
}

// An identifier from a reflected name: "i.uv" -> "i_uv", "@entryPointOutput" -> "entryPointOutput".
std::string Identifier(std::string_view name) {
    std::string out;
    for (char c : name) {
        const bool ok =
            (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
        if (ok)
            out += c;
        else if (c != '@' && c != '$')
            out += '_';
    }
    if (out.empty() || (out[0] >= '0' && out[0] <= '9'))
        out.insert(0, "_");
    return out;
}

// The names the pack's reflection records give the module's blocks, members, resources and
// stage variables, matched by set and binding, push-constant storage, or location.
void NameFromPack(spirv_cross::Compiler& c, const pack::Pack& pack, const pack::ModuleRec& m) {
    using pack::SectionTag;
    const spirv_cross::ShaderResources res = c.get_shader_resources();
    auto name_block = [&](const spirv_cross::Resource& r, bool push) {
        const uint32_t set = c.get_decoration(r.id, spv::DecorationDescriptorSet);
        const uint32_t binding = c.get_decoration(r.id, spv::DecorationBinding);
        for (uint32_t i = 0; i < m.block_count; ++i) {
            const auto b = pack.Get<pack::BlockRec>(SectionTag::kBlocks, m.first_block + i);
            if (!b || (b.value().kind == uint32_t(pack::BlockKind::kPushConstant)) != push ||
                (!push && (b.value().set != set || b.value().binding != binding)))
                continue;
            const std::string name = Identifier(pack.String(b.value().name));
            c.set_name(r.base_type_id, name);
            c.set_name(r.id, "_" + name);
            const spirv_cross::SPIRType& type = c.get_type(r.base_type_id);
            for (uint32_t k = 0; k < type.member_types.size(); ++k) {
                const uint32_t offset = c.type_struct_member_offset(type, k);
                for (uint32_t j = 0; j < b.value().member_count; ++j) {
                    const auto mem =
                        pack.Get<pack::MemberRec>(SectionTag::kMembers, b.value().first_member + j);
                    if (mem && mem.value().offset == offset) {
                        c.set_member_name(r.base_type_id, k,
                                          Identifier(pack.String(mem.value().name)));
                        break;
                    }
                }
            }
            return;
        }
    };
    for (const spirv_cross::Resource& r : res.uniform_buffers)
        name_block(r, false);
    for (const spirv_cross::Resource& r : res.push_constant_buffers)
        name_block(r, true);
    auto name_resource = [&](const spirv_cross::Resource& r) {
        const uint32_t set = c.get_decoration(r.id, spv::DecorationDescriptorSet);
        const uint32_t binding = c.get_decoration(r.id, spv::DecorationBinding);
        for (uint32_t i = 0; i < m.resource_count; ++i) {
            const auto rec =
                pack.Get<pack::ResourceRec>(SectionTag::kResources, m.first_resource + i);
            if (rec && rec.value().set == set && rec.value().binding == binding) {
                c.set_name(r.id, Identifier(pack.String(rec.value().name)));
                return;
            }
        }
    };
    for (const auto* list : {&res.sampled_images, &res.separate_images, &res.separate_samplers,
                             &res.storage_images, &res.storage_buffers}) {
        for (const spirv_cross::Resource& r : *list)
            name_resource(r);
    }
    auto name_stage = [&](const spirv_cross::Resource& r, uint32_t direction) {
        if (!c.has_decoration(r.id, spv::DecorationLocation))
            return;
        const uint32_t location = c.get_decoration(r.id, spv::DecorationLocation);
        for (uint32_t i = 0; i < m.interface_count; ++i) {
            const auto v =
                pack.Get<pack::InterfaceVarRec>(SectionTag::kInterface, m.first_interface + i);
            if (v && v.value().direction == direction && v.value().location == location) {
                c.set_name(r.id, (direction == 0 ? "in_" : "out_") +
                                     Identifier(pack.String(v.value().name)));
                return;
            }
        }
    };
    for (const spirv_cross::Resource& r : res.stage_inputs)
        name_stage(r, 0);
    for (const spirv_cross::Resource& r : res.stage_outputs)
        name_stage(r, 1);
}

struct Names {
    const pack::Pack* pack = nullptr;
    const pack::ModuleRec* module = nullptr;
    void Apply(spirv_cross::Compiler& c) const {
        if (pack && module)
            NameFromPack(c, *pack, *module);
    }
};

// GLSL and ESSL. ESSL (and GLSL without Vulkan semantics) has no separate images and samplers:
// each pair used together becomes one combined sampler named after both.
std::string CrossGlsl(std::vector<uint32_t> words, bool es, const Names& names) {
    spirv_cross::CompilerGLSL glsl(std::move(words));
    names.Apply(glsl);
    spirv_cross::CompilerGLSL::Options options = glsl.get_common_options();
    options.es = es;
    options.version = es ? 310 : 450;
    options.vulkan_semantics = !es;
    glsl.set_common_options(options);
    if (es) {
        glsl.build_combined_image_samplers();
        for (const spirv_cross::CombinedImageSampler& c : glsl.get_combined_image_samplers()) {
            glsl.set_name(c.combined_id,
                          glsl.get_name(c.image_id) + "_" + glsl.get_name(c.sampler_id));
        }
    }
    return glsl.compile();
}

std::string CrossMsl(std::vector<uint32_t> words, const Names& names) {
    spirv_cross::CompilerMSL msl(std::move(words));
    names.Apply(msl);
    spirv_cross::CompilerMSL::Options options = msl.get_msl_options();
    options.platform = spirv_cross::CompilerMSL::Options::macOS;
    options.set_msl_version(2, 1);
    msl.set_msl_options(options);
    return msl.compile();
}

std::string CrossHlsl(std::vector<uint32_t> words, const Names& names) {
    spirv_cross::CompilerHLSL hlsl(std::move(words));
    names.Apply(hlsl);
    spirv_cross::CompilerHLSL::Options options = hlsl.get_hlsl_options();
    options.shader_model = 50;
    hlsl.set_hlsl_options(options);
    return hlsl.compile();
}

}  // namespace

std::string_view ModuleViewName(ModuleView view) {
    switch (view) {
        case ModuleView::kSpirv:
            return "spirv";
        case ModuleView::kGlsl:
            return "glsl";
        case ModuleView::kEssl:
            return "essl";
        case ModuleView::kMsl:
            return "msl";
        case ModuleView::kCrossHlsl:
            return "cross-hlsl";
    }
    return "";
}

Result<std::string> ViewModule(std::span<const uint32_t> words,
                               ModuleView view,
                               const pack::Pack* pack,
                               const pack::ModuleRec* module) {
    const Names names{pack, module};
    if (words.empty())
        return ShowError("the module is empty");
    if (std::string invalid = Validate(words); !invalid.empty())
        return ShowError("the module is not valid SPIR-V: " + invalid);
    if (view == ModuleView::kSpirv)
        return Disassemble(words);
    // SPIRV-Cross reports what it cannot express by throwing; nothing leaves this function.
    try {
        std::vector<uint32_t> copy(words.begin(), words.end());
        switch (view) {
            case ModuleView::kGlsl:
                return CrossGlsl(std::move(copy), false, names);
            case ModuleView::kEssl:
                return CrossGlsl(std::move(copy), true, names);
            case ModuleView::kMsl:
                return CrossMsl(std::move(copy), names);
            case ModuleView::kCrossHlsl:
                return CrossHlsl(std::move(copy), names);
            case ModuleView::kSpirv:
                break;
        }
    } catch (const std::exception& e) {
        return ShowError("SPIRV-Cross cannot write the module as " +
                         std::string(ModuleViewName(view)) + ": " + e.what());
    }
    return ShowError("unknown view");
}

}  // namespace kiln
