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
#include <hush/passes/common/demodulate.hpp>
#include <hush/passes/common/reproject.hpp>
#include <hush/passes/common/sanitize.hpp>
#include <hush/passes/common/taa.hpp>
#include <hush/passes/common/tonemap.hpp>

namespace hush::passes {

struct BmfrSettings {
    // Take the primary hit's emission out before filtering and add it back after, as
    // the other chains do (docs/passes/common.md). Needs the emission channel.
    bool separateEmission = true;
    SanitizeSettings sanitize;
    DemodulateSettings demodulate;   // Sec. 3: "we remove first bounce surface albedo"
    ReprojectSettings reproject;     // the shared decision, made once, used by both accumulations
    BmfrAccumulateSettings accumulate;   // minWeight 0.2 (Sec. 3.1)
    BmfrFitSettings fit;                 // 32 x 32 blocks, 16 offsets, eps 0.01, Eq. 7's 10 features (Sec. 3.2, 5, 6.1)
    BmfrAccumulateSettings postAccumulate = bmfrPostAccumulateSettings();   // minWeight 0.1 (Sec. 3.3)
    TonemapSettings tonemap;
    TaaSettings taa;
    bool useTaa = true;   // Sec. 3.3: "As a last step of the pipeline, TAA (Karis 2014) is used"
    // Store the BMFR temporaries (both accumulations, their histories and the fit
    // output) as rgba16f instead of rgba32f; Sec. 6.1 credits half-precision buffers
    // for part of the paper's speed. Overrides the three stages' `format`. Values are
    // clamped to +-65504 (the largest finite half); the fit's matrix stays fp32.
    bool halfPrecision = false;
};

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
