// libFuzzer target: the reader of a shader's modules file (driver/module_bundle.h) on arbitrary
// bytes. A cache directory may hold anything: the file reads as entries inside it or as nothing,
// every payload read lies in the payload area, and what it reads writes back to a file that reads
// the same.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "driver/module_bundle.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    const auto modules = kiln::driver::ReadModuleBundle(bytes);
    if (!modules)
        return 0;
    size_t payload_bytes = 0;
    for (const auto& [key, payload] : *modules) {
        if (key.size() != 32)
            std::abort();
        payload_bytes += payload.size();
    }
    if (payload_bytes > size)
        std::abort();
    const std::string written = kiln::driver::BuildModuleBundle(*modules);
    if (kiln::driver::ReadModuleBundle(written) != modules)
        std::abort();
    return 0;
}
