// CreatePipeline: shader modules from the pack's SPIR-V, descriptor-set layouts and push
// constants from the variant's reflection (union of both stages), vertex input by semantic.
#include "vk/pipeline.h"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <map>
#include <set>

#include "kiln/pack/vertex.h"

namespace kiln::vk {
namespace {

using pack::SectionTag;

struct Stream {
    uint32_t offset;
    VkFormat format;
};

// The mesh stream a vertex input reads, by HLSL semantic (kiln/pack/vertex.h).
std::optional<Stream> StreamFor(std::string_view semantic) {
    constexpr VkFormat kFormats[] = {VK_FORMAT_UNDEFINED, VK_FORMAT_R32_SFLOAT,
                                     VK_FORMAT_R32G32_SFLOAT, VK_FORMAT_R32G32B32_SFLOAT,
                                     VK_FORMAT_R32G32B32A32_SFLOAT};
    const std::optional<pack::VertexStream> s = pack::VertexStreamFor(semantic);
    if (!s) {
        return std::nullopt;
    }
    return Stream{s->offset, kFormats[s->components]};
}

VkShaderStageFlags StageBit(uint32_t stage) {
    switch (pack::Stage(stage)) {
        case pack::Stage::kVertex:
            return VK_SHADER_STAGE_VERTEX_BIT;
        case pack::Stage::kFragment:
            return VK_SHADER_STAGE_FRAGMENT_BIT;
        case pack::Stage::kGeometry:
            return VK_SHADER_STAGE_GEOMETRY_BIT;
        case pack::Stage::kTessControl:
            return VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT;
        case pack::Stage::kTessEval:
            return VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT;
    }
    return VK_SHADER_STAGE_VERTEX_BIT;
}

VkDescriptorType DescriptorType(pack::ResourceKind kind) {
    switch (kind) {
        case pack::ResourceKind::kCombinedImageSampler:
            return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        case pack::ResourceKind::kSeparateImage:
            return VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
        case pack::ResourceKind::kSeparateSampler:
            return VK_DESCRIPTOR_TYPE_SAMPLER;
        case pack::ResourceKind::kStorageImage:
            return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
        case pack::ResourceKind::kStorageBuffer:
            return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    }
    return VK_DESCRIPTOR_TYPE_SAMPLER;
}

Status CreateLayout(const Context& c,
                    const pack::Pack& pack,
                    const std::vector<pack::ModuleRec>& modules,
                    VariantLayout& out) {
    // (set, binding) -> layout binding, stages OR-ed across the modules.
    std::map<std::pair<uint32_t, uint32_t>, VkDescriptorSetLayoutBinding> bindings;
    auto add = [&](uint32_t set, uint32_t binding, VkDescriptorType type, uint32_t count,
                   VkShaderStageFlags stage) {
        auto [it, fresh] = bindings.try_emplace({set, binding});
        if (fresh) {
            it->second =
                VkDescriptorSetLayoutBinding{binding, type, std::max(count, 1u), 0, nullptr};
        }
        it->second.stageFlags |= stage;
    };
    for (const pack::ModuleRec& m : modules) {
        const VkShaderStageFlags stage = StageBit(m.stage);
        for (uint32_t i = 0; i < m.block_count; ++i) {
            const auto b = pack.Get<pack::BlockRec>(SectionTag::kBlocks, m.first_block + i).value();
            if (pack::BlockKind(b.kind) == pack::BlockKind::kPushConstant) {
                out.push_constant_size = std::max(out.push_constant_size, b.size);
                out.push_constant_stages |= stage;
            } else {
                add(b.set, b.binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, stage);
            }
        }
        for (uint32_t i = 0; i < m.resource_count; ++i) {
            const auto r =
                pack.Get<pack::ResourceRec>(SectionTag::kResources, m.first_resource + i).value();
            add(r.set, r.binding, DescriptorType(pack::ResourceKind(r.kind)), r.array_size, stage);
        }
    }
    uint32_t set_count = 0;
    for (const auto& [key, b] : bindings) {
        if (key.first >= 8) {
            return Error{DiagCode::kRenderFailed, "descriptor set " + std::to_string(key.first) +
                                                      " is beyond the 8 sets the runtime supports"};
        }
        // The reflection is the pack's too: numbers no Kiln pack uses would reach the driver.
        if (key.second > kMaxBindingNumber || b.descriptorCount > kMaxDescriptorCount) {
            return Error{DiagCode::kBadPack, "the pack's reflection names set " +
                                                 std::to_string(key.first) + " binding " +
                                                 std::to_string(key.second) + " with " +
                                                 std::to_string(b.descriptorCount) +
                                                 " descriptors, more than any Kiln pack uses"};
        }
        set_count = std::max(set_count, key.first + 1);
    }
    if (out.push_constant_size > c.properties.limits.maxPushConstantsSize) {
        return Error{DiagCode::kBadPack,
                     "the variant's push constants take " + std::to_string(out.push_constant_size) +
                         " bytes; the device allows " +
                         std::to_string(c.properties.limits.maxPushConstantsSize)};
    }
    out.bindings.assign(set_count, {});
    for (const auto& [key, b] : bindings) {
        out.bindings[key.first].push_back(b);
    }
    for (uint32_t s = 0; s < set_count; ++s) {
        VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
        info.bindingCount = uint32_t(out.bindings[s].size());
        info.pBindings = out.bindings[s].data();
        VkDescriptorSetLayout layout = VK_NULL_HANDLE;
        if (VkResult r = vkCreateDescriptorSetLayout(c.device, &info, nullptr, &layout);
            r != VK_SUCCESS) {
            return VkError("cannot create a descriptor set layout", r);
        }
        out.sets.push_back(layout);
    }
    VkPushConstantRange push{out.push_constant_stages, 0, out.push_constant_size};
    VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    info.setLayoutCount = uint32_t(out.sets.size());
    info.pSetLayouts = out.sets.data();
    info.pushConstantRangeCount = out.push_constant_size ? 1 : 0;
    info.pPushConstantRanges = &push;
    if (VkResult r = vkCreatePipelineLayout(c.device, &info, nullptr, &out.layout);
        r != VK_SUCCESS) {
        return VkError("cannot create a pipeline layout", r);
    }
    return {};
}

// The name of the module's first OpEntryPoint (Kiln keeps the HLSL function's name), read with
// every word bounds-checked; empty when there is none.
std::string EntryPointName(std::span<const uint32_t> words) {
    constexpr uint32_t kOpEntryPoint = 15;
    for (size_t i = 5; i < words.size();) {
        const uint32_t count = words[i] >> 16, opcode = words[i] & 0xFFFF;
        if (count == 0 || count > words.size() - i) {
            break;
        }
        if (opcode == kOpEntryPoint && count > 3) {
            std::string name;
            for (size_t w = i + 3; w < i + count; ++w) {
                for (int b = 0; b < 4; ++b) {
                    const char ch = char((words[w] >> (8 * b)) & 0xFF);
                    if (ch == 0) {
                        return name;
                    }
                    name += ch;
                }
            }
            return name;
        }
        i += count;
    }
    return {};
}

bool DeclaresCapability(std::span<const uint32_t> words, uint32_t capability) {
    constexpr uint32_t kOpCapability = 17;
    for (size_t i = 5; i < words.size();) {
        const uint32_t count = words[i] >> 16, opcode = words[i] & 0xFFFF;
        if (count == 0 || count > words.size() - i) {
            break;
        }
        if (opcode == kOpCapability && count == 2 && words[i + 1] == capability) {
            return true;
        }
        i += count;
    }
    return false;
}

}  // namespace

Status CreatePipeline(const Context& c,
                      const pack::Pack& pack,
                      uint32_t variant,
                      const RenderState& state,
                      const PipelineTargets& targets,
                      VkPipelineCache cache,
                      ModuleChecker* checker,
                      Pipeline& out) {
    const pack::VariantRec v = pack.Variant(variant).value();
    std::vector<pack::ModuleRec> modules = {pack.Module(v.vertex_module).value(),
                                            pack.Module(v.fragment_module).value()};
    Pipeline p;
    auto fail = [&](Error e) {
        DestroyPipeline(c, p);
        return Status(std::move(e));
    };
    // Geometry and tessellation stages (the reader checked each module's stage).
    const Result<pack::VariantStagesRec> extra = pack.Stages(v);
    if (!extra)
        return fail(extra.error());
    for (uint32_t m : {extra.value().geometry_module, extra.value().tess_control_module,
                       extra.value().tess_eval_module}) {
        if (m != pack::kNoModule)
            modules.push_back(pack.Module(m).value());
    }
    const bool tessellated = extra.value().tess_control_module != pack::kNoModule;
    if (extra.value().geometry_module != pack::kNoModule && !c.geometry_shader) {
        return fail(Error{DiagCode::kRenderFailed,
                          std::string("the variant has a geometry stage (#pragma geometry) and "
                                      "device '") +
                              c.properties.deviceName + "' has no geometryShader feature"});
    }
    if (tessellated && !c.tessellation_shader) {
        return fail(Error{DiagCode::kRenderFailed,
                          std::string("the variant has tessellation stages (#pragma hull and "
                                      "domain) and device '") +
                              c.properties.deviceName + "' has no tessellationShader feature"});
    }
    if (Status e = CreateLayout(c, pack, modules, p.layout); !e.ok()) {
        return fail(e.error());
    }
    std::set<std::pair<uint32_t, uint32_t>> layout;
    for (uint32_t s = 0; s < p.layout.bindings.size(); ++s) {
        for (const VkDescriptorSetLayoutBinding& b : p.layout.bindings[s])
            layout.insert({s, b.binding});
    }
    std::vector<std::string> entry_points(modules.size());
    for (size_t i = 0; i < modules.size(); ++i) {
        const std::span<const uint8_t> spirv = pack.Spirv(modules[i]);
        if (spirv.empty()) {  // its bytes do not match the module's hash (checked on first use)
            return fail(Error{DiagCode::kPackChecksum,
                              "a SPIR-V module of the variant does not match its checksum (pack "
                              "corrupted)"});
        }
        std::vector<uint32_t> words(spirv.size() / 4);
        std::memcpy(words.data(), spirv.data(), words.size() * 4);
        if (checker != nullptr) {
            if (Status e = checker->Check(words, pack::Stage(modules[i].stage), layout); !e.ok())
                return fail(e.error());
        }
        entry_points[i] = EntryPointName(words);
        constexpr uint32_t kCapabilityFloat16 = 9;
        if (!c.shader_float16 && DeclaresCapability(words, kCapabilityFloat16)) {
            return fail(Error{DiagCode::kRenderFailed,
                              std::string("the variant computes in 16-bit floats (compiled with "
                                          "--precision half) and device '") +
                                  c.properties.deviceName +
                                  "' has no shaderFloat16; compile with --precision relaxed"});
        }
        if (entry_points[i].empty()) {
            return fail(Error{DiagCode::kRenderFailed,
                              "a SPIR-V module of the variant has no entry point"});
        }
        VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        info.codeSize = words.size() * 4;
        info.pCode = words.data();
        if (VkResult r = vkCreateShaderModule(c.device, &info, nullptr, &p.modules[i]);
            r != VK_SUCCESS) {
            return fail(VkError("cannot create a shader module", r));
        }
    }

    // Vertex input: one interleaved binding, an attribute per reflected input location.
    std::vector<VkVertexInputAttributeDescription> attributes;
    const pack::ModuleRec& vs = modules[0];
    for (uint32_t i = 0; i < vs.interface_count; ++i) {
        const auto var =
            pack.Get<pack::InterfaceVarRec>(SectionTag::kInterface, vs.first_interface + i).value();
        if (var.direction != 0 || var.location == ~0u) {
            continue;
        }
        const std::string_view semantic = pack.String(var.semantic);
        const std::optional<Stream> stream = StreamFor(semantic);
        if (!stream) {
            return fail(Error{DiagCode::kRenderFailed,
                              "vertex input '" + std::string(pack.String(var.name)) +
                                  "' has semantic '" + std::string(semantic) +
                                  "', which no mesh stream provides (POSITION, NORMAL, "
                                  "TEXCOORD0, TEXCOORD1, TANGENT, COLOR)"});
        }
        attributes.push_back({var.location, 0, stream->format, stream->offset});
    }
    VkVertexInputBindingDescription binding{0, sizeof(pack::MeshVertex),
                                            VK_VERTEX_INPUT_RATE_VERTEX};
    VkPipelineVertexInputStateCreateInfo input{
        VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    input.vertexBindingDescriptionCount = attributes.empty() ? 0 : 1;
    input.pVertexBindingDescriptions = &binding;
    input.vertexAttributeDescriptionCount = uint32_t(attributes.size());
    input.pVertexAttributeDescriptions = attributes.data();

    std::vector<VkPipelineShaderStageCreateInfo> stages(modules.size());
    for (size_t i = 0; i < modules.size(); ++i) {
        stages[i].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
        stages[i].stage = VkShaderStageFlagBits(StageBit(modules[i].stage));
        stages[i].module = p.modules[i];
        stages[i].pName = entry_points[i].c_str();
    }
    VkPipelineInputAssemblyStateCreateInfo assembly{
        VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    // Unity tessellates the mesh's triangles: each is a patch of three control points (a hull
    // shader's InputPatch<T, 3>).
    VkPipelineTessellationStateCreateInfo tessellation{
        VK_STRUCTURE_TYPE_PIPELINE_TESSELLATION_STATE_CREATE_INFO};
    tessellation.patchControlPoints = 3;
    if (tessellated)
        assembly.topology = VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
    VkPipelineViewportStateCreateInfo viewport{
        VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo raster{
        VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = state.cull;
    // The projection is right-handed and the viewport is flipped (negative height), so glTF's
    // counter-clockwise front faces stay counter-clockwise; a mirroring transform reverses them.
    raster.frontFace =
        state.front_clockwise ? VK_FRONT_FACE_CLOCKWISE : VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.depthBiasEnable = state.offset_factor != 0 || state.offset_units != 0;
    raster.depthBiasSlopeFactor = state.offset_factor;
    raster.depthBiasConstantFactor = state.offset_units;
    raster.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo multisample{
        VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = targets.samples;
    VkPipelineDepthStencilStateCreateInfo depth{
        VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depth.depthTestEnable = state.depth_test;
    depth.depthWriteEnable = state.zwrite;
    depth.depthCompareOp = state.ztest;
    depth.stencilTestEnable = state.stencil;
    auto face = [&](const StencilFace& f) {
        return VkStencilOpState{
            f.fail,           f.pass, f.zfail, f.compare, state.stencil_read, state.stencil_write,
            state.stencil_ref};
    };
    depth.front = face(state.front);
    depth.back = face(state.back);
    std::vector<VkPipelineColorBlendAttachmentState> blends(targets.color_count);
    for (uint32_t i = 0; i < targets.color_count; ++i) {
        const BlendTarget& t = state.targets[i];
        blends[i] = {t.enable, t.src, t.dst, t.op, t.src_alpha, t.dst_alpha, t.op_alpha, t.mask};
    }
    for (uint32_t i = 0; i < targets.color_count; ++i) {
        if (state.targets[i].enable && state.targets[i].advanced) {
            return fail(
                Error{DiagCode::kRenderFailed,
                      "an advanced BlendOp (Multiply, Screen, ... HSLLuminosity) needs "
                      "VK_EXT_blend_operation_advanced, which Kiln's renderer does not enable"});
        }
    }
    if (state.logic_op_enable && !c.logic_op) {
        return fail(Error{DiagCode::kRenderFailed,
                          "a Logical* BlendOp needs the logicOp feature, which this "
                          "Vulkan device does not support"});
    }
    VkPipelineColorBlendStateCreateInfo blend{
        VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend.logicOpEnable = state.logic_op_enable;
    blend.logicOp = state.logic_op;
    blend.attachmentCount = targets.color_count;
    blend.pAttachments = blends.data();
    const VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dynamic.dynamicStateCount = 2;
    dynamic.pDynamicStates = dynamic_states;

    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.stageCount = uint32_t(stages.size());
    info.pStages = stages.data();
    info.pTessellationState = tessellated ? &tessellation : nullptr;
    info.pVertexInputState = &input;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &blend;
    info.pDynamicState = &dynamic;
    info.layout = p.layout.layout;
    info.renderPass = targets.render_pass;
    if (VkResult r = vkCreateGraphicsPipelines(c.device, cache, 1, &info, nullptr, &p.pipeline);
        r != VK_SUCCESS) {
        return fail(VkError("cannot create a graphics pipeline", r));
    }
    out = p;
    return {};
}

void DestroyPipeline(const Context& c, Pipeline& p) {
    if (p.pipeline) {
        vkDestroyPipeline(c.device, p.pipeline, nullptr);
    }
    if (p.layout.layout) {
        vkDestroyPipelineLayout(c.device, p.layout.layout, nullptr);
    }
    for (VkDescriptorSetLayout s : p.layout.sets) {
        vkDestroyDescriptorSetLayout(c.device, s, nullptr);
    }
    for (VkShaderModule m : p.modules) {
        if (m) {
            vkDestroyShaderModule(c.device, m, nullptr);
        }
    }
    p = Pipeline{};
}

}  // namespace kiln::vk
