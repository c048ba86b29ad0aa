#include "render/grab_pass.h"

#include <algorithm>
#include <map>
#include <string>

#include "kiln/pack/engine_names.h"

namespace kiln::runtime {

Status BuildForwardPasses(DrawBuilder& builder,
                          Frame& frame,
                          const FramePass& first,
                          uint32_t source,
                          std::span<const DrawRequest> requests,
                          FrameStats& stats) {
    std::map<std::string, uint32_t, std::less<>> grabbed;  // texture -> frame target
    size_t current = frame.passes.size();
    frame.passes.push_back(first);
    builder.BeginPass(frame, frame.passes[current]);
    size_t begin = 0;  // the first request not built yet
    for (size_t i = 0; i <= requests.size(); ++i) {
        if (i < requests.size() && !requests[i].grab) {
            continue;
        }
        if (Status e = builder.BuildForward(requests.subspan(begin, i - begin),
                                            frame.passes[current].draws);
            !e.ok()) {
            return e;
        }
        begin = i + 1;
        if (i == requests.size()) {
            break;
        }
        const std::string& named = *requests[i].grab;
        const std::string texture = named.empty() ? std::string(pack::kTextureGrab) : named;
        const auto [it, fresh] = grabbed.try_emplace(texture, uint32_t(frame.targets.size()));
        if (!fresh && !named.empty()) {
            continue;  // a named grab is taken once per frame
        }
        if (fresh) {
            FrameTarget target{"grab " + texture, frame.targets[source].format, false, {}};
            target.filtered = true;
            frame.targets.push_back(target);
        }
        FramePass copy;
        copy.name = "grab " + texture;
        copy.colors = {it->second};
        copy.copy_from = source;
        copy.clear = false;
        frame.passes.push_back(copy);
        ++stats.grab_copies;
        FramePass next = first;
        next.clear = false;
        for (const auto& [name, target] : grabbed) {
            if (std::find(next.sampled.begin(), next.sampled.end(), target) == next.sampled.end()) {
                next.sampled.push_back(target);
            }
        }
        current = frame.passes.size();
        frame.passes.push_back(std::move(next));
        builder.BeginPass(frame, frame.passes[current], grabbed);
    }
    return {};
}

}  // namespace kiln::runtime
