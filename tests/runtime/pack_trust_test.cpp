// Packs are not trusted: a pack with a valid checksum but SPIR-V the driver would crash on (an id
// bound of 0x7fffffff, a Binding decoration of 2^30, a broken instruction) is rejected before it
// reaches the driver, with the validation layer silent; each distinct module is validated once.
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>

#include <xxhash.h>

#include "kiln/pack/format.h"
#include "kiln/pack/reader.h"
#include "kiln/pack/records.h"
#include "kiln/pack/seal.h"
#include "runtime/runtime_fixture.h"
#include "vk/spirv_check.h"

namespace kiln::test {
namespace {

namespace fs = std::filesystem;

std::vector<uint8_t> ReadBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

uint32_t GetWord(const std::vector<uint8_t>& b, size_t at) {
    uint32_t w;
    std::memcpy(&w, b.data() + at, 4);
    return w;
}
// Where the MODL section starts (the section table read by hand).
size_t ModulesSection(const std::vector<uint8_t>& b) {
    uint32_t sections = 0;
    std::memcpy(&sections, b.data() + 12, 4);
    for (uint32_t i = 0; i < sections; ++i) {
        const uint8_t* e = b.data() + pack::kHeaderSize + i * pack::kSectionEntrySize;
        if (std::memcmp(e, "MODL", 4) == 0) {
            uint64_t offset = 0;
            std::memcpy(&offset, e + 8, 8);
            return size_t(offset);
        }
    }
    ADD_FAILURE() << "no MODL section";
    return 0;
}

void SetWord(std::vector<uint8_t>& b, size_t at, uint32_t w) {
    std::memcpy(b.data() + at, &w, 4);
}

// The shipped pack with `patch(bytes, module_offset, word_count)` applied to every module, each
// module's hash, the section sums and the checksum recomputed so that the reader accepts it: a
// forged pack, which only the checks of the SPIR-V itself can refuse.
std::string PatchedPack(const std::string& name,
                        const std::function<void(std::vector<uint8_t>&, size_t, size_t)>& patch) {
    std::vector<uint8_t> bytes = ReadBytes(KILN_MATERIALS_PACK);
    {
        pack::Pack p;
        EXPECT_TRUE(Into(pack::Pack::Open(bytes), p));
        std::vector<std::pair<size_t, size_t>> modules;
        for (uint32_t m = 0; m < p.Count(pack::SectionTag::kModules); ++m) {
            const auto spirv = p.Spirv(p.Module(m).value());
            modules.push_back({size_t(spirv.data() - bytes.data()), spirv.size() / 4});
        }
        for (const auto& [at, words] : modules)
            patch(bytes, at, words);
        // ModuleRec::hash is the 8 bytes after the offset and size of module m's record.
        const size_t records = ModulesSection(bytes);
        for (size_t m = 0; m < modules.size(); ++m) {
            const auto [at, words] = modules[m];
            const uint64_t hash = XXH64(bytes.data() + at, words * 4, 0);
            std::memcpy(bytes.data() + records + m * pack::RecordSize<pack::ModuleRec>() + 8, &hash,
                        8);
        }
    }
    pack::Seal(bytes);
    const std::string path = (fs::temp_directory_path() / name).string();
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    return path;
}

class PackTrustTest : public ::testing::Test {
  protected:
    void SetUp() override { PinVulkanLibraries(); }

