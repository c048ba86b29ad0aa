#include "kiln/runtime/color.h"

#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "kiln/base/files.h"
#include "kiln/pack/names.h"

namespace OCIO = OCIO_NAMESPACE;

namespace kiln::runtime {
namespace {

std::string JoinNames(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names)
        out += (out.empty() ? "" : ", ") + n;
    return out;
}

constexpr const char* kLinear = "Linear Rec.709 (sRGB)";
constexpr const char* kSrgb = "sRGB - Texture";

constexpr uint64_t kMaxColorConfigBytes = uint64_t{16} << 20;

OCIO::ConstConfigRcPtr BuiltInConfig() {
    OCIO::ConfigRcPtr config = OCIO::Config::Create();
    config->setName("kiln-builtin");
    OCIO::ColorSpaceRcPtr linear = OCIO::ColorSpace::Create();
    linear->setName(kLinear);
    linear->setFamily("Scene-linear");
    config->addColorSpace(linear);

    OCIO::ColorSpaceRcPtr srgb = OCIO::ColorSpace::Create();
    srgb->setName(kSrgb);
    srgb->setFamily("Display");
    // Forward direction decodes: (x + 0.055) / 1.055)^2.4 above the break, x / 12.92 below.
    OCIO::ExponentWithLinearTransformRcPtr curve = OCIO::ExponentWithLinearTransform::Create();
    const double gamma[4] = {2.4, 2.4, 2.4, 1.0};
    const double offset[4] = {0.055, 0.055, 0.055, 0.0};
    curve->setGamma(gamma);
    curve->setOffset(offset);
    srgb->setTransform(curve, OCIO::COLORSPACE_DIR_TO_REFERENCE);
    config->addColorSpace(srgb);

    config->setRole(OCIO::ROLE_SCENE_LINEAR, kLinear);
    config->setRole(OCIO::ROLE_DEFAULT, kLinear);
    config->setRole(OCIO::ROLE_COLOR_PICKING, kSrgb);
    config->setRole(OCIO::ROLE_TEXTURE_PAINT, kSrgb);
    config->addDisplayView("sRGB", "Standard", kSrgb, "");
    config->addDisplayView("sRGB", "Raw", kLinear, "");
    config->validate();
    return config;
}

}  // namespace

struct ColorPipeline::Impl {
    OCIO::ConstCPUProcessorRcPtr decode_srgb;  // built-in sRGB -> linear
    OCIO::ConstCPUProcessorRcPtr display;      // scene_linear -> display/view
    float exposure_scale = 1;
};

ColorPipeline::ColorPipeline() = default;
ColorPipeline::~ColorPipeline() = default;
ColorPipeline::ColorPipeline(ColorPipeline&&) noexcept = default;
ColorPipeline& ColorPipeline::operator=(ColorPipeline&&) noexcept = default;

