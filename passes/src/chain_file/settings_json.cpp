#include "chain_file/settings_json.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <utility>

namespace hush::passes::chain_file {

namespace {
constexpr float kBig = std::numeric_limits<float>::max();

// An enum given by name ("aces"); the error lists the names.
template <class E, size_t N>
void readEnum(ObjectReader& r, std::string_view key, E& out, const std::array<std::pair<const char*, E>, N>& names) {
    std::string text;
    r.read(key, text);
    if (text.empty()) return;
    std::string list;
    for (const auto& [name, value] : names) {
        if (text == name) {
            out = value;
            return;
        }
        list += (list.empty() ? "'" : ", '") + std::string(name) + "'";
    }
    fail(r.source(), r.path(key), "unknown value '" + text + "'; one of " + list);
}
} // namespace

void readSettings(ObjectReader& r, SanitizeSettings& s) { r.read("maxRadiance", s.maxRadiance, 1.0f, 1e30f); }

void readSettings(ObjectReader& r, DemodulateSettings& s) { r.read("eps", s.eps, 1e-12f, 1.0f); }

void readSettings(ObjectReader& r, ReprojectSettings& s) {
    r.read("normalCosine", s.normalCosine, -1.0f, 1.0f);
    r.read("depthSlopeTolerance", s.depthSlopeTolerance, 0.0f, kBig);
    r.read("depthRelativeTolerance", s.depthRelativeTolerance, 0.0f, kBig);
    r.read("fallback3x3", s.fallback3x3);
}

void readSettings(ObjectReader& r, SvgfTemporalSettings& s) {
    r.read("alpha", s.alpha, 0.0f, 1.0f);
    r.read("momentsAlpha", s.momentsAlpha, 0.0f, 1.0f);
    r.read("maxHistoryLength", s.maxHistoryLength, 1.0f, 65536.0f);
}

void readSettings(ObjectReader& r, SvgfVarianceSettings& s) {
    r.read("minHistoryLength", s.minHistoryLength, 0.0f, 65536.0f);
    uint32_t radius = uint32_t(s.radius);
    r.read("radius", radius, 0, 16);
    s.radius = int(radius);
    r.read("sigmaZ", s.sigmaZ, 0.0f, kBig);
    r.read("sigmaN", s.sigmaN, 0.0f, kBig);
    r.read("depthEpsilon", s.depthEpsilon, 0.0f, kBig);
    r.read("shortHistoryBoost", s.shortHistoryBoost);
}

void readSettings(ObjectReader& r, SvgfAtrousSettings& s) {
    r.read("iterations", s.iterations, 0, 16);
    r.read("sigmaZ", s.sigmaZ, 0.0f, kBig);
    r.read("sigmaN", s.sigmaN, 0.0f, kBig);
    r.read("sigmaL", s.sigmaL, 0.0f, kBig);
    r.read("depthEpsilon", s.depthEpsilon, 0.0f, kBig);
    r.read("luminanceEpsilon", s.luminanceEpsilon, 0.0f, kBig);
}

void readSettings(ObjectReader& r, EawSettings& s) {
    r.read("iterations", s.iterations, 0, 16);
    r.read("sigmaRt", s.sigmaRt, 0.0f, kBig);
    r.read("sigmaN", s.sigmaN, 0.0f, kBig);
    r.read("sigmaX", s.sigmaX, 0.0f, kBig);
    r.read("sigmaXRelative", s.sigmaXRelative, 0.0f, kBig);
}

void readSettings(ObjectReader& r, TonemapSettings& s) {
    readEnum(r, "op", s.op,
             std::array{std::pair{"aces", TonemapOperator::AcesFit},
                        std::pair{"reinhard-luminance", TonemapOperator::ReinhardLuminance},
                        std::pair{"reinhard", TonemapOperator::ReinhardPerChannel}});
    r.read("exposure", s.exposure, 0.0f, kBig);
}

void readSettings(ObjectReader& r, TaaSettings& s) {
    r.read("alpha", s.alpha, 0.0f, 1.0f);
    readEnum(r, "box", s.box, std::array{std::pair{"minmax", TaaBox::MinMax}, std::pair{"variance", TaaBox::Variance}});
    readEnum(r, "rectify", s.rectify,
             std::array{std::pair{"clamp", TaaRectify::Clamp}, std::pair{"clip", TaaRectify::Clip}});
    r.read("varianceGamma", s.varianceGamma, 0.0f, kBig);
    readEnum(r, "historyFilter", s.historyFilter,
             std::array{std::pair{"bilinear", TaaHistoryFilter::Bilinear},
                        std::pair{"catmull-rom", TaaHistoryFilter::CatmullRom}});
}

void readSettings(ObjectReader& r, SvgfSettings& s) {
    r.read("splitLighting", s.splitLighting);
    r.read("separateEmission", s.separateEmission);
    r.read("useTaa", s.useTaa);
    readSection(r, "sanitize", s.sanitize);
    readSection(r, "demodulate", s.demodulate);
    readSection(r, "reproject", s.reproject);
    readSection(r, "temporal", s.temporal);
    readSection(r, "variance", s.variance);
    readSection(r, "atrous", s.atrous);
    readSection(r, "tonemap", s.tonemap);
    readSection(r, "taa", s.taa);
}

void readSettings(ObjectReader& r, EawChainSettings& s) {
    r.read("separateEmission", s.separateEmission);
    readSection(r, "sanitize", s.sanitize);
    readSection(r, "demodulate", s.demodulate);
    readSection(r, "atrous", s.atrous);
    readSection(r, "tonemap", s.tonemap);
}

} // namespace hush::passes::chain_file

