#include "vk/context.h"

#include <algorithm>
#include <cstring>

namespace kiln::vk {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

VKAPI_ATTR VkBool32 VKAPI_CALL OnDebugMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                              VkDebugUtilsMessageTypeFlagsEXT,
                                              const VkDebugUtilsMessengerCallbackDataEXT* data,
                                              void* user) {
    if (severity < VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
        return VK_FALSE;
    }
    auto* log = static_cast<ValidationLog*>(user);
    std::lock_guard<std::mutex> lock(log->mutex);
    log->messages.emplace_back(data && data->pMessage ? data->pMessage : "(no message)");
    return VK_FALSE;
}

bool HasLayer(const char* name) {
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& l) {
        return std::strcmp(l.layerName, name) == 0;
    });
}

int DeviceRank(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
            return 0;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
            return 1;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
            return 2;
        case VK_PHYSICAL_DEVICE_TYPE_CPU:
            return 3;
        default:
            return 4;
    }
}

std::optional<uint32_t> GraphicsQueueFamily(VkPhysicalDevice device) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    for (uint32_t i = 0; i < count; ++i) {
        if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) {
            return i;
        }
    }
    return std::nullopt;
}

Status CreateInstance(const ContextOptions& options, Context& c) {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "kiln";
    app.pEngineName = "kiln";
    app.apiVersion = VK_API_VERSION_1_1;

    std::vector<const char*> layers;
    std::vector<const char*> extensions;
    if (options.validation) {
        if (!HasLayer(kValidationLayer)) {
            return Error{DiagCode::kRenderFailed,
                         "validation requested but VK_LAYER_KHRONOS_validation is not "
                         "installed (Debian package vulkan-validationlayers)"};
        }
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    }
    VkDebugUtilsMessengerCreateInfoEXT messenger{
        VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messenger.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger.pfnUserCallback = OnDebugMessage;
    messenger.pUserData = c.log;

    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    info.enabledLayerCount = uint32_t(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    info.pNext = options.validation ? &messenger : nullptr;  // also covers instance creation
    if (VkResult r = vkCreateInstance(&info, nullptr, &c.instance); r != VK_SUCCESS) {
        return VkError("cannot create a Vulkan instance", r);
    }
    if (options.validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(c.instance, "vkCreateDebugUtilsMessengerEXT"));
        if (!create || create(c.instance, &messenger, nullptr, &c.messenger) != VK_SUCCESS) {
            return Error{DiagCode::kRenderFailed, "cannot create the validation message callback"};
        }
        c.validation = true;
    }
    return {};
}

Status PickDevice(const ContextOptions& options, Context& c) {
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(c.instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(c.instance, &count, devices.data());
    int best_rank = 1 << 30;
    std::string seen;
    for (VkPhysicalDevice d : devices) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(d, &p);
        seen += std::string(seen.empty() ? "" : ", ") + p.deviceName;
        if (p.apiVersion < VK_API_VERSION_1_1 || !GraphicsQueueFamily(d)) {
            continue;
        }
        if (!options.device_filter.empty() &&
            std::string(p.deviceName).find(options.device_filter) == std::string::npos) {
            continue;
        }
        if (DeviceRank(p.deviceType) < best_rank) {
            best_rank = DeviceRank(p.deviceType);
            c.physical = d;
            c.properties = p;
        }
    }
    if (c.physical == VK_NULL_HANDLE) {
        return Error{
            DiagCode::kRenderFailed,
            "no Vulkan 1.1 device with a graphics queue" +
                (options.device_filter.empty() ? std::string()
                                               : " matching '" + options.device_filter + "'") +
                " (devices: " + (seen.empty() ? "none" : seen) +
                "; install mesa-vulkan-drivers for lavapipe)"};
    }
    vkGetPhysicalDeviceMemoryProperties(c.physical, &c.memory);
    c.queue_family = *GraphicsQueueFamily(c.physical);
    return {};
}

}  // namespace

const char* ResultName(VkResult result) {
    switch (result) {
        case VK_SUCCESS:
            return "VK_SUCCESS";
        case VK_ERROR_OUT_OF_HOST_MEMORY:
            return "VK_ERROR_OUT_OF_HOST_MEMORY";
        case VK_ERROR_OUT_OF_DEVICE_MEMORY:
            return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
        case VK_ERROR_INITIALIZATION_FAILED:
            return "VK_ERROR_INITIALIZATION_FAILED";
        case VK_ERROR_DEVICE_LOST:
            return "VK_ERROR_DEVICE_LOST";
        case VK_ERROR_LAYER_NOT_PRESENT:
            return "VK_ERROR_LAYER_NOT_PRESENT";
        case VK_ERROR_EXTENSION_NOT_PRESENT:
            return "VK_ERROR_EXTENSION_NOT_PRESENT";
        case VK_ERROR_FEATURE_NOT_PRESENT:
            return "VK_ERROR_FEATURE_NOT_PRESENT";
        case VK_ERROR_INCOMPATIBLE_DRIVER:
            return "VK_ERROR_INCOMPATIBLE_DRIVER";
        case VK_ERROR_FORMAT_NOT_SUPPORTED:
            return "VK_ERROR_FORMAT_NOT_SUPPORTED";
        case VK_ERROR_INVALID_SHADER_NV:
            return "VK_ERROR_INVALID_SHADER_NV";
        default:
            return "VkResult error";
    }
}

Error VkError(const char* what, VkResult result) {
    return Error{DiagCode::kRenderFailed, std::string(what) + " (" + ResultName(result) + " " +
                                              std::to_string(int(result)) + ")"};
}

