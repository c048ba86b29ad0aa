#include "kiln/pack/pass_id.h"

#include "kiln/pack/engine_names.h"
#include "kiln/pack/reader.h"

namespace kiln::pack {

std::string PassId(const PassIdParts& parts) {
    std::string id = parts.several_subshaders
                         ? "SubShader " + std::to_string(parts.subshader + 1) + "/"
                         : std::string();
    if (!parts.name.empty()) {
        return id + std::string(parts.name);
    }
    if (!parts.light_mode.empty()) {
        return id + std::string(parts.light_mode);
    }
    return id + "#" + std::to_string(parts.index + 1);
}

std::string_view LightModeOf(const Pack& pack, uint32_t pass) {
    if (pass >= pack.Count(SectionTag::kPasses)) {
        return {};
    }
    const PassRec p = pack.Pass(pass).value();
    for (uint32_t i = 0; i < p.tag_count; ++i) {
        const auto tag = pack.Get<TagRec>(SectionTag::kTags, p.first_tag + i).value();
        if (pack.String(tag.key) == kTagLightMode) {
            return pack.String(tag.value);
        }
    }
    return {};
}

std::optional<int> RenderQueue(std::string_view value) {
    for (const auto& [name, base] : kRenderQueues) {
        const std::string_view n(name);
        if (value.substr(0, n.size()) != n) {
            continue;
        }
        const std::string_view rest = value.substr(n.size());
        if (rest.empty()) {
            return base;
        }
        if ((rest[0] == '+' || rest[0] == '-') && rest.size() > 1 && rest.size() < 7 &&
            rest.find_first_not_of("0123456789", 1) == std::string_view::npos) {
            const int offset = std::stoi(std::string(rest.substr(1)));
            return rest[0] == '+' ? base + offset : base - offset;
        }
        return std::nullopt;
    }
    if (!value.empty() && value.size() < 7 &&
        value.find_first_not_of("0123456789") == std::string_view::npos) {
        return std::stoi(std::string(value));
    }
    return std::nullopt;
}

std::optional<int> RenderQueueOf(const Pack& pack, uint32_t pass) {
    if (pass >= pack.Count(SectionTag::kPasses)) {
        return std::nullopt;
    }
    const PassRec p = pack.Pass(pass).value();
    for (uint32_t i = 0; i < p.tag_count; ++i) {
        const auto tag = pack.Get<TagRec>(SectionTag::kTags, p.first_tag + i).value();
        if (pack.String(tag.key) == kTagQueue) {
            return RenderQueue(pack.String(tag.value));
        }
    }
    return std::nullopt;
}

bool IsTransparentShader(const Pack& pack, uint32_t shader) {
    const auto s = pack.Shader(shader);
    if (!s || s.value().pass_count == 0) {
        return false;
    }
    const std::optional<int> queue = RenderQueueOf(pack, s.value().first_pass);
    return queue && *queue > kRenderQueueTransparentAbove;
}

PassIdParts PassIdPartsOf(const Pack& pack, uint32_t pass) {
    PassIdParts parts;
    if (pass >= pack.Count(SectionTag::kPasses)) {
        return parts;
    }
    const PassRec p = pack.Pass(pass).value();
    const ShaderRec s = pack.Shader(p.shader).value();
    parts.name = pack.String(p.name);
    parts.light_mode = LightModeOf(pack, pass);
    parts.subshader = p.subshader;
    for (uint32_t i = s.first_pass; i < s.first_pass + s.pass_count; ++i) {
        const uint32_t sub = pack.Pass(i).value().subshader;
        parts.index += i < pass && sub == p.subshader;
        parts.several_subshaders = parts.several_subshaders || sub != p.subshader;
    }
    return parts;
}

std::string PassLabel(const Pack& pack, uint32_t pass) {
    if (pass >= pack.Count(SectionTag::kPasses)) {
        return "";
    }
    return PassId(PassIdPartsOf(pack, pass));
}

}  // namespace kiln::pack
