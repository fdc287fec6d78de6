#pragma once
// SvgfChain: spatiotemporal variance-guided filtering (Schied et al. 2017, seed 003),
// every stage its own node (docs/passes/svgf.md), between the shared front and back
// ends (chain_front_end.hpp, chain_back_end.hpp):
//   front end -> per lighting term {demodulate -> temporal accumulation (4.1) ->
//   variance estimate (4.2) -> 5 x (variance prefilter + a-trous) (4.3-4.4)} ->
//   remodulate -> back end (tonemap, TAA) (Sec. 4, Fig. 2).
// Direct and indirect illumination are filtered separately when the frames carry
// them (Sec. 4); otherwise the combined colour is one term.
#include <hush/passes/chain.hpp>
#include <hush/passes/chain_back_end.hpp>
#include <hush/passes/chain_front_end.hpp>
#include <hush/passes/svgf/atrous.hpp>
#include <hush/passes/svgf/temporal_accumulation.hpp>
#include <hush/passes/svgf/variance_estimate.hpp>

namespace hush::passes {

struct SvgfSettings {
    ChainFrontSettings front;
    bool splitLighting = true;       // filter direct and indirect apart (needs both channels)
    SvgfTemporalSettings temporal;   // alpha = 0.2 colour and moments (4.1)
    SvgfVarianceSettings variance;   // spatial estimate under 4 frames (4.2)
    SvgfAtrousSettings atrous;       // 5 levels, sigma_z 1, sigma_n 128, sigma_l 4 (4.3-4.4)
    ChainBackSettings back;
};

template <class V> void describe(V&& v, SvgfSettings& s) {
    v.flatten(s.front);
    v.field("splitLighting", s.splitLighting);
    v.section("temporal", s.temporal);
    v.section("variance", s.variance);
    v.section("atrous", s.atrous);
    v.flatten(s.back);
}

class SvgfChain : public Chain {
public:
    // Throws hush::Error (InvalidArgument) without an a-trous level (level 0 is the
    // colour history).
    explicit SvgfChain(const SvgfSettings& settings = {});
    std::string name() const override { return "svgf"; }
    std::vector<InputChannel> inputs() const override;
    ChainOutputs build(NodeContext& ctx, const DenoiseInputs& inputs) override;
    const SvgfSettings& settings() const { return settings_; }

private:
    SvgfSettings settings_;
};

} // namespace hush::passes
