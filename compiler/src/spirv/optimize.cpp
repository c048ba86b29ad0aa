#include "spirv/optimize.h"

#include <string_view>

#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>

#include "spirv/hlsl_precision.h"

namespace kiln::spirv {
namespace {

constexpr spv_target_env kEnv = SPV_ENV_VULKAN_1_1;

spvtools::MessageConsumer Collect(std::string& out) {
    return [&out](spv_message_level_t, const char*, const spv_position_t& pos, const char* msg) {
        if (!out.empty())
            out += '\n';
        out += msg;
        if (pos.index > 0)
            out += " (word " + std::to_string(pos.index) + ")";
    };
}

// SPIRV-Tools' -Os list without eliminate-dead-members: that pass drops the uniform-block members
// one stage does not read, so the stages of a variant (and the runtime's one buffer per block)
// would disagree on the block's layout.
bool RegisterSizePassesKeepingBlockLayouts(spvtools::Optimizer& opt) {
    spvtools::Optimizer size(kEnv);
    size.RegisterSizePasses();
    std::vector<std::string> flags;
    for (const char* name : size.GetPassNames()) {
        if (std::string_view(name) != "eliminate-dead-members")
            flags.push_back(std::string("--") + name);
    }
    return opt.RegisterPassesFromFlags(flags);
}

// Kiln's -O: SPIRV-Tools' performance list (RegisterPerformancePasses, v2023.1) without its
// first half, which repeats what legalization has just done (wrap-opkill, merge-return, inlining,
// dead functions, private-to-local, the first scalar-replacement and load/store chains, the SSA
// rewrite). On the shipped materials and Unity's Standard it gives -O's code within 0.1% of
// instructions and bytes for a third less time in these passes (docs/performance.md). The
// second scalar-replacement chain stays: without it, 21% more instructions.
bool RegisterKilnPerformancePasses(spvtools::Optimizer& opt) {
    return opt.RegisterPassesFromFlags({
        "--ccp",
        "--loop-unroll",
        "--eliminate-dead-branches",
        "--redundancy-elimination",
        "--combine-access-chains",
        "--simplify-instructions",
        "--scalar-replacement=100",
        "--convert-local-access-chains",
        "--eliminate-local-single-block",
        "--eliminate-local-single-store",
        "--eliminate-dead-code-aggressive",
        "--vector-dce",
        "--eliminate-dead-inserts",
        "--eliminate-dead-branches",
        "--simplify-instructions",
        "--if-conversion",
        "--copy-propagate-arrays",
        "--reduce-load-size",
        "--eliminate-dead-code-aggressive",
        "--merge-blocks",
        "--redundancy-elimination",
        "--eliminate-dead-branches",
        "--merge-blocks",
        "--simplify-instructions",
    });
}

}  // namespace

std::string SpirvToolsVersion() {
    return spvSoftwareVersionString();
}

bool Optimize(std::vector<uint32_t>& words,
              OptLevel level,
              bool half_arithmetic,
              std::string& messages) {
    spvtools::OptimizerOptions options;
    options.set_run_validator(false);  // validated once at the end, after every change
    // RelaxedPrecision as HLSL promotes it, on glslang's own output: there a half variable or
    // parameter is still a load, so assigning a float to it narrows, as in HLSL.
    if (half_arithmetic)
        MatchHlslPromotion(words);
    spvtools::Optimizer opt(kEnv);
    opt.SetMessageConsumer(Collect(messages));
    if (half_arithmetic) {
        // Legalized in a run of its own: image accesses then read SSA values, whose
        // decorations KeepImageOperandsFloat drops before the conversion sees them.
        spvtools::Optimizer legalize(kEnv);
        legalize.SetMessageConsumer(Collect(messages));
        legalize.RegisterLegalizationPasses();
        std::vector<uint32_t> legal;
        if (!legalize.Run(words.data(), words.size(), &legal, options))
            return false;
        words = std::move(legal);
        KeepImageOperandsFloat(words);
        // After legalization has inlined and removed function-scope loads and stores, as the
        // pass asks; the clean-up folds the conversions it inserts.
        opt.RegisterPass(spvtools::CreateConvertRelaxedToHalfPass())
            .RegisterPass(spvtools::CreateSimplificationPass())
            .RegisterPass(spvtools::CreateRedundancyEliminationPass())
            .RegisterPass(spvtools::CreateAggressiveDCEPass());
    } else {
        opt.RegisterLegalizationPasses();
    }
    if (level == OptLevel::kPerformance && !RegisterKilnPerformancePasses(opt))
        return false;
    if (level == OptLevel::kPerformanceSpirvTools)
        opt.RegisterPerformancePasses();
    if (level == OptLevel::kSize && !RegisterSizePassesKeepingBlockLayouts(opt))
        return false;
    std::vector<uint32_t> out;
    if (!opt.Run(words.data(), words.size(), &out, options))
        return false;
    words = std::move(out);
    return true;
}

bool StripReflectionInfo(std::vector<uint32_t>& words,
                         bool keep_debug_info,
                         std::string& messages) {
    spvtools::Optimizer opt(kEnv);
    opt.SetMessageConsumer(Collect(messages));
    opt.RegisterPass(spvtools::CreateStripReflectInfoPass());
    if (!keep_debug_info)
        opt.RegisterPass(spvtools::CreateStripDebugInfoPass());
    spvtools::OptimizerOptions options;
    options.set_run_validator(false);
    std::vector<uint32_t> out;
    if (!opt.Run(words.data(), words.size(), &out, options))
        return false;
    words = std::move(out);
    return true;
}

bool Validate(const std::vector<uint32_t>& words, std::string& messages) {
    spvtools::SpirvTools tools(kEnv);
    tools.SetMessageConsumer(Collect(messages));
    spvtools::ValidatorOptions options;
    return tools.Validate(words.data(), words.size(), options);
}

}  // namespace kiln::spirv
