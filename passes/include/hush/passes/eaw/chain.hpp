#pragma once
// EawChain: the edge-avoiding a-trous wavelet filter of Dammertz et al. 2010, the
// baseline both the SVGF and the BMFR papers compare against: 5 a-trous levels with
// global edge-stopping parameters on colour, normal and world position, no
// temporal reuse and no variance guidance. Without TAA by default (the paper has
// none), so it reads no history at all:
//   front end (sanitize) -> demodulate -> 5 x a-trous -> remodulate -> tonemap
#include <hush/passes/chain.hpp>
#include <hush/passes/chain_back_end.hpp>
#include <hush/passes/chain_front_end.hpp>
#include <hush/passes/eaw/atrous.hpp>

namespace hush::passes {

struct EawChainSettings {
    ChainFrontSettings front;
    EawSettings atrous;
    ChainBackSettings back{.useTaa = false};
};

template <class V> void describe(V&& v, EawChainSettings& s) {
    v.flatten(s.front);
    v.section("atrous", s.atrous);
    v.flatten(s.back);
}

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
