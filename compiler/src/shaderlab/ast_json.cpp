// DumpJson: the stable JSON form of the AST, specified in docs/ast-json.md. Key order is fixed;
// optional members are omitted when unset. Ranges are [begin line, begin column, end line,
// end column] with 1-based lines and byte columns, end exclusive.
#include <algorithm>

#include <nlohmann/json.hpp>

#include "kiln/shaderlab/parse.h"

namespace kiln::shaderlab {
namespace {

using Json = nlohmann::ordered_json;

Json R(const SourceRange& r) {
    return Json::array({r.begin.line, r.begin.column, r.end.line, r.end.column});
}

Json Value(const StateValue& v) {
    Json j;
    switch (v.kind) {
        case StateValue::Kind::kLiteral:
            j["literal"] = v.text;
            break;
        case StateValue::Kind::kNumber:
            j["number"] = v.number;
            break;
        case StateValue::Kind::kPropertyRef:
            j["property"] = v.text;
            break;
    }
    j["range"] = R(v.range);
    return j;
}

Json Tags(const std::vector<Tag>& tags) {
    Json arr = Json::array();
    for (const Tag& t : tags) {
        arr.push_back({{"key", t.key}, {"value", t.value}, {"range", R(t.range)}});
    }
    return arr;
}

Json State(const RenderState& s) {
    Json j = Json::object();
    auto simple = [&](const char* key, const std::optional<SimpleState>& st) {
        if (st) {
            j[key] = {{"value", Value(st->value)}, {"range", R(st->range)}};
        }
    };
    simple("cull", s.cull);
    simple("ztest", s.ztest);
    simple("zwrite", s.zwrite);
    simple("zclip", s.zclip);
    simple("alpha_to_mask", s.alpha_to_mask);
    simple("conservative", s.conservative);
    if (s.offset) {
        j["offset"] = {{"factor", Value(s.offset->factor)},
                       {"units", Value(s.offset->units)},
                       {"range", R(s.offset->range)}};
    }
    if (!s.blend.empty()) {
        Json arr = Json::array();
        for (const BlendState& b : s.blend) {
            Json e = {{"target", b.target}, {"off", b.off}};
            if (!b.off) {
                e["src"] = Value(b.src);
                e["dst"] = Value(b.dst);
            }
            if (b.src_alpha) {
                e["src_alpha"] = Value(*b.src_alpha);
                e["dst_alpha"] = Value(*b.dst_alpha);
            }
            e["range"] = R(b.range);
            arr.push_back(e);
        }
        j["blend"] = arr;
    }
    if (!s.blend_op.empty()) {
        Json arr = Json::array();
        for (const BlendOpState& b : s.blend_op) {
            Json e = {{"target", b.target}, {"op", Value(b.op)}};
            if (b.op_alpha) {
                e["op_alpha"] = Value(*b.op_alpha);
            }
            e["range"] = R(b.range);
            arr.push_back(e);
        }
        j["blend_op"] = arr;
    }
    if (!s.color_mask.empty()) {
        Json arr = Json::array();
        for (const ColorMaskState& c : s.color_mask) {
            arr.push_back({{"target", c.target}, {"mask", Value(c.mask)}, {"range", R(c.range)}});
        }
        j["color_mask"] = arr;
    }
    if (s.stencil) {
        Json arr = Json::array();
        for (const StencilEntry& e : s.stencil->entries) {
            arr.push_back({{"key", e.key}, {"value", Value(e.value)}, {"range", R(e.range)}});
        }
        j["stencil"] = {{"entries", arr}, {"range", R(s.stencil->range)}};
    }
    return j;
}

Json Programs(const std::vector<ProgramBlock>& programs) {
    Json arr = Json::array();
    for (const ProgramBlock& p : programs) {
        Json pragmas = Json::array();
        for (const Pragma& pr : p.pragmas) {
            Json args = Json::array();
            for (const PragmaArg& a : pr.args) {
                args.push_back(a.text);
            }
            pragmas.push_back({{"name", pr.name}, {"args", args}, {"range", R(pr.range)}});
        }
        arr.push_back({{"kind", ProgramKindName(p.kind)},
                       {"range", R(p.range)},
                       {"body_begin", Json::array({p.body_begin.line, p.body_begin.column})},
                       {"pragmas", pragmas},
                       {"text", p.text}});
    }
    return arr;
}

Json PropertyJson(const Property& p) {
    Json attrs = Json::array();
    for (const Attribute& a : p.attributes) {
        Json e = {{"name", a.name}};
        if (a.has_parens) {
            e["args"] = a.args;
        }
        e["range"] = R(a.range);
        attrs.push_back(e);
    }
    Json j = {
        {"name", p.name}, {"display_name", p.display_name}, {"type", PropertyTypeName(p.type)}};
    if (p.type == PropertyType::kRange) {
        j["min"] = p.range_min;
        j["max"] = p.range_max;
    }
    if (IsTextureType(p.type)) {
        j["default"] = p.default_texture;
    } else {
        j["default"] = p.default_value;
    }
    j["attributes"] = attrs;
    j["range"] = R(p.range);
    return j;
}

Json PassJson(const PassEntry& entry) {
    if (const Pass* p = std::get_if<Pass>(&entry)) {
        Json j = {{"kind", "Pass"},
                  {"name", p->name},
                  {"tags", Tags(p->tags)},
                  {"state", State(p->state)},
                  {"programs", Programs(p->programs)},
                  {"range", R(p->range)}};
        if (p->lod) {
            j["lod"] = *p->lod;
        }
        return j;
    }
    if (const UsePass* u = std::get_if<UsePass>(&entry)) {
        return {{"kind", "UsePass"}, {"target", u->target}, {"range", R(u->range)}};
    }
    const GrabPass& g = std::get<GrabPass>(entry);
    return {{"kind", "GrabPass"},
            {"texture", g.texture_name},
            {"name", g.name},
            {"tags", Tags(g.tags)},
            {"range", R(g.range)}};
}

Json Entries(const std::vector<SubShaderEntry>& entries);

Json SubShaderJson(const SubShader& s) {
    Json passes = Json::array();
    for (const PassEntry& e : s.passes) {
        passes.push_back(PassJson(e));
    }
    Json j = {{"kind", "SubShader"}, {"tags", Tags(s.tags)}};
    if (s.lod) {
        j["lod"] = *s.lod;
    }
    j["state"] = State(s.state);
    j["programs"] = Programs(s.programs);
    j["passes"] = passes;
    j["range"] = R(s.range);
    return j;
}

Json Entries(const std::vector<SubShaderEntry>& entries) {
    Json arr = Json::array();
    for (const SubShaderEntry& entry : entries) {
        if (const SubShader* s = std::get_if<SubShader>(&entry)) {
            arr.push_back(SubShaderJson(*s));
            continue;
        }
        const Category& c = *std::get<std::unique_ptr<Category>>(entry);
        Json j = {{"kind", "Category"}, {"tags", Tags(c.tags)}};
        if (c.lod) {
            j["lod"] = *c.lod;
        }
        j["state"] = State(c.state);
        j["programs"] = Programs(c.programs);
        j["children"] = Entries(c.children);  // depth bounded by ParseOptions::max_nesting
        j["range"] = R(c.range);
        arr.push_back(j);
    }
    return arr;
}

// Pretty-prints like dump(2) but keeps arrays of scalars (ranges, vectors) on one line, which
// keeps golden files short enough to review.
void Write(const Json& j, size_t indent, std::string& out) {
    const bool container = j.is_object() || j.is_array();
    bool flat = !container || j.empty();
    if (j.is_array() && !flat) {
        flat = std::none_of(j.begin(), j.end(), [](const Json& e) { return e.is_structured(); });
    }
    if (flat && !j.is_object()) {
        if (!container) {
            out += j.dump(-1, ' ', false, Json::error_handler_t::replace);
            return;
        }
        out += '[';
        for (size_t i = 0; i < j.size(); ++i) {
            out += i ? ", " : "";
            Write(j[i], indent, out);
        }
        out += ']';
        return;
    }
    if (j.empty()) {
        out += "{}";
        return;
    }
    out += j.is_object() ? "{\n" : "[\n";
    size_t i = 0;
    for (auto it = j.begin(); it != j.end(); ++it, ++i) {
        out.append(indent + 2, ' ');
        if (j.is_object()) {
            out += Json(it.key()).dump(-1, ' ', false, Json::error_handler_t::replace) + ": ";
        }
        Write(*it, indent + 2, out);
        out += i + 1 < j.size() ? ",\n" : "\n";
    }
    out.append(indent, ' ');
    out += j.is_object() ? '}' : ']';
}

}  // namespace

std::string DumpJson(const Shader& shader) {
    Json props = Json::array();
    for (const Property& p : shader.properties) {
        props.push_back(PropertyJson(p));
    }
    Json j = {{"kind", "Shader"}, {"name", shader.name}, {"properties", props}};
    j["programs"] = Programs(shader.programs);
    j["subshaders"] = Entries(shader.subshaders);
    if (shader.fallback) {
        j["fallback"] = {{"off", shader.fallback->off},
                         {"name", shader.fallback->name},
                         {"range", R(shader.fallback->range)}};
    }
    if (shader.custom_editor) {
        j["custom_editor"] = *shader.custom_editor;
    }
    Json deps = Json::array();
    for (const Dependency& d : shader.dependencies) {
        deps.push_back({{"key", d.key}, {"value", d.value}, {"range", R(d.range)}});
    }
    j["dependencies"] = deps;
    j["range"] = R(shader.range);
    // Invalid UTF-8 from the input is replaced (U+FFFD), never thrown on.
    std::string out;
    Write(j, 0, out);
    return out;
}

}  // namespace kiln::shaderlab