Status CreateContext(const ContextOptions& options, Context& out) {
    Context c;
    c.log = new ValidationLog;
    auto fail = [&](Error e) {
        DestroyContext(c);
        return Status(std::move(e));
    };
    if (Status e = CreateInstance(options, c); !e.ok()) {
        return fail(e.error());
    }
    if (Status e = PickDevice(options, c); !e.ok()) {
        return fail(e.error());
    }
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue.queueFamilyIndex = c.queue_family;
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;
    VkPhysicalDeviceFeatures supported{};
    vkGetPhysicalDeviceFeatures(c.physical, &supported);
    VkPhysicalDeviceFeatures features{};
    features.independentBlend = supported.independentBlend;
    features.imageCubeArray = supported.imageCubeArray;  // samplerCUBE_Array defaults
    c.image_cube_array = supported.imageCubeArray == VK_TRUE;
    features.logicOp = supported.logicOp;  // BlendOp LogicalXor and the other logical ops
    c.logic_op = supported.logicOp == VK_TRUE;
    // Unity's #pragma geometry / hull / domain stages (lavapipe and desktop GPUs have both).
    features.geometryShader = supported.geometryShader;
    features.tessellationShader = supported.tessellationShader;
    c.geometry_shader = supported.geometryShader == VK_TRUE;
    c.tessellation_shader = supported.tessellationShader == VK_TRUE;
    // VK_KHR_maintenance4 relaxes vertex-output/fragment-input matching: a variant whose
    // fragment stage does not read every interpolator the shared vertex stage writes is valid
    // without it, but the validation layer reports it as a performance warning.
    std::vector<const char*> extensions;
    uint32_t ext_count = 0;
    vkEnumerateDeviceExtensionProperties(c.physical, nullptr, &ext_count, nullptr);
    std::vector<VkExtensionProperties> available(ext_count);
    vkEnumerateDeviceExtensionProperties(c.physical, nullptr, &ext_count, available.data());
    VkPhysicalDeviceMaintenance4FeaturesKHR maintenance4{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_4_FEATURES_KHR};
    // Packs compiled with --precision half compute in binary16 (the Float16 capability).
    VkPhysicalDeviceShaderFloat16Int8FeaturesKHR float16{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES_KHR};
    void* chain = nullptr;
    for (const VkExtensionProperties& e : available) {
        if (std::strcmp(e.extensionName, VK_KHR_MAINTENANCE_4_EXTENSION_NAME) == 0) {
            extensions.push_back(VK_KHR_MAINTENANCE_4_EXTENSION_NAME);
            maintenance4.maintenance4 = VK_TRUE;
            maintenance4.pNext = chain;
            chain = &maintenance4;
        }
        if (std::strcmp(e.extensionName, VK_KHR_SHADER_FLOAT16_INT8_EXTENSION_NAME) == 0) {
            VkPhysicalDeviceShaderFloat16Int8FeaturesKHR query{
                VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES_KHR};
            VkPhysicalDeviceFeatures2 all{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
            all.pNext = &query;
            vkGetPhysicalDeviceFeatures2(c.physical, &all);
            if (query.shaderFloat16) {
                extensions.push_back(VK_KHR_SHADER_FLOAT16_INT8_EXTENSION_NAME);
                float16.shaderFloat16 = VK_TRUE;
                float16.pNext = chain;
                chain = &float16;
                c.shader_float16 = true;
            }
        }
    }
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.pNext = chain;
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queue;
    info.pEnabledFeatures = &features;
    if (VkResult r = vkCreateDevice(c.physical, &info, nullptr, &c.device); r != VK_SUCCESS) {
        return fail(VkError("cannot create the Vulkan device", r));
    }
    vkGetDeviceQueue(c.device, c.queue_family, 0, &c.queue);
    VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool.queueFamilyIndex = c.queue_family;
    if (VkResult r = vkCreateCommandPool(c.device, &pool, nullptr, &c.command_pool);
        r != VK_SUCCESS) {
        return fail(VkError("cannot create a command pool", r));
    }
    out = c;
    return {};
}

void DestroyContext(Context& c) {
    if (c.command_pool) {
        vkDestroyCommandPool(c.device, c.command_pool, nullptr);
    }
    if (c.device) {
        vkDestroyDevice(c.device, nullptr);
    }
    if (c.messenger) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(c.instance, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy) {
            destroy(c.instance, c.messenger, nullptr);
        }
    }
    if (c.instance) {
        vkDestroyInstance(c.instance, nullptr);
    }
    delete c.log;
    c = Context{};
}

std::vector<std::string> ValidationMessages(const Context& context) {
    if (!context.log) {
        return {};
    }
    std::lock_guard<std::mutex> lock(context.log->mutex);
    return context.log->messages;
}

VkCommandBuffer BeginOneShot(const Context& context) {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = context.command_pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    if (vkAllocateCommandBuffers(context.device, &alloc, &cmd) != VK_SUCCESS) {
        return VK_NULL_HANDLE;
    }
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(cmd, &begin);
    return cmd;
}

Status SubmitAndWait(const Context& context, VkCommandBuffer cmd) {
    vkEndCommandBuffer(cmd);
    VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence = VK_NULL_HANDLE;
    vkCreateFence(context.device, &fence_info, nullptr, &fence);
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    VkResult r = vkQueueSubmit(context.queue, 1, &submit, fence);
    if (r == VK_SUCCESS) {
        r = vkWaitForFences(context.device, 1, &fence, VK_TRUE, UINT64_MAX);
    }
    vkDestroyFence(context.device, fence, nullptr);
    vkFreeCommandBuffers(context.device, context.command_pool, 1, &cmd);
    if (r != VK_SUCCESS) {
        return VkError("queue submission failed", r);
    }
    return {};
}

}  // namespace kiln::vk
