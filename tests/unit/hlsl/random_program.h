// A generator of random preprocessor programs for the tests of the inactive-text plan and the
// shared preamble (hlsl/inactive_text.h, hlsl/preamble.h).
#ifndef KILN_TESTS_UNIT_HLSL_RANDOM_PROGRAM_H_
#define KILN_TESTS_UNIT_HLSL_RANDOM_PROGRAM_H_

#include <cstdint>
#include <random>
#include <string>

#include "support/compile_support.h"

namespace kiln::test {

// Random programs over a few macros: conditionals nested and chained, defines and undefines in
// branches, includes with and without guards, expressions the plan evaluates and ones it does
// not. glslang must preprocess each alike with and without the blanking.
class RandomProgram {
  public:
    explicit RandomProgram(uint32_t seed) : rng_(seed) {}

    // f0.h to f3.h in `dir`: f0.h includes nothing, each later file may include the ones before
    // it, and f1.h and f3.h are guarded.
    void WriteIncludes(const ScratchDir& dir) {
        for (int f = 0; f < 4; ++f) {
            std::string text = File(1, f);
            if (f % 2 == 1)
                text = "#ifndef F" + std::to_string(f) + "_H\n#define F" + std::to_string(f) +
                       "_H\n" + text + "#endif\n";
            dir.Write("f" + std::to_string(f) + ".h", text);
        }
    }

    std::string File(int depth, int files) {
        std::string s;
        const int lines = Pick(2, 5);
        for (int i = 0; i < lines; ++i)
            s += Line(depth, files);
        return s + PlainLine();  // drawing nothing from the generator: the programs stay
    }

  private:
    int Pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
    std::string Name() { return std::string(1, static_cast<char>('A' + Pick(0, 4))); }

    std::string Expression(int depth) {
        switch (Pick(0, depth > 1 ? 4 : 12)) {
            case 0:
                return "defined(" + Name() + ")";
            case 1:
                return Name();
            case 2:
                return Name() + " == " + std::to_string(Pick(0, 2));
            case 3:
                return "!defined " + Name();
            case 4:
                return std::to_string(Pick(0, 1));
            case 5:
                return "(" + Expression(depth + 1) + " && " + Expression(depth + 1) + ")";
            case 6:
                return Expression(depth + 1) + " || " + Expression(depth + 1);
            case 7:
                return "FN(" + Name() + ")";  // not evaluated by the plan
            default:
                return Name() + " + 1 > " + std::to_string(Pick(0, 3));
        }
    }

    std::string Line(int depth, int files) {
        const int kind = Pick(0, depth > 2 ? 3 : 7);
        switch (kind) {
            case 0:
                return "float v" + std::to_string(counter_++) + " = " + Name() + ";\n";
            case 1: {
                // Undefined first: a redefinition with another value is glslang's error.
                const std::string n = Name();
                return "#undef " + n + "\n#define " + n + " " + std::to_string(Pick(0, 2)) + "\n";
            }
            case 2:
                return "#undef " + Name() + "\n";
            case 3:
                return files > 0 ? "#include \"f" + std::to_string(Pick(0, files - 1)) + ".h\"\n"
                                 : "// nothing\n";
            default: {
                std::string s =
                    Pick(0, 1) ? "#if " + Expression(0) + "\n" : "#ifdef " + Name() + "\n";
                s += File(depth + 1, files);
                for (int e = Pick(0, 2); e > 0; --e)
                    s += "#elif " + Expression(0) + "\n" + File(depth + 1, files);
                if (Pick(0, 1))
                    s += "#else /* else */\n" + File(depth + 1, files);
                return s + "#endif\n";
            }
        }
    }

    // Code for splicing (hlsl/splice.h): plain lines, one with a comment, and a macro call whose
    // argument runs on to the next line.
    std::string PlainLine() {
        static const char* const kLines[] = {
            "  float p%d = (0.5 + 1.0f) * .25 - 2e-3;\n",
            "\tint p%d = (7 << 2) >= 1 ? 0x1F : 3u;\n",
            "p%d . x :: y += z [ 1 ] , w;\n",
            "    float p%d = q(1, 2) + r; // with a comment\n",
            "float p%d = FN(1 +\n   2) + 3;\n",
        };
        const std::string line = kLines[plain_++ % 5];
        const size_t at = line.find("%d");
        return line.substr(0, at) + std::to_string(counter_++) + line.substr(at + 2);
    }

    std::mt19937 rng_;
    int counter_ = 0;
    int plain_ = 0;
};

}  // namespace kiln::test

#endif  // KILN_TESTS_UNIT_HLSL_RANDOM_PROGRAM_H_
