// The compile worker: the process that runs glslang and SPIRV-Tools for a compile, so that a crash,
// a runaway loop or an exhausted allocation in them ends one request, not the compile
// (docs/variants.md, "Isolation"). `kiln-worker` is this function's thin executable; kiln starts
// it itself and nobody else needs to.
#ifndef KILN_COMPILE_WORKER_H_
#define KILN_COMPILE_WORKER_H_

namespace kiln {

// Serves requests on the socket named by `--fd N` until it is closed (the protocol, with its
// hello and the files it asks the client for, is compiler/src/worker/protocol.h). Also takes
// `--memory-limit BYTES` (the address-space backstop) and `--stack BYTES` (the compile
// thread's).
int RunCompileWorker(int argc, char** argv);

}  // namespace kiln

#endif  // KILN_COMPILE_WORKER_H_
