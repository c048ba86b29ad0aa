// kiln-render: the commands of the one command table (cli/command_list.h) that link the renderer
// (Vulkan, OpenColorIO, tinygltf); kiln runs it for them.
#include "cli/commands.h"

int main(int argc, char** argv) {
    using namespace kiln::cli;
#define KILN_HOSTED_kKiln(fn) nullptr
#define KILN_HOSTED_kKilnRender(fn) &fn
#define KILN_COMMAND(name, binary, fn, summary) \
    Command{name, summary, Binary::binary, KILN_HOSTED_##binary(fn)},
    static const std::vector<Command> table = {
#include "cli/command_list.h"
    };
    return RunCli(argc, argv, Binary::kKilnRender, table);
}
