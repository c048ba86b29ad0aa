// DumpText: an indented, human-readable outline of the AST (for `kiln parse`).
#include <cstdio>

#include "kiln/shaderlab/parse.h"

namespace kiln::shaderlab {
namespace {

struct Printer {
    std::string out;

    void Line(int indent, const std::string& text) {
        out.append(static_cast<size_t>(indent) * 2, ' ');
        out += text;
        out += '\n';
    }
    static std::string At(const SourceRange& r) {
        return " @" + std::to_string(r.begin.line) + ":" + std::to_string(r.begin.column);
    }
    static std::string Num(double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", v);
        return buf;
    }
    static std::string Val(const StateValue& v) {
        return v.kind == StateValue::Kind::kPropertyRef ? "[" + v.text + "]" : v.text;
    }

    void Tags(int indent, const std::vector<Tag>& tags) {
        if (tags.empty()) {
            return;
        }
        std::string s = "Tags";
        for (const Tag& t : tags) {
            s += " \"" + t.key + "\"=\"" + t.value + "\"";
        }
        Line(indent, s);
    }

    void State(int indent, const RenderState& st) {
        auto simple = [&](const char* name, const std::optional<SimpleState>& s) {
            if (s) {
                Line(indent, std::string(name) + " " + Val(s->value));
            }
        };
        simple("Cull", st.cull);
        simple("ZTest", st.ztest);
        simple("ZWrite", st.zwrite);
        simple("ZClip", st.zclip);
        simple("AlphaToMask", st.alpha_to_mask);
        simple("Conservative", st.conservative);
        if (st.offset) {
            Line(indent, "Offset " + Val(st.offset->factor) + ", " + Val(st.offset->units));
        }
        for (const BlendState& b : st.blend) {
            std::string s = "Blend";
            s += b.target >= 0 ? " " + std::to_string(b.target) : "";
            s += b.off ? " Off" : " " + Val(b.src) + " " + Val(b.dst);
            if (b.src_alpha) {
                s += ", " + Val(*b.src_alpha) + " " + Val(*b.dst_alpha);
            }
            Line(indent, s);
        }
        for (const BlendOpState& b : st.blend_op) {
            std::string s = "BlendOp";
            s += b.target >= 0 ? " " + std::to_string(b.target) : "";
            s += " " + Val(b.op) + (b.op_alpha ? ", " + Val(*b.op_alpha) : "");
            Line(indent, s);
        }
        for (const ColorMaskState& c : st.color_mask) {
            Line(indent, "ColorMask " + Val(c.mask) +
                             (c.target >= 0 ? " " + std::to_string(c.target) : ""));
        }
        if (st.stencil) {
            std::string s = "Stencil {";
            for (const StencilEntry& e : st.stencil->entries) {
                s += " " + e.key + " " + Val(e.value);
            }
            Line(indent, s + " }");
        }
    }

    void Programs(int indent, const std::vector<ProgramBlock>& programs) {
        for (const ProgramBlock& p : programs) {
            size_t lines = 1;
            for (char c : p.text) {
                lines += c == '\n' ? 1 : 0;
            }
            Line(indent, std::string(ProgramKindName(p.kind)) + At(p.range) + " (" +
                             std::to_string(lines) + " lines)");
            for (const Pragma& pr : p.pragmas) {
                std::string s = "#pragma " + pr.name;
                for (const PragmaArg& a : pr.args) {
                    s += " " + a.text;
                }
                Line(indent + 1, s + At(pr.range));
            }
        }
    }

    void Entries(int indent, const std::vector<SubShaderEntry>& entries) {
        for (const SubShaderEntry& entry : entries) {
            if (const SubShader* sub = std::get_if<SubShader>(&entry)) {
                Line(indent, "SubShader" + At(sub->range));
                Tags(indent + 1, sub->tags);
                if (sub->lod) {
                    Line(indent + 1, "LOD " + std::to_string(*sub->lod));
                }
                State(indent + 1, sub->state);
                Programs(indent + 1, sub->programs);
                for (const PassEntry& pe : sub->passes) {
                    Pass(indent + 1, pe);
                }
                continue;
            }
            const Category& cat = *std::get<std::unique_ptr<Category>>(entry);
            Line(indent, "Category" + At(cat.range));
            Tags(indent + 1, cat.tags);
            State(indent + 1, cat.state);
            Programs(indent + 1, cat.programs);
            Entries(indent + 1, cat.children);
        }
    }

    void Pass(int indent, const PassEntry& entry) {
        if (const UsePass* u = std::get_if<UsePass>(&entry)) {
            Line(indent, "UsePass \"" + u->target + "\"" + At(u->range));
            return;
        }
        if (const GrabPass* g = std::get_if<GrabPass>(&entry)) {
            Line(indent, "GrabPass \"" + g->texture_name + "\"" + At(g->range));
            return;
        }
        const kiln::shaderlab::Pass& p = std::get<kiln::shaderlab::Pass>(entry);
        Line(indent, "Pass" + (p.name.empty() ? "" : " \"" + p.name + "\"") + At(p.range));
        if (p.lod) {
            Line(indent + 1, "LOD " + std::to_string(*p.lod));
        }
        Tags(indent + 1, p.tags);
        State(indent + 1, p.state);
        Programs(indent + 1, p.programs);
    }
};

}  // namespace

std::string DumpText(const Shader& shader) {
    Printer p;
    p.Line(0, "Shader \"" + shader.name + "\"" + Printer::At(shader.range));
    if (shader.properties_range) {
        p.Line(1, "Properties" + Printer::At(*shader.properties_range));
    }
    for (const Property& prop : shader.properties) {
        std::string s;
        for (const Attribute& a : prop.attributes) {
            s += "[" + a.name + (a.has_parens ? "(" + a.raw_args + ")" : "") + "] ";
        }
        s += prop.name + " (\"" + prop.display_name + "\", " + PropertyTypeName(prop.type);
        if (prop.type == PropertyType::kRange) {
            s += "(" + Printer::Num(prop.range_min) + ", " + Printer::Num(prop.range_max) + ")";
        }
        s += ") = ";
        if (IsTextureType(prop.type)) {
            s += "\"" + prop.default_texture + "\"";
        } else if (prop.default_value.size() == 1) {
            s += Printer::Num(prop.default_value[0]);
        } else {
            s += "(";
            for (size_t i = 0; i < prop.default_value.size(); ++i) {
                s += (i ? ", " : "") + Printer::Num(prop.default_value[i]);
            }
            s += ")";
        }
        p.Line(2, s);
    }
    p.Programs(1, shader.programs);
    p.Entries(1, shader.subshaders);
    if (shader.fallback) {
        p.Line(1, shader.fallback->off ? "Fallback Off"
                                       : "Fallback \"" + shader.fallback->name + "\"");
    }
    if (shader.custom_editor) {
        p.Line(1, "CustomEditor \"" + *shader.custom_editor + "\"");
    }
    for (const Dependency& d : shader.dependencies) {
        p.Line(1, "Dependency \"" + d.key + "\" = \"" + d.value + "\"");
    }
    return p.out;
}

}  // namespace kiln::shaderlab
