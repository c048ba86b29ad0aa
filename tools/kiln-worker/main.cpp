// kiln-worker: glslang and SPIRV-Tools in a process of their own (kiln/compile_worker.h).
#include "kiln/compile_worker.h"

// In sanitizer builds (tests): a segmentation fault in glslang is an outcome the parent reports
// (K5009), so it ends the worker as the signal it is instead of as AddressSanitizer's report and
// abort; and glslang's process-lifetime tables, never freed, are not leak reports. Kiln's own code
// paths in here also run in-process in the unit tests, under the full checks.
extern "C" const char* __asan_default_options() {
    return "handle_segv=0:detect_leaks=0";
}

int main(int argc, char** argv) {
    return kiln::RunCompileWorker(argc, argv);
}
