#pragma once
// The shared front of every chain: what all four methods do before their own stages.
//   sanitize (the numerical contract) -> surface + reprojection decision (when the
//   method or its TAA reads history) -> demodulation of each lighting term
// A method's chain (svgf/chain.hpp, ...) builds one, adds its own nodes between it
// and the back end (chain_back_end.hpp), and writes nothing else twice.
#include <string>
#include <vector>

#include <hush/passes/common/demodulate.hpp>
#include <hush/passes/common/reproject.hpp>
#include <hush/passes/common/sanitize.hpp>
#include <hush/passes/common/surface.hpp>
#include <hush/passes/denoise_inputs.hpp>
#include <hush/passes/node_context.hpp>
#include <hush/passes/settings.hpp>

namespace hush::passes {

struct ChainFrontSettings {
    // Take the primary hit's emission out before filtering and add it back after (no
    // halo around emitters; docs/passes/common.md). Needs the emission channel.
    bool separateEmission = true;
    SanitizeSettings sanitize;
    DemodulateSettings demodulate;
    ReprojectSettings reproject;
};

template <class V> void describe(V&& v, ChainFrontSettings& s) {
    v.field("separateEmission", s.separateEmission);
    v.section("sanitize", s.sanitize);
    v.section("demodulate", s.demodulate);
    v.section("reproject", s.reproject);
}

class ChainFrontEnd {
public:
    // The channels the front end reads: albedo, normal, depth; motion and meshid
    // when reprojecting; emission when separating it.
    static std::vector<InputChannel> inputs(const ChainFrontSettings& settings, bool reproject);

    // Adds "<chain>.sanitize" and, when `reproject`, "<chain>.surface" and
    // "<chain>.reproject" (one decision per frame, read by every temporal stage).
    ChainFrontEnd(NodeContext& ctx, std::string chain, const DenoiseInputs& raw, const ChainFrontSettings& settings,
                  bool reproject);

    // A sanitized input channel (invalid when the frame has none).
    graph::TextureHandle operator[](InputChannel channel) const { return sanitized_.inputs[channel]; }
    const DenoiseInputs& inputs() const { return sanitized_.inputs; }
    graph::BufferHandle sanitizeCounts() const { return sanitized_.counts; }
    const Surface& surface() const { return surface_; }                       // valid when reprojecting
    graph::TextureHandle reprojection() const { return reprojection_; }       // valid when reprojecting
    graph::TextureHandle emission() const;   // the separated emission, or invalid
    const std::string& chain() const { return chain_; }
    const ChainFrontSettings& settings() const { return settings_; }

    // "<chain>.<stage>": (term - emission) / albedo; the emission is taken out of the
    // term that carries it (`carriesEmission`: colour, or direct light).
    graph::TextureHandle demodulate(const std::string& stage, InputChannel term, bool carriesEmission = true) const;
    // "<chain>.remodulate": (a + b) * albedo + emission, the inverse of demodulate.
    graph::TextureHandle remodulate(graph::TextureHandle a, graph::TextureHandle b = {}) const;

private:
    NodeContext& ctx_;
    std::string chain_;
    ChainFrontSettings settings_;
    SanitizedInputs sanitized_;
    Surface surface_;
    graph::TextureHandle reprojection_;
};

// Channels a ∪ b, in InputChannel order, each once.
std::vector<InputChannel> mergeChannels(std::vector<InputChannel> a, const std::vector<InputChannel>& b);

} // namespace hush::passes
