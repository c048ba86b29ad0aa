// A pack's SPIR-V is checked before it reaches the driver: a checksum is not authentication, and
// drivers crash on modules that spirv-val rejects (an id bound of 0x7fffffff) or that bind outside
// the pipeline layout (a Binding decoration of 2^30). Each distinct module goes through spirv-val
// once per renderer (cached by its hash); the cheap checks against the variant's layout run for
// every pipeline. RendererOptions::trust_packs skips all of it for packs one built oneself.
#ifndef KILN_RUNTIME_VK_SPIRV_CHECK_H_
#define KILN_RUNTIME_VK_SPIRV_CHECK_H_

#include <vulkan/vulkan.h>

#include <cstdint>
#include <mutex>
#include <optional>
#include <set>
#include <span>
#include <unordered_set>
#include <utility>

#include "kiln/pack/format.h"
#include "kiln/result.h"

namespace kiln::vk {

// The largest binding number and descriptor count Kiln's binding model uses
// (docs/binding-model.md) is far below these; anything above is not from Kiln's compiler.
inline constexpr uint32_t kMaxBindingNumber = 1023;
inline constexpr uint32_t kMaxDescriptorCount = 1024;

class ModuleChecker {
  public:
    explicit ModuleChecker(const VkPhysicalDeviceLimits& limits) : limits_(limits) {}

    // Success when `words` may be handed to the driver as the `stage` module of a pipeline whose
    // layout has exactly the (set, binding) pairs in `layout`.
    Status Check(std::span<const uint32_t> words,
                 pack::Stage stage,
                 const std::set<std::pair<uint32_t, uint32_t>>& layout);

    const VkPhysicalDeviceLimits& limits() const { return limits_; }
    // Distinct modules spirv-val has accepted so far.
    size_t validated_count() {
        std::lock_guard<std::mutex> lock(mu_);
        return validated_.size();
    }

  private:
    VkPhysicalDeviceLimits limits_;
    std::mutex mu_;
    std::unordered_set<uint64_t> validated_;  // XXH64 of modules spirv-val accepted
};

}  // namespace kiln::vk

#endif  // KILN_RUNTIME_VK_SPIRV_CHECK_H_
