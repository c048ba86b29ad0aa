// The Vulkan instance, device and queue Kiln renders with: headless, one graphics queue, the
// validation layer on request with every message it sends counted and kept. Plain struct, free
// create/destroy (niagara's style).
#ifndef KILN_RUNTIME_VK_CONTEXT_H_
#define KILN_RUNTIME_VK_CONTEXT_H_

#include <vulkan/vulkan.h>

#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "kiln/result.h"

namespace kiln::vk {

struct ContextOptions {
    bool validation = false;    // enable VK_LAYER_KHRONOS_validation; an error when it is missing
    std::string device_filter;  // when set, only devices whose name contains it are considered
};

// Messages the validation layer (or the loader) reported through VK_EXT_debug_utils.
struct ValidationLog {
    std::mutex mutex;
    std::vector<std::string> messages;  // warnings and errors
};

struct Context {
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceMemoryProperties memory{};
    VkDevice device = VK_NULL_HANDLE;
    uint32_t queue_family = 0;
    VkQueue queue = VK_NULL_HANDLE;
    VkCommandPool command_pool = VK_NULL_HANDLE;
    bool validation = false;
    bool image_cube_array = false;     // the imageCubeArray feature is enabled
    bool logic_op = false;             // the logicOp feature is enabled
    bool shader_float16 = false;       // shaderFloat16 is enabled (--precision half packs)
    bool geometry_shader = false;      // the geometryShader feature is enabled
    bool tessellation_shader = false;  // the tessellationShader feature is enabled
    ValidationLog* log = nullptr;      // owned; the messenger's user data
};

// Picks a discrete GPU, then an integrated or virtual one, then a CPU device (lavapipe).
Status CreateContext(const ContextOptions& options, Context& out);
void DestroyContext(Context& context);

// Messages reported so far (copied under the log's lock).
std::vector<std::string> ValidationMessages(const Context& context);

const char* ResultName(VkResult result);
Error VkError(const char* what, VkResult result);

Status SubmitAndWait(const Context& context, VkCommandBuffer cmd);
VkCommandBuffer BeginOneShot(const Context& context);

// Records and submits a one-off command buffer on the queue and waits for it.
template <class Record>
Status SubmitOnce(const Context& context, Record&& record) {
    VkCommandBuffer cmd = BeginOneShot(context);
    if (cmd == VK_NULL_HANDLE) {
        return Error{DiagCode::kRenderFailed, "cannot allocate a command buffer"};
    }
    record(cmd);
    return SubmitAndWait(context, cmd);
}

}  // namespace kiln::vk

#endif  // KILN_RUNTIME_VK_CONTEXT_H_
