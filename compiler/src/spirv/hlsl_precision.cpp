#include "spirv/hlsl_precision.h"

#include <unordered_map>
#include <unordered_set>

namespace kiln::spirv {
namespace {

// SPIR-V opcodes and the decoration this pass reads.
enum Op : uint32_t {
    kOpUndef = 1,
    kOpExtInst = 12,
    kOpTypeFloat = 22,
    kOpTypeVector = 23,
    kOpTypeMatrix = 24,
    kOpTypeStruct = 30,
    kOpTypePointer = 32,
    kOpConstant = 43,
    kOpConstantComposite = 44,
    kOpConstantNull = 46,
    kOpSpecConstant = 50,
    kOpSpecConstantComposite = 51,
    kOpSpecConstantOp = 52,
    kOpFunctionParameter = 55,
    kOpVariable = 59,
    kOpLoad = 61,
    kOpAccessChain = 65,
    kOpInBoundsAccessChain = 66,
    kOpDecorate = 71,
    kOpMemberDecorate = 72,
    kOpVectorShuffle = 79,
    kOpCompositeConstruct = 80,
    kOpCompositeExtract = 81,
    kOpCompositeInsert = 82,
    kOpCopyObject = 83,
    kOpTranspose = 84,
    kOpFNegate = 127,
    kOpFAdd = 129,
    kOpFSub = 131,
    kOpFMul = 133,
    kOpFDiv = 136,
    kOpFRem = 140,
    kOpFMod = 141,
    kOpVectorTimesScalar = 142,
    kOpOuterProduct = 147,
    kOpDot = 148,
    kOpSelect = 169,
    kOpFOrdEqual = 180,
    kOpFUnordGreaterThanEqual = 191,
    kOpDPdx = 207,
    kOpFwidthCoarse = 215,
    kOpPhi = 245,
    kOpImageSampleImplicitLod = 87,  // through kOpImageQueryLod (105): every image access
    kOpImageQueryLod = 105,
    kOpImageSparseSampleImplicitLod = 305,  // through OpImageSparseRead (320)
    kOpImageSparseRead = 320,
};
constexpr uint32_t kRelaxedPrecision = 0;

struct Instruction {
    uint32_t opcode = 0;
    size_t at = 0, count = 0;  // word offset and word count
};

// The operand words (after result type and result id) that are ids of values, for the
// arithmetic this pass judges; empty `last` for anything else.
struct ValueOperands {
    size_t first = 0, last = 0, step = 1;
};

ValueOperands ValueOperandsOf(uint32_t opcode, size_t operands) {
    switch (opcode) {
        case kOpExtInst:  // set, instruction number, then values
            return {2, operands, 1};
        case kOpCompositeExtract:  // the composite, then literal indices
            return {0, operands > 0 ? 1u : 0u, 1};
        case kOpCompositeInsert:  // object, composite, literal indices
        case kOpVectorShuffle:    // two vectors, literal components
            return {0, operands < 2 ? operands : 2, 1};
        case kOpPhi:  // (value, parent block) pairs
            return {0, operands, 2};
        case kOpCompositeConstruct:
        case kOpCopyObject:
        case kOpTranspose:
        case kOpSelect:
            return {0, operands, 1};
        default:
            break;
    }
    const bool arithmetic = (opcode >= kOpFNegate && opcode <= kOpDot) ||
                            (opcode >= kOpFOrdEqual && opcode <= kOpFUnordGreaterThanEqual) ||
                            (opcode >= kOpDPdx && opcode <= kOpFwidthCoarse);
    return {0, arithmetic ? operands : 0, 1};
}

bool IsConstant(uint32_t opcode) {
    return opcode == kOpUndef || opcode == kOpConstant || opcode == kOpConstantComposite ||
           opcode == kOpConstantNull || (opcode >= kOpSpecConstant && opcode <= kOpSpecConstantOp);
}

struct State {
    explicit State(const std::vector<uint32_t>& w) : words(w) {}
    const std::vector<uint32_t>& words;
    std::vector<Instruction> instructions;
    std::unordered_map<uint32_t, size_t> def;  // result id -> instruction index
    std::unordered_set<uint32_t> float32_types, relaxed;
    std::unordered_set<uint64_t> relaxed_members;      // (struct type << 32) | member
    std::unordered_map<uint32_t, uint32_t> pointee;    // pointer type -> pointee type
    std::unordered_map<uint32_t, uint32_t> constants;  // 32-bit integer constant -> value
    std::unordered_map<uint32_t, std::vector<uint32_t>> members;  // struct -> member types

    uint32_t ResultOf(const Instruction& in) const { return words[in.at + 2]; }

    void Parse() {
        for (size_t i = 5; i < words.size();) {
            const uint32_t count = words[i] >> 16, opcode = words[i] & 0xFFFF;
            if (count == 0 || count > words.size() - i)
                break;
            instructions.push_back({opcode, i, count});
            i += count;
        }
        for (size_t k = 0; k < instructions.size(); ++k) {
            const Instruction& in = instructions[k];
            const uint32_t* w = &words[in.at];
            if (in.opcode == kOpTypeFloat && in.count == 3 && w[2] == 32)
                float32_types.insert(w[1]);
            else if ((in.opcode == kOpTypeVector || in.opcode == kOpTypeMatrix) && in.count == 4 &&
                     float32_types.count(w[2]))
                float32_types.insert(w[1]);
            else if (in.opcode == kOpDecorate && in.count == 3 && w[2] == kRelaxedPrecision)
                relaxed.insert(w[1]);
            else if (in.opcode == kOpMemberDecorate && in.count == 4 && w[3] == kRelaxedPrecision)
                relaxed_members.insert(uint64_t(w[1]) << 32 | w[2]);
            else if (in.opcode == kOpTypePointer && in.count == 4)
                pointee[w[1]] = w[3];
            else if (in.opcode == kOpTypeStruct)
                members[w[1]].assign(w + 2, w + in.count);
            else if (in.opcode == kOpConstant && in.count == 4)
                constants[w[2]] = w[3];
            if (in.count >= 3 && in.opcode != kOpDecorate)
                def.emplace(w[2], k);
        }
    }

