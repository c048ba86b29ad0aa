#include "vk/timestamps.h"

#include <algorithm>

namespace kiln::vk {

Timestamps::Timestamps(const Context& c, uint32_t count) : c_(c), count_(count) {
    uint32_t n = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(c.physical, &n, nullptr);
    std::vector<VkQueueFamilyProperties> families(n);
    vkGetPhysicalDeviceQueueFamilyProperties(c.physical, &n, families.data());
    const uint32_t bits = c.queue_family < n ? families[c.queue_family].timestampValidBits : 0;
    if (bits == 0 || count < 2) {
        return;
    }
    mask_ = bits >= 64 ? ~uint64_t{0} : (uint64_t{1} << bits) - 1;
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = count;
    if (vkCreateQueryPool(c.device, &info, nullptr, &pool_) != VK_SUCCESS) {
        pool_ = VK_NULL_HANDLE;
    }
}

Timestamps::~Timestamps() {
    if (pool_) {
        vkDestroyQueryPool(c_.device, pool_, nullptr);
    }
}

void Timestamps::Reset(VkCommandBuffer cmd, uint32_t used) {
    used_ = std::min(used, count_);
    if (pool_) {
        vkCmdResetQueryPool(cmd, pool_, 0, used_);
    }
}

void Timestamps::Mark(VkCommandBuffer cmd, uint32_t index, bool end) {
    if (pool_ && index < used_) {
        vkCmdWriteTimestamp(
            cmd, end ? VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT : VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
            pool_, index);
    }
}

std::vector<double> Timestamps::Intervals() const {
    if (!pool_ || used_ < 2) {
        return {};
    }
    std::vector<uint64_t> t(used_);
    if (vkGetQueryPoolResults(c_.device, pool_, 0, used_, t.size() * sizeof(uint64_t), t.data(),
                              sizeof(uint64_t),
                              VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) != VK_SUCCESS) {
        return {};
    }
    const double period_ms = double(c_.properties.limits.timestampPeriod) * 1e-6;
    std::vector<double> out;
    for (uint32_t i = 1; i < used_; ++i) {
        const uint64_t ticks = ((t[i] & mask_) - (t[i - 1] & mask_)) & mask_;
        out.push_back(double(ticks) * period_ms);
    }
    return out;
}

}  // namespace kiln::vk
