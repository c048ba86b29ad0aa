// GPU timestamps: a query pool of `count` timestamps written into a command buffer and read back
// as milliseconds between marks. Inactive (every time negative) when the queue family has no
// timestamp bits; the caller needs no other check. Used by RecordFrame (per pass and per frame)
// and the frame debugger (per draw).
#ifndef KILN_RUNTIME_VK_TIMESTAMPS_H_
#define KILN_RUNTIME_VK_TIMESTAMPS_H_

#include <cstdint>
#include <vector>

#include "vk/context.h"

namespace kiln::vk {

class Timestamps {
  public:
    Timestamps(const Context& c, uint32_t count);
    ~Timestamps();
    Timestamps(const Timestamps&) = delete;
    Timestamps& operator=(const Timestamps&) = delete;

    bool active() const { return pool_ != VK_NULL_HANDLE; }
    // Outside a render pass, before the marks of a submission: `used` marks of the pool's
    // (all by default), which Intervals reads.
    void Reset(VkCommandBuffer cmd, uint32_t used = UINT32_MAX);
    uint32_t count() const { return count_; }
    // Query `index`: the top of the pipe for a start mark, the bottom for an end mark.
    void Mark(VkCommandBuffer cmd, uint32_t index, bool end);
    // After the submission completed: the times between consecutive marks, in milliseconds
    // (count - 1 values); empty when inactive or the results cannot be read.
    std::vector<double> Intervals() const;

  private:
    const Context& c_;
    uint32_t count_ = 0, used_ = 0;
    VkQueryPool pool_ = VK_NULL_HANDLE;
    uint64_t mask_ = 0;
};

}  // namespace kiln::vk

#endif  // KILN_RUNTIME_VK_TIMESTAMPS_H_
