#include "surface/functions.h"

namespace kiln::surface {

using hlsl::Token;

size_t FindDefinition(const std::vector<Token>& tok,
                      std::string_view name,
                      size_t& close,
                      size_t& body) {
    for (size_t i = 1; i + 1 < tok.size(); ++i) {
        if (tok[i].text != name || tok[i + 1].text != "(" || !tok[i - 1].ident ||
            tok[i - 1].text == "return")
            continue;
        close = hlsl::MatchForward(tok, i + 1);
        if (close == SIZE_MAX)
            return SIZE_MAX;
        size_t k = close + 1;
        if (k + 1 < tok.size() && tok[k].text == ":")  // a return semantic
            k += 2;
        if (k < tok.size() && tok[k].text == "{") {
            body = k;
            return i + 1;
        }
    }
    return SIZE_MAX;
}

std::vector<Param> Params(const std::vector<Token>& tok, size_t open, size_t close) {
    std::vector<Param> out;
    size_t b = open + 1;
    for (size_t k = b; k <= close; ++k) {
        if (k != close && tok[k].text != ",")
            continue;
        Param p;
        size_t i = b;
        while (i < k && (tok[i].text == "in" || tok[i].text == "out" || tok[i].text == "inout" ||
                         tok[i].text == "uniform")) {
            p.qualifier = std::string(tok[i++].text);
        }
        if (i < k)
            p.type = std::string(tok[i++].text);
        if (i < k && tok[i].ident)
            p.name = std::string(tok[i].text);
        if (b < k)
            out.push_back(std::move(p));
        b = k + 1;
    }
    return out;
}

}  // namespace kiln::surface
