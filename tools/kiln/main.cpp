// kiln: the shader-variant compiler's command line, over the one command table
// (cli/command_list.h). It runs the compile-side commands and hands the render-side ones to
// kiln-render beside it.
#include "cli/commands.h"

int main(int argc, char** argv) {
    using namespace kiln::cli;
#define KILN_HOSTED_kKiln(fn) &fn
#define KILN_HOSTED_kKilnRender(fn) nullptr
#define KILN_COMMAND(name, binary, fn, summary) \
    Command{name, summary, Binary::binary, KILN_HOSTED_##binary(fn)},
    static const std::vector<Command> table = {
#include "cli/command_list.h"
    };
    return RunCli(argc, argv, Binary::kKiln, table);
}
