#include "chain_file/graph_chain.hpp"

#include <algorithm>
#include <map>

#include <hush/core/error.hpp>

namespace hush::passes::chain_file {

namespace {

constexpr std::string_view kInputPrefix = "input.";

struct Resolved {
    PortKind kind;
    // Where the value is once built: an input channel, or node `node`'s output `port`.
    int channel = -1;
    size_t node = 0, port = 0;
};

// Resolves `ref` as seen by node `before` (only nodes defined before it are visible).
Resolved resolve(const ChainDescription& d, const std::string& ref, size_t before, const std::string& where) {
    if (ref.rfind(kInputPrefix, 0) == 0) {
        const auto channel = parseInputChannel(std::string_view(ref).substr(kInputPrefix.size()));
        if (!channel) {
            std::string names;
            for (const auto& c : allInputChannels()) names += (names.empty() ? "" : ", ") + std::string(c.name);
            fail(d.source, where, "'" + ref + "' names no input channel; channels: " + names);
        }
        return {PortKind::Texture, int(*channel)};
    }
    const auto dot = ref.find('.');
    const std::string id = ref.substr(0, dot);
    for (size_t n = 0; n < before; ++n) {
        const auto& node = d.nodes[n];
        if (node.id != id) continue;
        size_t port = 0;
        if (dot != std::string::npos) {
            const std::string portName = ref.substr(dot + 1);
            auto it = std::find_if(node.type->outputs.begin(), node.type->outputs.end(),
                                   [&](const PortSpec& p) { return p.name == portName; });
            if (it == node.type->outputs.end()) {
                std::string names;
                for (const auto& p : node.type->outputs) names += (names.empty() ? "" : ", ") + std::string(p.name);
                fail(d.source, where, "node '" + id + "' (" + std::string(node.type->type) + ") has no output '" +
                                          portName + "'; its outputs: " + names);
            }
            port = size_t(it - node.type->outputs.begin());
        }
        return {node.type->outputs[port].kind, -1, n, port};
    }
    const bool later = std::any_of(d.nodes.begin() + ptrdiff_t(before), d.nodes.end(),
                                   [&](const NodeInstance& n) { return n.id == id; });
    fail(d.source, where,
         "'" + ref + "' refers to " +
             (later ? "node '" + id + "', which is defined after this one (nodes run in file order)"
                    : "no node called '" + id + "' (and is not 'input.<channel>')"));
}

} // namespace

void validate(const ChainDescription& d) {
    for (size_t n = 0; n < d.nodes.size(); ++n) {
        const auto& node = d.nodes[n];
        for (size_t p = 0; p < node.type->inputs.size(); ++p) {
            const auto& spec = node.type->inputs[p];
            const std::string where = node.path + ".inputs." + std::string(spec.name);
            if (node.inputs[p].empty()) {
                if (!spec.optional)
                    fail(d.source, node.path, "input '" + std::string(spec.name) + "' of node '" + node.id + "' (" +
                                                  std::string(node.type->type) + ") is not connected");
                continue;
            }
            const auto r = resolve(d, node.inputs[p], n, where);
            if (r.kind != spec.kind)
                fail(d.source, where, "'" + node.inputs[p] + "' is a " + std::string(toString(r.kind)) +
                                          ", but input '" + std::string(spec.name) + "' takes a " +
                                          std::string(toString(spec.kind)));
        }
    }
    if (d.displayOutput.empty()) fail(d.source, "outputs", "missing 'display' (the tonemapped image)");
    for (const auto& [key, ref] : {std::pair{"display", d.displayOutput}, std::pair{"radiance", d.radianceOutput}}) {
        if (ref.empty()) continue;
        const auto r = resolve(d, ref, d.nodes.size(), std::string("outputs.") + key);
        if (r.kind != PortKind::Texture)
            fail(d.source, std::string("outputs.") + key, "'" + ref + "' is a " + std::string(toString(r.kind)) +
                                                              ", not a texture");
    }
}

GraphChain::GraphChain(ChainDescription description) : description_(std::move(description)) {
    validate(description_);
    // The channels the nodes read, in InputChannel order.
    std::vector<bool> used(kInputChannelCount, false);
    auto mark = [&](const std::string& ref) {
        if (ref.rfind(kInputPrefix, 0) == 0)
            if (auto c = parseInputChannel(std::string_view(ref).substr(kInputPrefix.size()))) used[size_t(*c)] = true;
    };
    for (const auto& node : description_.nodes)
        for (const auto& ref : node.inputs) mark(ref);
    mark(description_.displayOutput);
    mark(description_.radianceOutput);
    for (const auto& info : allInputChannels())
        if (used[size_t(info.channel)]) inputs_.push_back(info.channel);
}

ChainOutputs GraphChain::build(NodeContext& ctx, const DenoiseInputs& raw) {
    const auto& d = description_;
    const auto sanitized = addSanitizePass(ctx, d.name + ".sanitize", raw, d.sanitize);
    std::vector<std::vector<Value>> built;
    auto value = [&](const std::string& ref, size_t before) -> Value {
        const auto r = resolve(d, ref, before, d.source);
        if (r.channel >= 0) return sanitized.inputs[InputChannel(r.channel)];
        return built[r.node][r.port];
    };
    for (size_t n = 0; n < d.nodes.size(); ++n) {
        const auto& node = d.nodes[n];
        std::vector<Value> inputs;
        inputs.reserve(node.inputs.size());
        for (const auto& ref : node.inputs) inputs.push_back(ref.empty() ? Value{} : value(ref, n));
        std::vector<const Value*> pointers;
        for (size_t p = 0; p < inputs.size(); ++p) pointers.push_back(node.inputs[p].empty() ? nullptr : &inputs[p]);
        built.push_back(node.type->build({ctx, node.id, pointers, node.settings}));
    }
    const auto display = std::get<graph::TextureHandle>(value(d.displayOutput, d.nodes.size()));
    const auto radiance = d.radianceOutput.empty()
                              ? display
                              : std::get<graph::TextureHandle>(value(d.radianceOutput, d.nodes.size()));
    ctx.graph.markOutput(display);
    ctx.graph.markOutput(radiance);
    return {display, radiance, sanitized.counts};
}

} // namespace hush::passes::chain_file