    // Renders the Lambert material on a sphere from `pack` alone; the error, if any.
    Status RenderWith(const std::string& pack) {
        runtime::RendererOptions options;
        options.validation = true;
        Result<runtime::Renderer> made = runtime::Renderer::Create(options);
        if (!made)
            return made.error();
        runtime::Renderer renderer = std::move(made).value();
        if (Status e = renderer.AddPack(pack); !e.ok())
            return e;
        runtime::ColorPipeline color;
        EXPECT_TRUE(CreateColorInto({}, color));
        runtime::Scene scene =
            SphereOnFloor(std::string(KILN_SOURCE_DIR) + "/materials/Lambert.material");
        runtime::FrameSettings settings;
        settings.width = 64;
        settings.height = 48;
        runtime::LinearImage image;
        runtime::FrameStats stats;
        Status e = renderer.Render(scene, settings, color, image, stats);
        for (const std::string& m : renderer.ValidationMessages())
            ADD_FAILURE() << "the driver saw the module: " << m;
        return e;
    }
};

TEST_F(PackTrustTest, TheShippedPackRenders) {
    const auto e = RenderWith(KILN_MATERIALS_PACK);
    EXPECT_TRUE(Ok(e));
}

TEST_F(PackTrustTest, AnIdBoundPastSpirvsLimitIsRejected) {
    const std::string pack = PatchedPack(
        "kiln_bound.kpack", [](auto& b, size_t at, size_t) { SetWord(b, at + 12, 0x7fffffff); });
    const Status e = RenderWith(pack);
    ASSERT_FALSE(e.ok());
    EXPECT_EQ(e.error().code, DiagCode::kBadPack);
    EXPECT_NE(e.error().message.find("id bound 2147483647 is over SPIR-V's limit"),
              std::string::npos)
        << e.error().message;
}

TEST_F(PackTrustTest, ABindingOutsideTheLayoutIsRejected) {
    const std::string pack = PatchedPack("kiln_binding.kpack", [](auto& b, size_t at, size_t n) {
        for (size_t i = 5; i < n;) {
            const uint32_t w = GetWord(b, at + i * 4), count = w >> 16;
            if ((w & 0xFFFF) == 71 && count >= 4 && GetWord(b, at + (i + 2) * 4) == 33)
                SetWord(b, at + (i + 3) * 4, 1u << 30);  // OpDecorate %x Binding 2^30
            i += count == 0 ? n : count;
        }
    });
    const Status e = RenderWith(pack);
    ASSERT_FALSE(e.ok());
    EXPECT_NE(
        e.error().message.find("binding 1073741824, which the variant's layout does not have"),
        std::string::npos)
        << e.error().message;
}

TEST_F(PackTrustTest, AModuleSpirvValRejectsIsRejected) {
    // The first instruction after the header becomes an unknown opcode of the same length.
    const std::string pack = PatchedPack("kiln_opcode.kpack", [](auto& b, size_t at, size_t) {
        const uint32_t w = GetWord(b, at + 20);
        SetWord(b, at + 20, (w & 0xFFFF0000u) | 0xFFFEu);
    });
    const Status e = RenderWith(pack);
    ASSERT_FALSE(e.ok());
    EXPECT_NE(e.error().message.find("spirv-val:"), std::string::npos) << e.error().message;
}

TEST(ModuleChecker, EachDistinctModuleIsValidatedOnce) {
    std::vector<uint8_t> bytes = ReadBytes(KILN_MATERIALS_PACK);
    pack::Pack p;
    ASSERT_TRUE(Into(pack::Pack::Open(bytes), p));
    VkPhysicalDeviceLimits limits{};
    limits.maxBoundDescriptorSets = 8;
    vk::ModuleChecker checker(limits);
    const pack::ModuleRec m = p.Module(0).value();
    const auto spirv = p.Spirv(m);
    std::vector<uint32_t> words(spirv.size() / 4);
    std::memcpy(words.data(), spirv.data(), spirv.size());
    std::set<std::pair<uint32_t, uint32_t>> everything;
    for (uint32_t s = 0; s < 8; ++s) {
        for (uint32_t b = 0; b < 64; ++b)
            everything.insert({s, b});
    }
    const auto stage = pack::Stage(m.stage);
    EXPECT_TRUE(Ok(checker.Check(words, stage, everything)));
    EXPECT_TRUE(Ok(checker.Check(words, stage, everything)));
    EXPECT_EQ(checker.validated_count(), 1u);
    // The wrong stage for the module is refused even once it is known to be valid.
    const auto other =
        stage == pack::Stage::kVertex ? pack::Stage::kFragment : pack::Stage::kVertex;
    EXPECT_FALSE(checker.Check(words, other, everything).ok());
    EXPECT_TRUE(!checker.Check(words, stage, {}).ok() || words.empty())
        << "no layout, but bindings";
}

}  // namespace
}  // namespace kiln::test
