#pragma once
// Tonemapping: linear HDR radiance -> linear display values in [0, 1] (the sRGB
// transfer curve is applied only when an 8-bit file is written). The curves:
//   AcesFit            Narkowicz, "ACES Filmic Tone Mapping Curve" (blog post, 2016-01-06):
//                      f(x) = x (a x + b) / (x (c x + d) + e), a = 2.51, b = 0.03,
//                      c = 2.43, d = 0.59, e = 0.14, saturated to [0, 1], per channel.
//                      A fit of ACES RRT + ODT, pre-exposed so that f(1) ~ 0.8 (for the
//                      original ACES exposure multiply x by 0.6, i.e. exposure = 0.6).
//   ReinhardLuminance  Reinhard et al. 2002, Eq. 3, L_d = L / (1 + L), on the Rec. 709
//                      luminance L; the colour is scaled by L_d / L = 1 / (1 + L) (no
//                      division by L), then each channel clamped to 1 (a saturated colour
//                      brighter than white clips; its hue shifts).
//   ReinhardPerChannel x / (1 + x) on each channel (desaturates the highlights).
// Input: exposure * radiance. Negative and non-finite input is not expected (sanitize
// runs first); negatives map to 0 all the same, and any finite input, however large
// (1e6, 65504, FLT_MAX), maps into [0, 1]. The same curves are exposed on the CPU so
// that tools tonemap references exactly as the GPU does before comparing.
#include <cstdint>
#include <string>

#include <hush/passes/settings.hpp>
#include <hush/passes/node_context.hpp>

namespace hush::passes {

enum class TonemapOperator : uint32_t {
    AcesFit = 0,              // Narkowicz 2016 fit of the ACES filmic curve (the default)
    ReinhardLuminance = 1,    // Reinhard 2002, Eq. 3, on luminance
    ReinhardPerChannel = 2,   // Reinhard 2002, Eq. 3, on each channel
};

struct TonemapSettings {
    TonemapOperator op = TonemapOperator::AcesFit;
    float exposure = 1.0f;   // multiplies the radiance before the curve
};

inline constexpr EnumNames<TonemapOperator, 3> kTonemapOperatorNames{
    {{"aces", TonemapOperator::AcesFit},
     {"reinhard-luminance", TonemapOperator::ReinhardLuminance},
     {"reinhard", TonemapOperator::ReinhardPerChannel}}};

template <class V> void describe(V&& v, TonemapSettings& s) {
    v.field("op", s.op, kTonemapOperatorNames);
    v.field("exposure", s.exposure, Range{0.0, kUnbounded});
}

// Adds pass "<name>"; returns the display values (rgba32f transient "<name>", alpha 1).
graph::TextureHandle addTonemapPass(NodeContext& ctx, const std::string& name, graph::TextureHandle radiance,
                                    const TonemapSettings& settings = {});

// The same curves on the CPU (fp32, the shader's order of operations).
float tonemapAcesFit(float x);          // Narkowicz's fit, saturated; x < 0 -> 0
float tonemapReinhard(float x);         // x / (1 + x); x < 0 -> 0
float tonemapLuminance(const float rgb[3]);   // Rec. 709: 0.2126 R + 0.7152 G + 0.0722 B
// Tonemaps rgb in place: exposure, then the operator.
void tonemap(const TonemapSettings& settings, float rgb[3]);

} // namespace hush::passes
