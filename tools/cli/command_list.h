// Every kiln command, once: KILN_COMMAND(name, binary, Add function, summary), in the order
// `kiln --help` lists them. `binary` is the program that runs it: kKiln, or kKilnRender for the
// commands that link the renderer (Vulkan, OpenColorIO, tinygltf), which kiln hands to
// kiln-render beside it with the whole command line. Each main (tools/kiln, tools/kiln-render)
// makes its table from this list (cli.h, Command); the Add functions are in commands.h.
// An X-macro list, included more than once: no include guard.
// clang-format off
KILN_COMMAND("parse", kKiln, AddParseCommand, "Parse .shader files and print their AST")
KILN_COMMAND("compile", kKiln, AddCompileCommand, "Compile .shader files into a variant pack")
KILN_COMMAND("watch", kKiln, AddWatchCommand,
             "Compile like kiln compile, then again whenever a file the build read changes")
KILN_COMMAND("variants", kKiln, AddVariantsCommand,
             "List keyword sets and variant counts per pass, and unique stage programs")
KILN_COMMAND("lint", kKiln, AddLintCommand,
             "Report what the keywords cost and where they are wasted (every variant is built)")
KILN_COMMAND("diff", kKiln, AddDiffCommand,
             "Variants and bytes each shader and pass gains or loses between two packs")
KILN_COMMAND("info", kKiln, AddInfoCommand, "Describe a variant pack")
KILN_COMMAND("extract", kKiln, AddExtractCommand, "Write one variant's SPIR-V module to a file")
KILN_COMMAND("show", kKiln, AddShowCommand,
             "Show what Kiln compiled for one variant and stage: the HLSL glslang compiled, "
             "SPIR-V assembly, GLSL, ESSL, MSL, HLSL, reflection")
KILN_COMMAND("validate", kKiln, AddValidateCommand,
             "Check .material files against their shaders' Properties in a pack")
KILN_COMMAND("new", kKiln, AddNewCommand, "Write a new .shader from a templates/ scaffold")
KILN_COMMAND("render", kKilnRender, AddRenderCommand,
             "Render a glTF scene headless with the runtime")
KILN_COMMAND("test", kKilnRender, AddTestCommand,
             "Draw every variant of packs in a test harness and check it (docs/variants.md)")
KILN_COMMAND("report", kKilnRender, AddReportCommand,
             "Render a scene as a reference and in each approximation (light modes, deferred "
             "G-buffer formats, other packs) and report error against run time")
KILN_COMMAND("stability", kKilnRender, AddStabilityCommand,
             "Check lighting on stiff and extreme inputs: the templates' functions on adversarial "
             "grids against the CPU reference, or materials' variants under extreme lights and "
             "property values (--material); no NaN or infinity may appear")
// clang-format on
