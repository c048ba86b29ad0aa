#include "render/frame_cache.h"

#include <algorithm>

namespace kiln::runtime {

FrameCache::~FrameCache() {
    shapes_.clear();
    timer_.reset();
    vk::DestroyBuffer(c_, staging_);
    if (fence_) {
        vkDestroyFence(c_.device, fence_, nullptr);
    }
    if (cmd_) {
        vkFreeCommandBuffers(c_.device, c_.command_pool, 1, &cmd_);
    }
}

Status FrameCache::Prepare(Renderer::State& s,
                           const Frame& frame,
                           FrameObjects*& out,
                           uint32_t& allocations) {
    const std::string shape = ShapeOf(frame);
    auto it = std::find_if(shapes_.begin(), shapes_.end(),
                           [&](const auto& f) { return f->shape == shape; });
    if (it == shapes_.end()) {
        if (shapes_.size() >= kShapes) {
            shapes_.pop_back();  // the least recently used
        }
        auto f = std::make_unique<FrameObjects>(c_);
        f->shape = shape;
        if (Status e = CreateTargets(s, frame, *f, allocations); !e.ok()) {
            return e;
        }
        shapes_.push_front(std::move(f));
    } else if (it != shapes_.begin()) {
        shapes_.splice(shapes_.begin(), shapes_, it);
    }
    out = shapes_.front().get();
    return PrepareDraws(c_, frame, *out, allocations);
}

Status FrameCache::Begin(VkCommandBuffer& out, uint32_t& allocations) {
    if (!cmd_) {
        VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        alloc.commandPool = c_.command_pool;
        alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        alloc.commandBufferCount = 1;
        if (VkResult r = vkAllocateCommandBuffers(c_.device, &alloc, &cmd_); r != VK_SUCCESS) {
            cmd_ = VK_NULL_HANDLE;
            return vk::VkError("cannot allocate a command buffer", r);
        }
        ++allocations;
    } else if (VkResult r = vkResetCommandBuffer(cmd_, 0); r != VK_SUCCESS) {
        return vk::VkError("cannot reset the frame's command buffer", r);
    }
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    if (VkResult r = vkBeginCommandBuffer(cmd_, &begin); r != VK_SUCCESS) {
        return vk::VkError("cannot begin the frame's command buffer", r);
    }
    out = cmd_;
    return {};
}

Status FrameCache::SubmitAndWait(VkCommandBuffer cmd, uint32_t& allocations) {
    if (VkResult r = vkEndCommandBuffer(cmd); r != VK_SUCCESS) {
        return vk::VkError("cannot end the frame's command buffer", r);
    }
    if (!fence_) {
        VkFenceCreateInfo info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        if (VkResult r = vkCreateFence(c_.device, &info, nullptr, &fence_); r != VK_SUCCESS) {
            fence_ = VK_NULL_HANDLE;
            return vk::VkError("cannot create the frame's fence", r);
        }
        ++allocations;
    }
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    VkResult r = vkQueueSubmit(c_.queue, 1, &submit, fence_);
    if (r == VK_SUCCESS) {
        r = vkWaitForFences(c_.device, 1, &fence_, VK_TRUE, UINT64_MAX);
    }
    vkResetFences(c_.device, 1, &fence_);
    if (r != VK_SUCCESS) {
        return vk::VkError("queue submission failed", r);
    }
    return {};
}

vk::Timestamps& FrameCache::Timer(VkCommandBuffer cmd, uint32_t marks, uint32_t& allocations) {
    if (!timer_ || timer_->count() < marks) {
        timer_ = std::make_unique<vk::Timestamps>(
            c_, std::max(marks, 2 * (timer_ ? timer_->count() : 8u)));
        allocations += timer_->active() ? 1 : 0;
    }
    timer_->Reset(cmd, marks);
    return *timer_;
}

Status FrameCache::Staging(VkDeviceSize size, vk::Buffer*& out, uint32_t& allocations) {
    if (staging_.size < size) {
        vk::DestroyBuffer(c_, staging_);
        if (Status e = vk::CreateBuffer(c_, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, staging_);
            !e.ok()) {
            return e;
        }
        ++allocations;
    }
    out = &staging_;
    return {};
}

}  // namespace kiln::runtime
