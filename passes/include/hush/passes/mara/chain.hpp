#pragma once
// MaraChain: Mara, McGuire, Bitterli and Jarosz 2017, "An Efficient Denoising
// Algorithm for Global Illumination" (seed 000; docs/passes/mara.md): the filter
// chain of Fig. 2 over the factored indirect terms (Sec. 3.1-3.3), every numbered
// stage its own graph pass:
//   front end (sanitize, surface; reprojection for TAA)
//   matte:  3 temporal -> 4 sparse pre-bilateral (fed back as the history)
//           5 disocclusion radius, 6 3x3 median, 7 sparse bilateral with that radius
//   glossy: 8 temporal on the virtual position -> 9, 10 separable bilateral
//   compose: direct + (1 - F)^2 albedo matte + F glossy -> back end (tonemap, TAA)
// The glossy branch is declared whenever the frames carry its layers (glossy,
// virtualpos, roughness); with `glossy` off the compose does not read it and the
// graph culls all of it.
#include <hush/passes/chain.hpp>
#include <hush/passes/chain_back_end.hpp>
#include <hush/passes/chain_front_end.hpp>
#include <hush/passes/mara/compose.hpp>
#include <hush/passes/mara/disocclusion.hpp>
#include <hush/passes/mara/glossy_bilateral.hpp>
#include <hush/passes/mara/median.hpp>
#include <hush/passes/mara/sparse_bilateral.hpp>
#include <hush/passes/mara/temporal.hpp>

namespace hush::passes {

enum class MaraGlossy : uint32_t {
    Auto = 0,   // filter the glossy term when the frames carry it
    On = 1,     // the frames must carry it
    Off = 2,    // leave it out (the graph culls the branch)
};
inline constexpr EnumNames<MaraGlossy, 3> kMaraGlossyNames{
    {{"auto", MaraGlossy::Auto}, {"on", MaraGlossy::On}, {"off", MaraGlossy::Off}}};

struct MaraSettings {
    // Mara et al. filter no term that carries emission (the direct light is not
    // filtered), so there is none to separate.
    ChainFrontSettings front{.separateEmission = false};
    MaraGlossy glossy = MaraGlossy::Auto;
    MaraTemporalSettings matteTemporal;                  // 3: h 0.98, d0 5 cm, d1 7 cm
    MaraSparseBilateralSettings preBilateral;            // 4: 50 taps, diameter 1% of the width
    MaraDisocclusionSettings disocclusion;               // 5: R = width / 20, x6 where c < 1/2
    bool fireflySuppression = true;                      // 6: the 3x3 median
    MaraSparseBilateralSettings bilateral;               // 7: radius from stage 5
    MaraTemporalSettings glossyTemporal;                 // 8: as 3, on virtual positions
    MaraGlossyBilateralSettings glossyBilateral;         // 9, 10: sigma = 7 roughness^0.1 + eps
    // The paper's chain ends at the composite (Fig. 2): no TAA by default. Measured on
    // every built-in scene, TAA after it costs RMSE except on cornell, and lowers the
    // temporal error (docs/passes/mara.md).
    ChainBackSettings back{.useTaa = false};
};

template <class V> void describe(V&& v, MaraSettings& s) {
    v.flatten(s.front);
    v.field("glossy", s.glossy, kMaraGlossyNames);
    v.section("matteTemporal", s.matteTemporal);
    v.section("preBilateral", s.preBilateral);
    v.section("disocclusion", s.disocclusion);
    v.field("fireflySuppression", s.fireflySuppression);
    v.section("bilateral", s.bilateral);
    v.section("glossyTemporal", s.glossyTemporal);
    v.section("glossyBilateral", s.glossyBilateral);
    v.flatten(s.back);
}

class MaraChain : public Chain {
public:
    explicit MaraChain(const MaraSettings& settings = {}) : settings_(settings) {}
    std::string name() const override { return "mara"; }
    std::vector<InputChannel> inputs() const override;
    std::vector<InputChannel> optionalInputs() const override;
    // Throws hush::Error (InvalidArgument) without the frame's camera.
    ChainOutputs build(NodeContext& ctx, const DenoiseInputs& inputs) override;
    const MaraSettings& settings() const { return settings_; }

private:
    graph::TextureHandle filterMatte(NodeContext& ctx, const ChainFrontEnd& front, const FrameCameraRef& camera) const;
    graph::TextureHandle filterGlossy(NodeContext& ctx, const ChainFrontEnd& front, const FrameCameraRef& camera) const;

    MaraSettings settings_;
};

} // namespace hush::passes
