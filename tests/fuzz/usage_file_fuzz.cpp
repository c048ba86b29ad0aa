// libFuzzer target: the usage file reader (kiln compile --usage reads engines' files) and the
// diagnostics-JSON reader (kiln compile --scene reads kiln-render's) on arbitrary bytes. Each
// answers a value or an error; a value written back must read back the same.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "kiln/diagnostic.h"
#include "kiln/pack/variant_selector.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const kiln::Result<kiln::pack::UsageLog> log = kiln::pack::ParseUsageFile(text);
    if (log) {
        const auto again = kiln::pack::ParseUsageFile(kiln::pack::UsageFileText(log.value()));
        if (!again || again.value().lookups.size() != log.value().lookups.size() ||
            again.value().materials != log.value().materials)
            std::abort();
    } else if (log.error().message.empty()) {
        std::abort();
    }
    const kiln::Result<kiln::DiagnosticList> diags = kiln::ParseDiagnosticsJson(text);
    if (diags) {
        const auto again = kiln::ParseDiagnosticsJson(kiln::FormatDiagnosticsJson(diags.value()));
        if (!again || again.value().all().size() != diags.value().all().size())
            std::abort();
    }
    return 0;
}
