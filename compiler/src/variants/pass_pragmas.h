// Interprets the `#pragma` lines of a pass's program: entry points, shader target, keyword sets
// (multi_compile / shader_feature with _local and _vertex/_fragment forms and the built-in
// shortcuts), skip_variants and renderer restrictions. Keyword-set semantics follow Unity:
// a variant picks exactly one keyword from every set; `_`, `__`, ... mean "no keyword"; a
// one-keyword shader_feature means `_ KEYWORD`.
#ifndef KILN_VARIANTS_PASS_PRAGMAS_H_
#define KILN_VARIANTS_PASS_PRAGMAS_H_

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "kiln/diagnostic.h"
#include "kiln/pack/format.h"
#include "kiln/shaderlab/ast.h"

namespace kiln::variants {

struct KeywordSet {
    pack::KeywordSetKind kind = pack::KeywordSetKind::kMultiCompile;
    uint32_t flags = 0;                 // pack::KeywordSetFlags
    std::vector<std::string> keywords;  // "" = no keyword
    std::string pragma;                 // as written, e.g. "multi_compile_fwdadd"
    SourceRange range;                  // the pragma line
    // Declared in generated code (a surface shader's pass, driver/surface_passes.h): the user
    // cannot change it, so lint says nothing about it.
    bool generated = false;
};

// A combination rule from a built-in shortcut: a variant that enables `keyword` must also enable
// one of `any_of` (when not empty) and none of `none_of`. Unity never builds the combinations
// these rules exclude (e.g. DIRECTIONAL with SHADOWS_DEPTH), and its include files cannot compile
// some of them.
struct KeywordRule {
    std::string keyword;
    std::vector<std::string> any_of;
    std::vector<std::string> none_of;
    std::string pragma;  // the shortcut it came from
};

// A built-in shortcut: keyword sets whose product, filtered by the rules, is Unity's exact
// variant list for it (docs/variants.md has one table per shortcut).
struct Shortcut {
    std::vector<std::vector<std::string>> sets;
    std::vector<KeywordRule> rules;
};

struct EntryPoint {
    std::string name;
    SourceRange range;  // of the name
};

struct PassPragmas {
    std::optional<EntryPoint> vertex, fragment;
    // `#pragma geometry`, `#pragma hull` and `#pragma domain` (hull and domain come together).
    std::optional<EntryPoint> geometry, hull, domain;

    // The entry point of a stage (nullptr: the program has none).
    const EntryPoint* Entry(pack::Stage s) const {
        const std::optional<EntryPoint>* slots[] = {&vertex, &fragment, &geometry, &hull, &domain};
        const std::optional<EntryPoint>& e = *slots[static_cast<size_t>(s)];
        return e ? &*e : nullptr;
    }
    // The stages the program compiles, in the order of a variant's tasks: vertex, fragment, then
    // geometry, hull and domain where given.
    std::vector<pack::Stage> Stages() const {
        std::vector<pack::Stage> out = {pack::Stage::kVertex, pack::Stage::kFragment};
        if (geometry)
            out.push_back(pack::Stage::kGeometry);
        if (hull && domain) {
            out.push_back(pack::Stage::kTessControl);
            out.push_back(pack::Stage::kTessEval);
        }
        return out;
    }
    int shader_target = 25;  // SHADER_TARGET: 25 unless `#pragma target`
    std::vector<KeywordSet> sets;
    std::vector<KeywordRule> rules;  // from built-in shortcuts
    std::vector<shaderlab::PragmaArg> skip_variants;
    std::vector<std::string> only_renderers, exclude_renderers;
};

// Reads the pragmas of `blocks` (include blocks, then the pass program, in that order). Problems
// are reported into `diags` against `file`.
PassPragmas ReadPassPragmas(const std::vector<const shaderlab::ProgramBlock*>& blocks,
                            const std::string& file,
                            SourceRange pass_range,
                            DiagnosticList& diags);

// What a built-in shortcut (e.g. "multi_compile_fwdadd") expands to; nullopt when `name` is not
// a shortcut. Documented in docs/variants.md.
std::optional<Shortcut> BuiltinShortcut(const std::string& name);

// True when the enabled `keywords` satisfy every rule.
bool SatisfiesRules(const std::vector<KeywordRule>& rules,
                    const std::vector<std::string>& keywords);
// The first rule the enabled `keywords` break, or nullptr.
const KeywordRule* BrokenRule(const std::vector<KeywordRule>& rules,
                              const std::vector<std::string>& keywords);

bool IsNoKeyword(const std::string& word);  // "_", "__", ...
// A keyword one of Unity's built-in shortcuts declares: the engine sets it per draw (light type,
// shadows, lightmaps, fog, instancing), never a material.
bool IsBuiltinKeyword(const std::string& word);

}  // namespace kiln::variants

#endif  // KILN_VARIANTS_PASS_PRAGMAS_H_
