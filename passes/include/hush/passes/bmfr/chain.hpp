#pragma once
// BmfrChain: blockwise multi-order feature regression (Koskela et al. 2019, seed 002),
// every stage its own node (docs/passes/bmfr-chain.md), the pipeline of Fig. 2:
//   sanitize -> surface -> reproject -> demodulate (Sec. 3) -> (I) accumulate the
//   noisy illumination, 20 % (Sec. 3.1) -> (II) per-block feature fit (Sec. 3.2) ->
//   (III) accumulate the fitted illumination, 10 %, through the same reprojection
//   decision (Sec. 3.3) -> remodulate -> tonemap -> TAA (Sec. 3.3).
// The colour is filtered as one term: the paper filters direct and indirect light at
// once (Sec. 3, "we filter both components at once").
#include <hush/passes/bmfr/accumulate.hpp>
#include <hush/passes/bmfr/fit.hpp>
#include <hush/passes/chain.hpp>
#include <hush/passes/chain_back_end.hpp>
#include <hush/passes/chain_front_end.hpp>

namespace hush::passes {

struct BmfrSettings {
    // Sec. 3: "we remove first bounce surface albedo"; the reprojection decision is made
    // once and used by both accumulations (Sec. 3.3).
    ChainFrontSettings front;
    BmfrAccumulateSettings accumulate;   // minWeight 0.2 (Sec. 3.1)
    BmfrFitSettings fit;                 // 32 x 32 blocks, 16 offsets, eps 0.01, Eq. 7's 10 features (Sec. 3.2, 5, 6.1)
    BmfrAccumulateSettings postAccumulate = bmfrPostAccumulateSettings();   // minWeight 0.1 (Sec. 3.3)
    // Store the BMFR temporaries (both accumulations, their histories and the fit
    // output) as rgba16f instead of rgba32f; Sec. 6.1 credits half-precision buffers
    // for part of the paper's speed. Overrides the three stages' `format`. Values are
    // clamped to +-65504 (the largest finite half); the fit's matrix stays fp32.
    bool halfPrecision = false;
    // Sec. 3.3: "As a last step of the pipeline, TAA (Karis 2014) is used".
    ChainBackSettings back;
};

template <class V> void describe(V&& v, BmfrSettings& s) {
    v.flatten(s.front);
    v.section("accumulate", s.accumulate);
    v.section("fit", s.fit);
    v.section("postAccumulate", s.postAccumulate);
    v.field("halfPrecision", s.halfPrecision);
    v.flatten(s.back);
}

class BmfrChain : public Chain {
public:
    // Throws hush::Error (InvalidArgument) on a bad accumulation weight.
    explicit BmfrChain(const BmfrSettings& settings = {});
    std::string name() const override { return "bmfr"; }
    std::vector<InputChannel> inputs() const override;
    ChainOutputs build(NodeContext& ctx, const DenoiseInputs& inputs) override;
    const BmfrSettings& settings() const { return settings_; }

private:
    BmfrSettings settings_;
};

} // namespace hush::passes
