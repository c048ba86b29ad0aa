// Pack::Open on packs of 3 MB and 125 MB, so that the cost of opening can be compared across
// sizes in one run (issue 43: a 125 MB pack opens within 2x of a 3 MB one). The packs are made
// here from the shipped materials pack's modules: one pass whose variants each get a vertex and a
// fragment module copied from it, made distinct by their SPIR-V generator word, each with the
// reflection of the module it copies, until the pack reaches its size. So a large pack is large
// as a real one is: in variants, modules, reflection and SPIR-V, not in shaders or passes.
#include <benchmark/benchmark.h>

#include <deque>
#include <map>
#include <string>
#include <vector>

#include "kiln/pack/reader.h"
#include "pack/pack_builder.h"

namespace {

using namespace kiln::pack;
using kiln::spirv::Reflection;

// A module's reflection as the pack stores it, back in the compiler's form.
Reflection ReflectionOf(const Pack& p, const ModuleRec& m) {
    Reflection r;
    for (uint32_t i = m.first_interface; i < m.first_interface + m.interface_count; ++i) {
        const auto v = p.Get<InterfaceVarRec>(SectionTag::kInterface, i).value();
        r.interface.push_back({std::string(p.String(v.name)), std::string(p.String(v.semantic)),
                               v.location, v.direction, BaseType(v.base_type), v.vecsize});
    }
    for (uint32_t i = m.first_block; i < m.first_block + m.block_count; ++i) {
        const auto b = p.Get<BlockRec>(SectionTag::kBlocks, i).value();
        kiln::spirv::Block block{
            std::string(p.String(b.name)), BlockKind(b.kind), b.set, b.binding, b.size, {}};
        for (uint32_t k = b.first_member; k < b.first_member + b.member_count; ++k) {
            const auto mem = p.Get<MemberRec>(SectionTag::kMembers, k).value();
            block.members.push_back({std::string(p.String(mem.name)), mem.offset, mem.size,
                                     BaseType(mem.base_type), mem.vecsize, mem.columns,
                                     mem.array_size});
        }
        r.blocks.push_back(std::move(block));
    }
    for (uint32_t i = m.first_resource; i < m.first_resource + m.resource_count; ++i) {
        const auto s = p.Get<ResourceRec>(SectionTag::kResources, i).value();
        r.resources.push_back({std::string(p.String(s.name)), ResourceKind(s.kind), s.set,
                               s.binding, ImageDim(s.dim), s.arrayed != 0, s.array_size});
    }
    return r;
}

// A pack of about `target` bytes: one pass of variants over the materials pack's modules.
std::vector<uint8_t> MakePack(size_t target) {
    auto file = MappedFile::Map(KILN_MATERIALS_PACK);
    if (!file)
        return {};
    auto opened = Pack::Open(file.value().bytes());
    if (!opened)
        return {};
    const Pack& source = opened.value();
    std::vector<uint32_t> vertex, fragment;  // the source's modules by stage
    for (uint32_t m = 0; m < source.Count(SectionTag::kModules); ++m) {
        const ModuleRec rec = source.Module(m).value();
        if (rec.stage == uint32_t(Stage::kVertex))
            vertex.push_back(m);
        if (rec.stage == uint32_t(Stage::kFragment))
            fragment.push_back(m);
    }
    if (vertex.empty() || fragment.empty())
        return {};
    std::deque<Reflection> reflections;  // outlive the builder's use of them
    std::map<uint32_t, const Reflection*> reflection_of;
    for (uint32_t m = 0; m < source.Count(SectionTag::kModules); ++m) {
        reflections.push_back(ReflectionOf(source, source.Module(m).value()));
        reflection_of[m] = &reflections.back();
    }

    kiln::pack_builder::PackBuilder b;
    constexpr uint32_t kSets = 4, kPerSet = 16;  // up to 65,536 variants, key = variant index
    for (uint32_t s = 0; s < kSets; ++s) {
        KeywordSetRec set;
        set.first_keyword = static_cast<uint32_t>(b.keywords.size());
        set.keyword_count = kPerSet;
        set.key_shift = 4 * s;
        set.key_bits = BitsForCount(kPerSet);
        for (uint32_t k = 0; k < kPerSet; ++k)
            b.keywords.push_back(b.Str("K" + std::to_string(s) + "_" + std::to_string(k)));
        b.keyword_sets.push_back(set);
    }
    ShaderRec shader;
    shader.name = b.Str("Bench/LargePack");
    shader.pass_count = 1;
    b.shaders.push_back(shader);
    PassRec pass;
    pass.name = b.Str("Large");
    pass.keyword_set_count = kSets;
    size_t bytes = 0;
    std::vector<uint32_t> words;
    auto copy = [&](uint32_t module, uint32_t stamp) {
        const ModuleRec rec = source.Module(module).value();
        const std::span<const uint32_t> from = source.SpirvWords(rec);
        words.assign(from.begin(), from.end());
        words[2] = stamp;  // the generator word: any value is valid SPIR-V
        size_t members = 0;
        for (const kiln::spirv::Block& block : reflection_of[module]->blocks)
            members += block.members.size();
        bytes += words.size() * 4 + 48 +
                 32 * (rec.interface_count + rec.block_count + members + rec.resource_count);
        return b.AddModule(Stage(rec.stage), words, *reflection_of[module]);
    };
    for (uint32_t v = 0; bytes + 24 * v < target && v < (1u << (4 * kSets)); ++v) {
        VariantRec variant;
        variant.key = v;
        variant.vertex_module = copy(vertex[v % vertex.size()], 2 * v);
        variant.fragment_module = copy(fragment[v % fragment.size()], 2 * v + 1);
        b.variants.push_back(variant);
    }
    pass.variant_count = static_cast<uint32_t>(b.variants.size());
    b.passes.push_back(pass);
    MetaRec meta = source.meta();
    meta.producer = b.Str(source.String(meta.producer));
    return b.Finish(meta);
}

void OpenBench(benchmark::State& state, size_t target, OpenChecks checks) {
    static std::map<size_t, std::vector<uint8_t>> made;
    std::vector<uint8_t>& bytes = made[target];
    if (bytes.empty())
        bytes = MakePack(target);
    const auto checked = Pack::Open(bytes);
    if (!checked) {
        state.SkipWithError(bytes.empty() ? "the benchmark's pack could not be made"
                                          : checked.error().message.c_str());
        return;
    }
    for (auto _ : state) {
        auto opened = Pack::Open(bytes, checks);
        benchmark::DoNotOptimize(opened);
    }
    state.counters["MB"] = double(bytes.size()) / 1e6;
    state.counters["variants"] = checked.value().Count(SectionTag::kVariants);
}

// The runtime's open (Renderer::AddPack): the variant data checked on first use.
void BM_PackOpen3MB(benchmark::State& state) {
    OpenBench(state, 3000000, OpenChecks::kOnFirstUse);
}
void BM_PackOpen125MB(benchmark::State& state) {
    OpenBench(state, 125000000, OpenChecks::kOnFirstUse);
}
// The tools' open, every record and the whole-file checksum: grows with the file.
void BM_PackOpen125MBAllChecks(benchmark::State& state) {
    OpenBench(state, 125000000, OpenChecks::kAll);
}
// Three repetitions each: check_targets.py compares the fastest.
BENCHMARK(BM_PackOpen3MB)->Unit(benchmark::kMicrosecond)->Repetitions(3);
BENCHMARK(BM_PackOpen125MB)->Unit(benchmark::kMicrosecond)->Repetitions(3);
BENCHMARK(BM_PackOpen125MBAllChecks)->Unit(benchmark::kMicrosecond);

}  // namespace
