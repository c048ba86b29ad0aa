// The frame debugger's recording (RecordFrame with an observer): the same frame as RecordFrame
// records in one command buffer, submitted one step at a time — a pass's clear, then each draw in
// a render pass that loads what the steps before it wrote — with the targets the pass writes read
// back after each step and the draw timed with timestamp queries where the queue has them.
#include "render/frame_internal.h"

namespace kiln::runtime {
namespace {

// Two timestamps around a draw; inactive when the queue has no timestamp bits.
class DrawTimer {
  public:
    explicit DrawTimer(const vk::Context& c) : c_(c) {
        uint32_t n = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(c.physical, &n, nullptr);
        std::vector<VkQueueFamilyProperties> families(n);
        vkGetPhysicalDeviceQueueFamilyProperties(c.physical, &n, families.data());
        const uint32_t bits = c.queue_family < n ? families[c.queue_family].timestampValidBits : 0;
        if (bits == 0) {
            return;
        }
        mask_ = bits >= 64 ? ~uint64_t{0} : (uint64_t{1} << bits) - 1;
        VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        info.queryType = VK_QUERY_TYPE_TIMESTAMP;
        info.queryCount = 2;
        if (vkCreateQueryPool(c.device, &info, nullptr, &pool_) != VK_SUCCESS) {
            pool_ = VK_NULL_HANDLE;
        }
    }
    ~DrawTimer() {
        if (pool_) {
            vkDestroyQueryPool(c_.device, pool_, nullptr);
        }
    }
    DrawTimer(const DrawTimer&) = delete;
    DrawTimer& operator=(const DrawTimer&) = delete;

    void Reset(VkCommandBuffer cmd) {  // outside a render pass
        if (pool_) {
            vkCmdResetQueryPool(cmd, pool_, 0, 2);
        }
    }
    void Mark(VkCommandBuffer cmd, uint32_t query) {
        if (pool_) {
            vkCmdWriteTimestamp(cmd,
                                query == 0 ? VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT
                                           : VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT,
                                pool_, query);
        }
    }
    // Milliseconds between the marks of the last submitted step; negative when not timed.
    double Milliseconds() const {
        if (!pool_) {
            return -1;
        }
        uint64_t t[2] = {};
        if (vkGetQueryPoolResults(c_.device, pool_, 0, 2, sizeof t, t, sizeof t[0],
                                  VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) !=
            VK_SUCCESS) {
            return -1;
        }
        const uint64_t ticks = ((t[1] & mask_) - (t[0] & mask_)) & mask_;
        return double(ticks) * double(c_.properties.limits.timestampPeriod) * 1e-6;
    }

  private:
    const vk::Context& c_;
    VkQueryPool pool_ = VK_NULL_HANDLE;
    uint64_t mask_ = 0;
};

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
    DrawTimer timer(c);
    Layouts layouts{frame, f.targets,
                    std::vector<VkImageLayout>(frame.targets.size(), VK_IMAGE_LAYOUT_UNDEFINED)};
    const VkRect2D full{{0, 0}, {frame.width, frame.height}};
    // The targets pass `p` writes, read back where the steps left them.
    auto capture = [&](size_t p, int draw, double ms) -> Status {
        const FramePass& pass = frame.passes[p];
        std::vector<CapturedTarget> targets;
        for (uint32_t t : Attachments(pass)) {
            if (frame.targets[t].depth && pass.depth_read_only) {
                continue;  // unchanged by the pass
            }
            CapturedTarget& ct = targets.emplace_back();
            ct.target = t;
            if (Status e = ReadTarget(c, frame, f, t, layouts.current[t], ct.bytes); !e.ok()) {
                return e;
            }
        }
        return observer(frame, p, draw, std::move(targets), ms);
    };
    for (size_t p = 0; p < frame.passes.size(); ++p) {
        const FramePass& pass = frame.passes[p];
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
            timer.Mark(cmd, 0);
            RecordDraws(cmd, std::span(pass.draws).subspan(first, i + 1 - first),
                        std::span(f.sets[p]).subspan(first, i + 1 - first), full);
            timer.Mark(cmd, 1);
            vkCmdEndRenderPass(cmd);
            if (Status e = vk::SubmitAndWait(c, cmd); !e.ok()) {
                return e;
            }
            if (Status e = capture(p, int(i), timer.Milliseconds()); !e.ok()) {
                return e;
            }
        }
    }
    return ReadOutput(c, frame, f, layouts.current[frame.output], out);
}

}  // namespace kiln::runtime
