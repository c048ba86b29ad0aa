// kiln-worker: glslang and SPIRV-Tools in a process of their own (kiln/compile_worker.h).
#include "kiln/compile_worker.h"

int main(int argc, char** argv) {
    return kiln::RunCompileWorker(argc, argv);
}
