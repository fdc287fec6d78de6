#pragma once
// SvgfChain: spatiotemporal variance-guided filtering (Schied et al. 2017, seed 003),
// every stage its own node (docs/passes/svgf.md):
//   sanitize -> surface -> reproject -> per lighting term {demodulate -> temporal
//   accumulation (4.1) -> variance estimate (4.2) -> 5 x (variance prefilter +
//   a-trous) (4.3-4.4)} -> remodulate -> tonemap -> TAA (Sec. 4, Fig. 2).
// Direct and indirect illumination are filtered separately when the frames carry
// them (Sec. 4); otherwise the combined colour is one term.
#include <hush/passes/chain.hpp>
#include <hush/passes/common/demodulate.hpp>
#include <hush/passes/common/reproject.hpp>
#include <hush/passes/common/sanitize.hpp>
#include <hush/passes/common/taa.hpp>
#include <hush/passes/common/tonemap.hpp>
#include <hush/passes/svgf/atrous.hpp>
#include <hush/passes/svgf/temporal_accumulation.hpp>
#include <hush/passes/svgf/variance_estimate.hpp>

namespace hush::passes {

struct SvgfSettings {
    bool splitLighting = true;   // filter direct and indirect apart (needs both channels)
    // Take the primary hit's emission out before filtering and add it back after
    // (no halo around emitters; docs/passes/common.md). Needs the emission channel.
    bool separateEmission = true;
    SanitizeSettings sanitize;
    DemodulateSettings demodulate;
    ReprojectSettings reproject;
    SvgfTemporalSettings temporal;   // alpha = 0.2 colour and moments (4.1)
    SvgfVarianceSettings variance;   // spatial estimate under 4 frames (4.2)
    SvgfAtrousSettings atrous;       // 5 levels, sigma_z 1, sigma_n 128, sigma_l 4 (4.3-4.4)
    TonemapSettings tonemap;
    TaaSettings taa;
    bool useTaa = true;
};

class SvgfChain : public Chain {
public:
    explicit SvgfChain(const SvgfSettings& settings = {});
    std::string name() const override { return "svgf"; }
    std::vector<InputChannel> inputs() const override;
    ChainOutputs build(NodeContext& ctx, const DenoiseInputs& inputs) override;
    const SvgfSettings& settings() const { return settings_; }

private:
    SvgfSettings settings_;
};

} // namespace hush::passes
