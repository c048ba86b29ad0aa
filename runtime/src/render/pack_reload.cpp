// Live edit in the runtime: Renderer::ReplacePack and RemovePack (kiln/runtime/renderer.h). A
// replaced pack's pipelines are matched to the new pack's variants by content: the SPIR-V of
// every stage and the reflection its layout and vertex input are made from.
#include <xxhash.h>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string_view>

#include "kiln/runtime/renderer.h"
#include "render/frame_cache.h"
#include "render/renderer_state.h"

namespace kiln::runtime {
namespace {

using pack::SectionTag;

class Hasher {
  public:
    Hasher() : state_(XXH64_createState()) { XXH64_reset(state_, 0); }
    ~Hasher() { XXH64_freeState(state_); }
    Hasher(const Hasher&) = delete;
    Hasher& operator=(const Hasher&) = delete;

    void Add(uint64_t v) { XXH64_update(state_, &v, sizeof v); }
    void Add(std::string_view s) {
        Add(uint64_t{s.size()});
        XXH64_update(state_, s.data(), s.size());
    }
    uint64_t Digest() const { return XXH64_digest(state_); }

  private:
    XXH64_state_t* state_;
};

// What a pipeline of `variant` is made from: each stage's SPIR-V (by its hash) and reflection,
// strings by their text (their offsets differ between packs). Records are read through Get, so
// a record the pack does not hold is skipped (the pack's variant data was checked before).
uint64_t ContentKey(const pack::Pack& p, uint32_t variant) {
    Hasher h;
    const Result<pack::VariantRec> v = p.Variant(variant);
    if (!v)
        return 0;
    for (uint32_t index : p.ModulesOf(v.value())) {
        const Result<pack::ModuleRec> m = p.Module(index);
        if (!m)
            return 0;
        const pack::ModuleRec& mod = m.value();
        h.Add(mod.hash);
        h.Add(mod.stage);
        h.Add(mod.spirv_size);
        for (uint32_t i = mod.first_interface; i < mod.first_interface + mod.interface_count; ++i) {
            if (const auto r = p.Get<pack::InterfaceVarRec>(SectionTag::kInterface, i); r) {
                const pack::InterfaceVarRec& x = r.value();
                h.Add(p.String(x.name));
                h.Add(p.String(x.semantic));
                h.Add(uint64_t{x.location} << 32 | x.direction);
                h.Add(uint64_t{x.base_type} << 32 | x.vecsize);
            }
        }
        for (uint32_t i = mod.first_block; i < mod.first_block + mod.block_count; ++i) {
            const auto r = p.Get<pack::BlockRec>(SectionTag::kBlocks, i);
            if (!r)
                continue;
            const pack::BlockRec& b = r.value();
            h.Add(p.String(b.name));
            h.Add(uint64_t{b.kind} << 32 | b.set);
            h.Add(uint64_t{b.binding} << 32 | b.size);
            for (uint32_t k = b.first_member; k < b.first_member + b.member_count; ++k) {
                if (const auto mr = p.Get<pack::MemberRec>(SectionTag::kMembers, k); mr) {
                    const pack::MemberRec& x = mr.value();
                    h.Add(p.String(x.name));
                    h.Add(uint64_t{x.offset} << 32 | x.size);
                    h.Add(uint64_t{x.base_type} << 32 | x.vecsize);
                    h.Add(uint64_t{x.columns} << 32 | x.array_size);
                }
            }
        }
        for (uint32_t i = mod.first_resource; i < mod.first_resource + mod.resource_count; ++i) {
            if (const auto r = p.Get<pack::ResourceRec>(SectionTag::kResources, i); r) {
                const pack::ResourceRec& x = r.value();
                h.Add(p.String(x.name));
                h.Add(uint64_t{x.kind} << 32 | x.set);
                h.Add(uint64_t{x.binding} << 32 | x.dim);
                h.Add(uint64_t{x.arrayed} << 32 | x.array_size);
            }
        }
    }
    return h.Digest();
}

Error BadIndex(size_t index, size_t count) {
    return Error{DiagCode::kIndexOutOfRange, "pack " + std::to_string(index) +
                                                 " is out of range (the renderer has " +
                                                 std::to_string(count) + " packs)"};
}

// Nothing a frame made from the old pack is kept: material instances, uniform layouts and
// descriptor sets are made again on the next frame. Frames wait for the device before they
// return, so nothing is in flight; the wait is for work a caller may have submitted otherwise.
void ForgetFrames(Renderer::State& s) {
    vkDeviceWaitIdle(s.context.device);
    s.scene_resources.reset();
    s.frame_cache.reset();
}

// The pipelines of pack `index`: each kept, re-tagged to the variant `new_variant` gives for its
// old one, or destroyed where it gives none. Other packs' pipelines are untouched.
Renderer::PackReload KeepPipelines(
    Renderer::State& s,
    size_t index,
    const std::function<std::optional<uint32_t>(uint32_t)>& new_variant) {
    Renderer::PackReload out;
    std::deque<PipelineEntry> kept;
    for (PipelineEntry& p : s.pipelines) {
        if (p.pack == index) {
            const std::optional<uint32_t> v = new_variant(p.variant);
            if (!v) {
                vk::DestroyPipeline(s.context, p.pipeline);
                ++out.pipelines_dropped;
                continue;
            }
            p.variant = *v;
            ++out.pipelines_kept;
        }
        kept.push_back(std::move(p));
    }
    s.pipelines = std::move(kept);
    return out;
}

}  // namespace

Result<Renderer::PackReload> Renderer::ReplacePack(size_t index, const std::string& path) {
    State& s = *state_;
    if (index >= s.packs.size())
        return BadIndex(index, s.packs.size());
    auto loaded = std::make_unique<LoadedPack>();
    loaded->path = path;
    Result<pack::MappedFile> mapped = pack::MappedFile::Map(path);
    if (!mapped)
        return mapped.error();
    loaded->file = std::move(mapped).value();
    Result<pack::Pack> opened =
        pack::Pack::Open(loaded->file.bytes(), pack::OpenChecks::kOnFirstUse);
    if (!opened)
        return Error{opened.error().code, path + ": " + opened.error().message};
    loaded->pack = std::move(opened).value();
    // Every variant's content is read below: its damage is reported now, the old pack kept.
    if (Status checked = loaded->pack.CheckVariantData(); !checked.ok())
        return Error{checked.error().code, path + ": " + checked.error().message};
    loaded->selector =
        std::make_unique<pack::VariantSelector>(loaded->pack, s.options.missing_variant);

    std::map<uint64_t, uint32_t> by_content;  // the new pack's variants
    for (uint32_t v = 0; v < loaded->pack.Count(SectionTag::kVariants); ++v)
        by_content.emplace(ContentKey(loaded->pack, v), v);

    ForgetFrames(s);
    const pack::Pack& old = s.packs[index]->pack;
    const PackReload out =
        KeepPipelines(s, index, [&](uint32_t variant) -> std::optional<uint32_t> {
            const auto it = by_content.find(ContentKey(old, variant));
            return it == by_content.end() ? std::nullopt : std::optional<uint32_t>(it->second);
        });
    s.packs[index] = std::move(loaded);
    return out;
}

Status Renderer::RemovePack(size_t index) {
    State& s = *state_;
    if (index >= s.packs.size())
        return BadIndex(index, s.packs.size());
    ForgetFrames(s);
    (void)KeepPipelines(s, index, [](uint32_t) { return std::optional<uint32_t>(); });
    auto empty = std::make_unique<LoadedPack>();  // finds no shader; the index stays taken
    empty->selector =
        std::make_unique<pack::VariantSelector>(empty->pack, s.options.missing_variant);
    s.packs[index] = std::move(empty);
    return {};
}

}  // namespace kiln::runtime
