#include "chain_file/graph_chain.hpp"

#include <algorithm>
#include <map>

#include <hush/core/error.hpp>

namespace hush::passes::chain_file {

namespace {

constexpr std::string_view kInputPrefix = "input.";
constexpr std::string_view kHistoryPrefix = "history:";

bool isHistory(const std::string& ref) { return ref.rfind(kHistoryPrefix, 0) == 0; }
std::string historyTarget(const std::string& ref) { return ref.substr(kHistoryPrefix.size()); }

struct Resolved {
    const ValueKind* kind;
    // Where the value is once built: an input channel, or node `node`'s output `port`.
    int channel = -1;
    size_t node = 0, port = 0;
};

[[noreturn]] void fail(const ChainDescription& d, const std::string& where, const std::string& what) {
    core::failAt(d.source, where, what);
}

size_t outputPort(const ChainDescription& d, const NodeInstance& node, const std::string& portName,
                  const std::string& where) {
    const auto it = std::find_if(node.type->outputs.begin(), node.type->outputs.end(),
                                 [&](const PortSpec& p) { return p.name == portName; });
    if (it != node.type->outputs.end()) return size_t(it - node.type->outputs.begin());
    std::string names;
    for (const auto& p : node.type->outputs) names += (names.empty() ? "" : ", ") + std::string(p.name);
    fail(d, where, "node '" + node.id + "' (" + std::string(node.type->type) + ") has no output '" + portName +
                       "'; its outputs: " + names);
}

// Resolves `ref` as seen by node `before` (only nodes defined before it are visible).
Resolved resolve(const ChainDescription& d, const std::string& ref, size_t before, const std::string& where) {
    if (ref.rfind(kInputPrefix, 0) == 0) {
        const auto channel = parseInputChannel(std::string_view(ref).substr(kInputPrefix.size()));
        if (!channel) {
            std::string names;
            for (const auto& c : allInputChannels()) names += (names.empty() ? "" : ", ") + std::string(c.name);
            fail(d, where, "'" + ref + "' names no input channel; channels: " + names);
        }
        return {&kTextureKind, int(*channel)};
    }
    const auto dot = ref.find('.');
    const std::string id = ref.substr(0, dot);
    for (size_t n = 0; n < before; ++n) {
        const auto& node = d.nodes[n];
        if (node.id != id) continue;
        const size_t port = dot == std::string::npos ? 0 : outputPort(d, node, ref.substr(dot + 1), where);
        return {node.type->outputs[port].kind, -1, n, port};
    }
    const bool later = std::any_of(d.nodes.begin() + ptrdiff_t(before), d.nodes.end(),
                                   [&](const NodeInstance& n) { return n.id == id; });
    fail(d, where,
         "'" + ref + "' refers to " +
             (later ? "node '" + id + "', which is defined after this one (nodes run in file order; " +
                          "last frame's value of a later node is \"history:" + ref + "\")"
                    : "no node called '" + id + "' (and is not 'input.<channel>')"));
}

// What a reference gives, for a port of node `before`: a history may name any node.
Resolved resolveInput(const ChainDescription& d, const std::string& ref, size_t before, const std::string& where) {
    if (!isHistory(ref)) return resolve(d, ref, before, where);
    const Resolved target = resolve(d, historyTarget(ref), d.nodes.size(), where);
    if (target.channel >= 0 || target.kind != &kTextureKind)
        fail(d, where, "'" + ref + "': only a node's texture output has a history");
    return target;
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
                    fail(d, node.path, "input '" + std::string(spec.name) + "' of node '" + node.id + "' (" +
                                           std::string(node.type->type) + ") is not connected");
                continue;
            }
            const auto r = resolveInput(d, node.inputs[p], n, where);
            if (r.kind != spec.kind)
                fail(d, where, "'" + node.inputs[p] + "' is a " + std::string(r.kind->description) + ", but input '" +
                                   std::string(spec.name) + "' takes a " + std::string(spec.kind->description));
        }
    }
    if (d.displayOutput.empty()) fail(d, "outputs", "missing 'display' (the tonemapped image)");
    for (const auto& [key, ref] : {std::pair{"display", d.displayOutput}, std::pair{"radiance", d.radianceOutput}}) {
        if (ref.empty()) continue;
        const auto r = resolve(d, ref, d.nodes.size(), std::string("outputs.") + key);
        if (r.kind != &kTextureKind)
            fail(d, std::string("outputs.") + key, "'" + ref + "' is a " + std::string(r.kind->description) +
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
    // Histories are declared first and bound to their sources once every node is built.
    std::map<std::string, graph::TextureHandle> histories;
    for (const auto& node : d.nodes)
        for (const auto& ref : node.inputs)
            if (isHistory(ref) && !histories.count(ref))
                histories[ref] = ctx.graph.history(d.name + "." + ref, fullSize());
    std::vector<std::vector<Value>> built;
    auto value = [&](const std::string& ref, size_t before) -> Value {
        if (isHistory(ref)) return textureValue(histories.at(ref));
        const auto r = resolve(d, ref, before, d.source);
        if (r.channel >= 0) return textureValue(sanitized.inputs[InputChannel(r.channel)]);
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
    for (const auto& [ref, history] : histories)
        ctx.graph.bindHistory(history, value(historyTarget(ref), d.nodes.size()).textures[0]);
    const auto display = value(d.displayOutput, d.nodes.size()).textures[0];
    const auto radiance = d.radianceOutput.empty() ? display : value(d.radianceOutput, d.nodes.size()).textures[0];
    ctx.graph.markOutput(display);
    ctx.graph.markOutput(radiance);
    return {display, radiance, sanitized.counts};
}

} // namespace hush::passes::chain_file
