// The frame debugger's recording (RecordFrame with an observer): the same frame as RecordFrame
// records in one command buffer, submitted one step at a time — a pass's clear, then each draw in
// a render pass that loads what the steps before it wrote — with the targets the pass writes read
// back after each step and the draw timed with timestamp queries where the queue has them.
#include "render/frame_internal.h"
#include "vk/timestamps.h"

namespace kiln::runtime {

namespace {

// The GPU time of the last submitted step; negative when not timed.
double StepMilliseconds(const vk::Timestamps& timer) {
    const std::vector<double> ms = timer.Intervals();
    return ms.empty() ? -1.0 : ms[0];
}

}  // namespace

Status RecordFrameSteps(Renderer::State& s,
                        const Frame& frame,
                        LinearImage& out,
                        const StepObserver& observer) {
    const vk::Context& c = s.context;
    FrameObjects f(c);
    if (Status e = PrepareFrame(s, frame, f); !e.ok()) {
        return e;
    }
    vk::Timestamps timer(c, 2);  // around each step's draws
    Layouts layouts{frame, f.targets,
                    std::vector<VkImageLayout>(frame.targets.size(), VK_IMAGE_LAYOUT_UNDEFINED)};
    // The targets pass `p` writes, read back where the steps left them: a multisampled
    // attachment through the target the pass resolves it into, a cube map's face the pass drew.
    auto capture = [&](size_t p, int draw, double ms) -> Status {
        const FramePass& pass = frame.passes[p];
        std::vector<CapturedTarget> targets;
        std::vector<uint32_t> written = Attachments(pass);
        written.insert(written.end(), pass.resolves.begin(), pass.resolves.end());
        for (uint32_t t : written) {
            const FrameTarget& target = frame.targets[t];
            if ((target.depth && pass.depth_read_only) || target.samples != VK_SAMPLE_COUNT_1_BIT ||
                !target.shown) {
                continue;  // unchanged by the pass, shown resolved, or never written
            }
            CapturedTarget& ct = targets.emplace_back();
            ct.target = t;
            ct.layer = target.cube ? pass.layer : 0;
            const VkExtent2D extent = ExtentOf(frame, target);
            ct.width = extent.width;
            ct.height = extent.height;
            if (Status e = ReadTarget(c, frame, f, t, ct.layer, layouts.current[t], ct.bytes);
                !e.ok()) {
                return e;
            }
        }
        return observer(frame, p, draw, std::move(targets), ms);
    };
    for (size_t p = 0; p < frame.passes.size(); ++p) {
        const FramePass& pass = frame.passes[p];
        if (pass.copy_from) {  // one step: the copy, and the target it fills
            VkCommandBuffer cmd = vk::BeginOneShot(c);
            if (cmd == VK_NULL_HANDLE) {
                return Error{DiagCode::kRenderFailed, "cannot allocate a command buffer"};
            }
            timer.Reset(cmd);
            layouts.Before(cmd, pass);
            timer.Mark(cmd, 0, false);
            RecordCopy(cmd, frame, f, pass);
            timer.Mark(cmd, 1, true);
            if (Status e = vk::SubmitAndWait(c, cmd); !e.ok()) {
                return e;
            }
            if (Status e = capture(p, -1, StepMilliseconds(timer)); !e.ok()) {
                return e;
            }
            continue;
        }
        VkRenderPass load = VK_NULL_HANDLE;
        if (Status e = s.RenderPass(FormatsOf(frame, pass), false, pass.depth_read_only, load);
            !e.ok()) {
            return e;
        }
        // The pass's layout transitions, and its clear as a step of its own.
        VkCommandBuffer cmd = vk::BeginOneShot(c);
        if (cmd == VK_NULL_HANDLE) {
            return Error{DiagCode::kRenderFailed, "cannot allocate a command buffer"};
        }
        layouts.Before(cmd, pass);
        if (pass.clear) {
            BeginPass(cmd, frame, f, p, f.render_passes[p]);
            vkCmdEndRenderPass(cmd);
        }
        if (Status e = vk::SubmitAndWait(c, cmd); !e.ok()) {
            return e;
        }
        if (pass.clear) {
            if (Status e = capture(p, -1, -1); !e.ok()) {
                return e;
            }
        }
        for (size_t i = 0; i < pass.draws.size(); ++i) {
            // A step is a draw and the draws that join it (a light's stencil mask).
            const size_t first = i;
            while (i + 1 < pass.draws.size() && pass.draws[i].joins_next) {
                ++i;
            }
            cmd = vk::BeginOneShot(c);
            if (cmd == VK_NULL_HANDLE) {
                return Error{DiagCode::kRenderFailed, "cannot allocate a command buffer"};
            }
            timer.Reset(cmd);
            BeginPass(cmd, frame, f, p, load);
            timer.Mark(cmd, 0, false);
            RecordDraws(cmd, std::span(pass.draws).subspan(first, i + 1 - first),
                        std::span(f.sets[p]).subspan(first, i + 1 - first),
                        {{0, 0}, ExtentOf(frame, pass)});
            timer.Mark(cmd, 1, true);
            vkCmdEndRenderPass(cmd);
            if (Status e = vk::SubmitAndWait(c, cmd); !e.ok()) {
                return e;
            }
            if (Status e = capture(p, int(i), StepMilliseconds(timer)); !e.ok()) {
                return e;
            }
        }
    }
    return ReadOutput(c, frame, f, layouts.current[frame.output], out);
}

}  // namespace kiln::runtime
