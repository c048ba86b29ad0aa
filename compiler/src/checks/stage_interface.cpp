// The stage-interface check (K5004, K5007): per variant, what the fragment stage reads against
// what the last stage before rasterization writes, and the uniform blocks both declare.
#include <set>
#include <string>

#include "checks/check_functions.h"

namespace kiln::checks {
namespace {

using driver::CompileState;
using driver::PassUnit;
using pack::Stage;

// One pass's stages as the check sees them.
struct PassStages {
    size_t pass = 0;
    size_t pre = 0;  // slot of the stage before rasterization
    std::string pre_name;
    const variants::EntryPoint* pre_entry = nullptr;
    std::set<std::string> reported;  // each message once per pass
};

// The fragment stage reads what the last stage before rasterization writes: geometry, else
// domain (tessellation evaluation), else vertex.
size_t PreRasterSlot(const std::vector<Stage>& stages) {
    size_t pre = 0;
    for (size_t slot = 2; slot < stages.size(); ++slot) {
        if (stages[slot] == Stage::kGeometry ||
            (stages[slot] == Stage::kTessEval && stages[pre] != Stage::kGeometry))
            pre = slot;
    }
    return pre;
}

// "" when `in` is fed by `vs`'s outputs, else what is wrong.
std::string InputProblem(const spirv::InterfaceVar& in,
                         const spirv::Reflection& vs,
                         const std::string& pre_name) {
    const spirv::InterfaceVar* match = nullptr;
    for (const auto& out : vs.interface) {
        if (out.direction == 1 && out.location == in.location)
            match = &out;
    }
    if (!match) {
        return "fragment input " + (in.semantic.empty() ? in.name : in.semantic) + " (location " +
               std::to_string(in.location) + ") is not written by the " + pre_name + " shader";
    }
    if (!in.semantic.empty() && !match->semantic.empty() && in.semantic != match->semantic) {
        return "fragment input " + in.semantic + " and " + pre_name + " output " + match->semantic +
               " share location " + std::to_string(in.location) + "; declare the " + pre_name +
               " outputs and fragment inputs in the same order";
    }
    if (match->vecsize < in.vecsize) {
        return "fragment input " + in.semantic + " has " + std::to_string(in.vecsize) +
               " components but the " + pre_name + " shader writes " +
               std::to_string(match->vecsize);
    }
    return "";
}

// True when the blocks `a` and `b` share a binding but not a layout.
bool LayoutsDiffer(const spirv::Block& a, const spirv::Block& b) {
    if (a.kind != b.kind || a.set != b.set || a.binding != b.binding)
        return false;
    if (a.kind == pack::BlockKind::kUniform && a.name != b.name)
        return false;
    bool same = a.size == b.size || a.kind == pack::BlockKind::kPushConstant;
    for (const auto& ma : a.members) {
        for (const auto& mb : b.members) {
            if (ma.name == mb.name && ma.offset != mb.offset)
                same = false;
        }
    }
    return !same;
}

void CheckVariant(CompileState& st, PassStages& ps, size_t v) {
    const PassUnit& pu = st.passes[ps.pass];
    const driver::ShaderUnit& unit = st.shaders[pu.shader];
    const std::string& file = unit.file->path();
    const spirv::Reflection& vs = driver::FinalFor(st, ps.pass, pu.TaskOf(v, ps.pre)).reflection;
    const spirv::Reflection& fs = driver::FinalFor(st, ps.pass, pu.TaskOf(v, 1)).reflection;
    for (const spirv::InterfaceVar& in : fs.interface) {
        if (in.direction != 0 || in.location == ~0u)
            continue;
        const std::string msg = InputProblem(in, vs, ps.pre_name);
        if (!msg.empty() && ps.reported.insert(msg).second) {
            st.diags.Error(DiagCode::kStageInterfaceMismatch, file, pu.pragmas.fragment->range, msg)
                .notes.push_back({file, ps.pre_entry->range,
                                  "in " + driver::VariantName(st, ps.pass, pu.expansion.keys[v])});
        }
    }
    for (const spirv::Block& a : vs.blocks) {
        for (const spirv::Block& b : fs.blocks) {
            const std::string msg = "uniform block '" + a.name +
                                    "' has a different layout in the " + ps.pre_name +
                                    " and fragment stages; declare the same globals for both "
                                    "stages";
            if (LayoutsDiffer(a, b) && ps.reported.insert(msg).second) {
                st.diags.Error(DiagCode::kBlockLayoutMismatch, file,
                               unit.passes[pu.flat].program->range, msg);
            }
        }
    }
}

}  // namespace

void CheckStageInterfaces(Inputs& in) {
    CompileState& st = *in.st;
    for (size_t p = 0; p < st.passes.size(); ++p) {
        const PassUnit& pu = st.passes[p];
        const std::vector<Stage> stages = pu.pragmas.Stages();
        PassStages ps;
        ps.pass = p;
        ps.pre = PreRasterSlot(stages);
        ps.pre_name = pack::StageName(stages[ps.pre]);
        ps.pre_entry = pu.pragmas.Entry(stages[ps.pre]);
        for (size_t v = 0; v < pu.expansion.keys.size(); ++v)
            CheckVariant(st, ps, v);
    }
}

}  // namespace kiln::checks