Result<ColorPipeline> ColorPipeline::Create(const ColorOptions& options) {
    auto impl = std::make_unique<Impl>();
    std::string description;
    try {
        OCIO::ConstConfigRcPtr builtin = BuiltInConfig();
        impl->decode_srgb = builtin->getProcessor(kSrgb, kLinear)->getDefaultCPUProcessor();

        std::string path = options.config_path;
        if (path.empty()) {
            const char* env = std::getenv("OCIO");
            path = env ? env : "";
        }
        // The config is read as every input is (bounded, regular files only); OpenColorIO
        // parses the text, with the config's folder as its working folder for the LUTs it names.
        OCIO::ConstConfigRcPtr config = builtin;
        if (!path.empty()) {
            Result<std::string> text = base::ReadRegularFile(path, kMaxColorConfigBytes);
            if (!text) {
                return Error{DiagCode::kBadColorConfig,
                             "cannot read the OpenColorIO config: " + text.error().message};
            }
            std::istringstream in(text.value());
            OCIO::ConfigRcPtr read = OCIO::Config::CreateFromStream(in)->createEditableCopy();
            std::error_code ec;
            const std::filesystem::path dir =
                std::filesystem::absolute(std::filesystem::path(path), ec).parent_path();
            read->setWorkingDir(dir.c_str());
            config = read;
        }
        const std::string display =
            options.display.empty() ? config->getDefaultDisplay() : options.display;
        std::vector<std::string> displays;
        for (int i = 0; i < config->getNumDisplays(); ++i)
            displays.emplace_back(config->getDisplay(i));
        if (std::find(displays.begin(), displays.end(), display) == displays.end()) {
            return Error{DiagCode::kBadColorConfig,
                         "display '" + display + "' is not in the OpenColorIO config" +
                             (path.empty() ? std::string(" (built-in)") : " '" + path + "'") +
                             pack::DidYouMean(display, displays) +
                             " (displays: " + JoinNames(displays) + ")"};
        }
        const std::string view =
            options.view.empty() ? config->getDefaultView(display.c_str()) : options.view;
        std::vector<std::string> views;
        for (int i = 0; i < config->getNumViews(display.c_str()); ++i)
            views.emplace_back(config->getView(display.c_str(), i));
        if (std::find(views.begin(), views.end(), view) == views.end()) {
            return Error{DiagCode::kBadColorConfig,
                         "view '" + view + "' is not a view of display '" + display + "'" +
                             pack::DidYouMean(view, views) + " (views: " + JoinNames(views) + ")"};
        }
        impl->display = config
                            ->getProcessor(OCIO::ROLE_SCENE_LINEAR, display.c_str(), view.c_str(),
                                           OCIO::TRANSFORM_DIR_FORWARD)
                            ->getDefaultCPUProcessor();
        description = (path.empty() ? std::string("built-in config") : "config '" + path + "'") +
                      ", display '" + display + "', view '" + view + "'";
    } catch (const OCIO::Exception& e) {
        return Error{DiagCode::kBadColorConfig, std::string("opencolorio: ") + e.what()};
    }
    if (!std::isfinite(options.exposure) || std::fabs(options.exposure) > 64) {
        return Error{DiagCode::kBadColorConfig,
                     "exposure must be a finite number of stops within [-64, 64]"};
    }
    impl->exposure_scale = std::exp2(options.exposure);
    ColorPipeline out;
    out.impl_ = std::move(impl);
    out.description_ = std::move(description);
    return out;
}

void ColorPipeline::SrgbToLinear(float rgb[3], bool hdr) const {
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(rgb[i])) {
            rgb[i] = 0;
        }
        rgb[i] = hdr ? std::max(rgb[i], 0.0f) : std::clamp(rgb[i], 0.0f, 1.0f);
    }
    impl_->decode_srgb->applyRGB(rgb);
}

void ColorPipeline::ApplyDisplay(std::vector<float>& rgba) const {
    for (size_t i = 0; i + 3 < rgba.size(); i += 4) {
        for (int c = 0; c < 3; ++c) {
            const float v = rgba[i + size_t(c)] * impl_->exposure_scale;
            rgba[i + size_t(c)] = std::isfinite(v) ? std::max(v, 0.0f) : 0.0f;
        }
    }
    if (rgba.empty()) {
        return;
    }
    OCIO::PackedImageDesc desc(rgba.data(), long(rgba.size() / 4), 1, 4);
    impl_->display->apply(desc);
}

std::vector<uint8_t> ColorPipeline::Quantize(const std::vector<float>& rgba) {
    std::vector<uint8_t> out(rgba.size());
    for (size_t i = 0; i < rgba.size(); ++i) {
        const float v = std::isfinite(rgba[i]) ? std::clamp(rgba[i], 0.0f, 1.0f) : 0.0f;
        out[i] = uint8_t(std::lround(v * 255.0f));
    }
    return out;
}

}  // namespace kiln::runtime