    // Whether what `pointer` points at was declared half: the variable or parameter at the root
    // of its access chain, or the struct member it selects (glslang also decorates loads of
    // plain float values that meet a half one, as GLSL ES's precision rules do).
    bool DeclaredRelaxed(uint32_t pointer, int depth = 0) const {
        const auto d = def.find(pointer);
        if (d == def.end() || depth > 64)
            return false;
        const Instruction& in = instructions[d->second];
        const uint32_t* w = &words[in.at];
        if (in.opcode != kOpAccessChain && in.opcode != kOpInBoundsAccessChain)
            return relaxed.count(pointer) > 0;
        if (in.count < 4 || DeclaredRelaxed(w[3], depth + 1))
            return true;
        // Walk the indices from the base's pointee type; a decorated member on the way counts.
        const auto base = def.find(w[3]);
        if (base == def.end())
            return false;
        const auto pt = pointee.find(words[instructions[base->second].at + 1]);
        uint32_t type = pt == pointee.end() ? 0 : pt->second;
        for (size_t k = 4; k < in.count && type != 0; ++k) {
            const auto s = members.find(type);
            if (s == members.end()) {
                type = 0;  // an array or vector element: its own type is not tracked further
                break;
            }
            const auto index = constants.find(w[k]);
            if (index == constants.end() || index->second >= s->second.size())
                return false;
            if (relaxed_members.count(uint64_t(type) << 32 | index->second))
                return true;
            type = s->second[index->second];
        }
        return false;
    }

    // Loads keep their decoration only where the value was declared half.
    void JudgeLoads() {
        for (const Instruction& in : instructions) {
            if (in.opcode == kOpLoad && in.count >= 4 && relaxed.count(words[in.at + 2]) &&
                !DeclaredRelaxed(words[in.at + 3]))
                relaxed.erase(words[in.at + 2]);
        }
    }

    // A float operand that makes an HLSL operation float: 32-bit, not relaxed, not a constant.
    bool IsFullFloat(uint32_t id) const {
        const auto d = def.find(id);
        if (d == def.end() || relaxed.count(id))
            return false;
        const Instruction& in = instructions[d->second];
        return !IsConstant(in.opcode) && in.count >= 3 && float32_types.count(words[in.at + 1]);
    }

    // One sweep in module order; true when a decoration was dropped.
    bool Sweep() {
        bool changed = false;
        for (const Instruction& in : instructions) {
            if (in.count < 3 || !relaxed.count(ResultOf(in)))
                continue;
            const ValueOperands v = ValueOperandsOf(in.opcode, in.count - 3);
            for (size_t k = v.first; k < v.last; k += v.step) {
                if (IsFullFloat(words[in.at + 3 + k])) {
                    relaxed.erase(ResultOf(in));
                    changed = true;
                    break;
                }
            }
        }
        return changed;
    }
};

}  // namespace

namespace {

// Rewrites `words` without the RelaxedPrecision decorations of ids `st` no longer holds relaxed.
size_t DropUndecorated(const State& st, std::vector<uint32_t>& words) {
    std::vector<uint32_t> out(words.begin(), words.begin() + 5);
    out.reserve(words.size());
    size_t removed = 0;
    for (const Instruction& in : st.instructions) {
        const uint32_t* w = &words[in.at];
        if (in.opcode == kOpDecorate && in.count == 3 && w[2] == kRelaxedPrecision &&
            !st.relaxed.count(w[1])) {
            ++removed;
            continue;
        }
        out.insert(out.end(), w, w + in.count);
    }
    words = std::move(out);
    return removed;
}

bool IsImageAccess(uint32_t opcode) {
    return (opcode >= kOpImageSampleImplicitLod && opcode <= kOpImageQueryLod) ||
           (opcode >= kOpImageSparseSampleImplicitLod && opcode <= kOpImageSparseRead);
}

}  // namespace

size_t MatchHlslPromotion(std::vector<uint32_t>& words) {
    if (words.size() < 5)
        return 0;
    State st{words};
    st.Parse();
    st.JudgeLoads();
    while (st.Sweep()) {
    }
    return DropUndecorated(st, words);
}

size_t KeepImageOperandsFloat(std::vector<uint32_t>& words) {
    if (words.size() < 5)
        return 0;
    State st{words};
    st.Parse();
    for (const Instruction& in : st.instructions) {
        if (!IsImageAccess(in.opcode) || in.count < 5)
            continue;
        // After the result type, the result and the (sampled) image: coordinates, Dref or
        // component, then the image operands. The mask among them is a literal; dropping the
        // decoration of an id that happens to equal it only keeps that value in 32 bits.
        for (size_t k = in.at + 4; k < in.at + in.count; ++k)
            st.relaxed.erase(words[k]);
    }
    return DropUndecorated(st, words);
}

}  // namespace kiln::spirv
