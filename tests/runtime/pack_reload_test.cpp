// Live edit in the runtime (Renderer::ReplacePack, RemovePack): a pack replaced by one built from
// an edited shader draws the edit on the next frame, keeps the pipelines of the variants the
// edit did not change and makes only the others again; a bad replacement keeps the old pack; a
// removed pack's shaders are found nowhere.
#include <gtest/gtest.h>

#include "kiln/base/files.h"
#include "runtime/runtime_fixture.h"

namespace kiln::test {
namespace {

class PackReloadTest : public RuntimeTest {
  protected:
    void SetUp() override {
        RuntimeTest::SetUp();
        ASSERT_TRUE(Ok(renderer_.AddPack(KILN_RELOAD_PACK)));
        index_ = renderer_.pack_count() - 1;
        scene_ = SphereOnFloor(RuntimeData("reload.material"));
        scene_.id = runtime::NewSceneId();
        settings_.width = 160;
        settings_.height = 90;
    }

    // The pixel at the image's centre (the sphere), linear RGB.
    static glm::vec3 Centre(const runtime::LinearImage& image) {
        const size_t at = (size_t{image.height / 2} * image.width + image.width / 2) * 4;
        return {image.rgba[at], image.rgba[at + 1], image.rgba[at + 2]};
    }

    size_t index_ = 0;
    runtime::Scene scene_;
    runtime::FrameSettings settings_;
};

TEST_F(PackReloadTest, AnEditIsDrawnAndOnlyItsPipelinesAreMadeAgain) {
    runtime::FrameStats first;
    const runtime::LinearImage before = Render(scene_, settings_, &first);
    EXPECT_EQ(first.pipelines_created, 2u);  // the base pass and the added pass
    // On the sphere: the unlit grey (g, linear) plus 0.25 blue from pass 2.
    const float g = Centre(before).g;
    EXPECT_GT(g, 0.0f);
    EXPECT_NEAR(Centre(before).r, g, 0.01f);
    EXPECT_NEAR(Centre(before).b, g + 0.25f, 0.01f);

    const Result<runtime::Renderer::PackReload> edited =
        renderer_.ReplacePack(index_, KILN_RELOAD_EDITED_PACK);
    ASSERT_TRUE(edited) << edited.error().message;
    EXPECT_EQ(edited.value().pipelines_kept, 1u);     // the base pass: same code
    EXPECT_EQ(edited.value().pipelines_dropped, 1u);  // the added pass: now red
    runtime::FrameStats second;
    const runtime::LinearImage after = Render(scene_, settings_, &second);
    EXPECT_EQ(second.pipelines_created, 1u);
    EXPECT_NEAR(Centre(after).r, g + 0.25f, 0.01f);  // pass 2 now adds red
    EXPECT_NEAR(Centre(after).b, g, 0.01f);
    KeepImage(before);
    KeepImage(after);

    // Back to the original: the base pass's pipeline is kept again, and the frame is the first
    // one, bit for bit (the same pipelines' code on the same device).
    const auto restored = renderer_.ReplacePack(index_, KILN_RELOAD_PACK);
    ASSERT_TRUE(restored) << restored.error().message;
    EXPECT_EQ(restored.value().pipelines_kept, 1u);
    EXPECT_EQ(restored.value().pipelines_dropped, 1u);
    EXPECT_EQ(Render(scene_, settings_).rgba, before.rgba);
}

TEST_F(PackReloadTest, AReplacementThatFailsKeepsTheOldPack) {
    const runtime::LinearImage before = Render(scene_, settings_);
    const std::string missing = ::testing::TempDir() + "/no-such.kpack";
    const auto failed = renderer_.ReplacePack(index_, missing);
    ASSERT_FALSE(failed);
    EXPECT_EQ(failed.error().code, DiagCode::kCannotReadFile);
    // A damaged pack (a byte of its variant data changed) is refused before anything changes.
    Result<std::string> bytes = base::ReadRegularFile(KILN_RELOAD_EDITED_PACK, 1 << 20);
    ASSERT_TRUE(bytes);
    std::string damaged = bytes.value();
    const size_t variants = damaged.find("VARI");
    ASSERT_NE(variants, std::string::npos);
    uint64_t offset = 0;
    for (int k = 7; k >= 0; --k)
        offset = offset << 8 | uint8_t(damaged[variants + 8 + k]);
    damaged[offset] ^= 1;
    const std::string path = ::testing::TempDir() + "/damaged.kpack";
    ASSERT_TRUE(Ok(base::WriteFileAtomically(path, damaged, {})));
    const auto refused = renderer_.ReplacePack(index_, path);
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.error().code, DiagCode::kPackChecksum) << refused.error().message;
    EXPECT_FALSE(renderer_.ReplacePack(renderer_.pack_count(), KILN_RELOAD_PACK));
    runtime::FrameStats stats;
    EXPECT_EQ(Render(scene_, settings_, &stats).rgba, before.rgba);
    EXPECT_EQ(stats.pipelines_created, 0u);
}

TEST_F(PackReloadTest, ARemovedPacksShadersAreFoundNowhere) {
    (void)Render(scene_, settings_);
    const size_t packs = renderer_.pack_count();
    ASSERT_TRUE(Ok(renderer_.RemovePack(index_)));
    EXPECT_EQ(renderer_.pack_count(), packs);  // other packs keep their index
    EXPECT_EQ(renderer_.pack(index_).Count(pack::SectionTag::kShaders), 0u);
    runtime::LinearImage image;
    runtime::FrameStats stats;
    const Status drawn = renderer_.Render(scene_, settings_, color_, image, stats);
    ASSERT_FALSE(drawn.ok());
    EXPECT_NE(drawn.error().message.find("Test/Reload"), std::string::npos)
        << drawn.error().message;
    // The shipped materials still draw, and a pack can be loaded in its place again.
    ASSERT_TRUE(renderer_.ReplacePack(index_, KILN_RELOAD_PACK));
    const glm::vec3 again = Centre(Render(scene_, settings_));
    EXPECT_NEAR(again.b - again.r, 0.25f, 0.01f);
}

}  // namespace
}  // namespace kiln::test
