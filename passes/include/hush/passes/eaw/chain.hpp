#pragma once
// EawChain: the edge-avoiding a-trous wavelet filter of Dammertz et al. 2010, the
// baseline both the SVGF and the BMFR papers compare against: 5 a-trous levels with
// global edge-stopping parameters on colour, normal and world position, no
// temporal reuse (so no TAA either) and no variance guidance.
//   sanitize -> demodulate -> 5 x a-trous -> remodulate -> tonemap
#include <hush/passes/chain.hpp>
#include <hush/passes/common/demodulate.hpp>
#include <hush/passes/common/sanitize.hpp>
#include <hush/passes/common/tonemap.hpp>
#include <hush/passes/eaw/atrous.hpp>

namespace hush::passes {

struct EawChainSettings {
    bool separateEmission = true;   // as SvgfSettings::separateEmission
    SanitizeSettings sanitize;
    DemodulateSettings demodulate;
    EawSettings atrous;
    TonemapSettings tonemap;
};

class EawChain : public Chain {
public:
    explicit EawChain(const EawChainSettings& settings = {}) : settings_(settings) {}
    std::string name() const override { return "eaw"; }
    std::vector<InputChannel> inputs() const override;
    ChainOutputs build(NodeContext& ctx, const DenoiseInputs& inputs) override;
    const EawChainSettings& settings() const { return settings_; }

private:
    EawChainSettings settings_;
};

} // namespace hush::passes