namespace hush::passes::chain_file {

void readSettings(ObjectReader& r, BmfrAccumulateSettings& s) { r.read("minWeight", s.minWeight, 1e-6f, 1.0f); }

void readSettings(ObjectReader& r, BmfrFitSettings& s) {
    r.read("blockSize", s.blockSize, 16, 64);
    if (s.blockSize != 16 && s.blockSize != 32 && s.blockSize != 64)
        fail(r.source(), r.path("blockSize"), "must be 16, 32 or 64");
    r.read("epsilon", s.epsilon, 0.0f, kBig);
    r.read("offsetBlocks", s.offsetBlocks);
    const Json* features = r.child("features");
    if (!features) return;
    // The names of BmfrFeature's values, in its order.
    static constexpr std::array<const char*, kBmfrFeatureKinds> kNames = {
        "one",        "normalX",    "normalY",    "normalZ", "positionX", "positionY",
        "positionZ",  "positionX2", "positionY2", "positionZ2", "albedoR", "albedoG",
        "albedoB",    "roughness",  "meshId",     "blockU",  "blockV"};
    const std::string path = r.path("features");
    if (!features->is_array() || features->empty() || features->size() > kBmfrMaxFeatures)
        fail(r.source(), path, "expected an array of 1 to " + std::to_string(kBmfrMaxFeatures) + " feature names");
    s.features.clear();
    for (size_t i = 0; i < features->size(); ++i) {
        const Json& f = (*features)[i];
        const std::string at = path + "[" + std::to_string(i) + "]";
        std::string list;
        for (const char* n : kNames) list += (list.empty() ? "'" : ", '") + std::string(n) + "'";
        if (!f.is_string()) fail(r.source(), at, "expected a feature name; one of " + list);
        const auto name = f.get<std::string>();
        const auto it = std::find(kNames.begin(), kNames.end(), name);
        if (it == kNames.end()) fail(r.source(), at, "unknown feature '" + name + "'; one of " + list);
        s.features.push_back(BmfrFeature(uint32_t(it - kNames.begin())));
    }
}

void readSettings(ObjectReader& r, BmfrSettings& s) {
    r.read("separateEmission", s.separateEmission);
    r.read("useTaa", s.useTaa);
    r.read("halfPrecision", s.halfPrecision);
    readSection(r, "sanitize", s.sanitize);
    readSection(r, "demodulate", s.demodulate);
    readSection(r, "reproject", s.reproject);
    readSection(r, "accumulate", s.accumulate);
    readSection(r, "fit", s.fit);
    readSection(r, "postAccumulate", s.postAccumulate);
    readSection(r, "tonemap", s.tonemap);
    readSection(r, "taa", s.taa);
}

} // namespace hush::passes::chain_file
