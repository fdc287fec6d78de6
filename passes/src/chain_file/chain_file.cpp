#include <hush/passes/chain_file.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <hush/passes/bmfr/chain.hpp>
#include <hush/passes/eaw/chain.hpp>
#include <hush/passes/svgf/chain.hpp>
#include <hush/core/error.hpp>

#include "chain_file/graph_chain.hpp"
#include "chain_file/settings_json.hpp"

namespace hush::passes {

using chain_file::fail;
using chain_file::Json;
using chain_file::ObjectReader;

std::vector<std::string> builtinChainNames() { return {"svgf", "eaw", "bmfr"}; }

std::unique_ptr<Chain> makeBuiltinChain(std::string_view name) {
    if (name == "svgf") return std::make_unique<SvgfChain>();
    if (name == "eaw") return std::make_unique<EawChain>();
    if (name == "bmfr") return std::make_unique<BmfrChain>();
    return nullptr;
}

namespace {

bool validId(const std::string& id) {
    if (id.empty() || id == "input") return false;
    return std::all_of(id.begin(), id.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
    });
}

// A built-in chain under the file's name, so that two presets of one chain stay
// apart in reports and output folders.
class NamedChain : public Chain {
public:
    NamedChain(std::string name, std::unique_ptr<Chain> inner) : name_(std::move(name)), inner_(std::move(inner)) {}
    std::string name() const override { return name_; }
    std::vector<InputChannel> inputs() const override { return inner_->inputs(); }
    ChainOutputs build(NodeContext& ctx, const DenoiseInputs& inputs) override { return inner_->build(ctx, inputs); }
    const Chain& inner() const { return *inner_; }

private:
    std::string name_;
    std::unique_ptr<Chain> inner_;
};

std::unique_ptr<Chain> presetChain(ObjectReader& root, const std::string& base) {
    if (base == "svgf") {
        SvgfSettings settings;
        chain_file::readSection(root, "settings", settings);
        return std::make_unique<SvgfChain>(settings);
    }
    if (base == "eaw") {
        EawChainSettings settings;
        chain_file::readSection(root, "settings", settings);
        return std::make_unique<EawChain>(settings);
    }
    if (base == "bmfr") {
        BmfrSettings settings;
        chain_file::readSection(root, "settings", settings);
        return std::make_unique<BmfrChain>(settings);
    }
    fail(root.source(), "base", "unknown chain '" + base + "'; built-in chains: svgf, eaw, bmfr");
}

chain_file::NodeInstance readNode(const Json& value, const std::string& source, const std::string& path) {
    ObjectReader r(value, source, path);
    chain_file::NodeInstance node;
    node.path = path;
    std::string type;
    r.read("id", node.id);
    r.read("node", type);
    if (!validId(node.id))
        fail(source, r.path("id"), node.id.empty() ? "missing (every node needs an id)"
                                                   : "'" + node.id + "' is not a valid id (letters, digits, _ and -; "
                                                                     "not 'input')");
    if (type.empty()) fail(source, r.path("node"), "missing (the node type)");
    node.type = chain_file::findNodeType(type);
    if (!node.type) {
        std::string names;
        for (const auto& t : chain_file::nodeTypes()) names += (names.empty() ? "" : ", ") + std::string(t.type);
        fail(source, r.path("node"), "unknown node type '" + type + "'; node types: " + names);
    }
    node.inputs.assign(node.type->inputs.size(), {});
    if (const Json* inputs = r.child("inputs")) {
        ObjectReader in(*inputs, source, r.path("inputs"));
        for (size_t p = 0; p < node.type->inputs.size(); ++p) in.read(node.type->inputs[p].name, node.inputs[p]);
        in.finish();
    }
    static const Json empty = Json::object();
    const Json* settings = r.child("settings");
    ObjectReader s(settings ? *settings : empty, source, r.path("settings"));
    node.settings = node.type->readSettings(s);
    s.finish();
    r.finish();
    return node;
}

std::unique_ptr<Chain> customChain(ObjectReader& root, const Json& nodes) {
    const std::string& source = root.source();
    chain_file::ChainDescription d;
    d.source = source;
    d.name = std::filesystem::path(source).stem().string();
    root.read("name", d.name);
    chain_file::readSection(root, "sanitize", d.sanitize);
    if (!nodes.is_array() || nodes.empty()) fail(source, "nodes", "expected a non-empty array of nodes");
    std::set<std::string> ids;
    for (size_t i = 0; i < nodes.size(); ++i) {
        auto node = readNode(nodes[i], source, "nodes[" + std::to_string(i) + "]");
        if (!ids.insert(node.id).second) fail(source, node.path + ".id", "'" + node.id + "' is already used");
        d.nodes.push_back(std::move(node));
    }
    // svgf.temporal feeds back the first level of an svgf.atrous node, defined anywhere.
    for (const auto& node : d.nodes) {
        if (node.type->type != "svgf.temporal") continue;
        const auto& id = std::any_cast<const chain_file::TemporalNodeSettings&>(node.settings).colorHistory;
        const bool ok = std::any_of(d.nodes.begin(), d.nodes.end(),
                                    [&](const auto& n) { return n.id == id && n.type->type == "svgf.atrous"; });
        if (!ok) fail(source, node.path + ".settings.colorHistory", "'" + id + "' is not an svgf.atrous node");
    }
    const Json* outputs = root.child("outputs");
    if (!outputs) fail(source, "", "missing 'outputs' ({\"display\": ..., \"radiance\": ...})");
    ObjectReader out(*outputs, source, "outputs");
    out.read("display", d.displayOutput);
    out.read("radiance", d.radianceOutput);
    out.finish();
    return std::make_unique<chain_file::GraphChain>(std::move(d));
}

} // namespace

const Chain& unwrapChain(const Chain& chain) {
    if (const auto* named = dynamic_cast<const NamedChain*>(&chain)) return named->inner();
    return chain;
}

std::unique_ptr<Chain> parseChainJson(std::string_view text, const std::string& source) {
    const Json json = chain_file::parse(text, source);
    ObjectReader root(json, source, "");
    std::string base;
    root.read("base", base);
    const Json* nodes = root.child("nodes");
    if (!base.empty() && nodes) fail(source, "", "give either 'base' (a built-in chain) or 'nodes', not both");
    std::unique_ptr<Chain> chain;
    if (!base.empty()) {
        std::string name = std::filesystem::path(source).stem().string();
        root.read("name", name);
        chain = std::make_unique<NamedChain>(name, presetChain(root, base));
    } else if (nodes) {
        chain = customChain(root, *nodes);
    } else {
        fail(source, "", "expected 'base' (svgf, eaw or bmfr) or 'nodes'");
    }
    root.finish();
    return chain;
}

std::unique_ptr<Chain> loadChainFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(ErrorKind::NotFound, "chain file '" + path + "' cannot be opened");
    std::ostringstream text;
    text << in.rdbuf();
    return parseChainJson(text.str(), path);
}

std::unique_ptr<Chain> makeChain(const std::string& nameOrPath) {
    if (auto chain = makeBuiltinChain(nameOrPath)) return chain;
    if (!std::filesystem::exists(nameOrPath)) {
        std::string names;
        for (const auto& n : builtinChainNames()) names += (names.empty() ? "" : ", ") + n;
        throw Error(ErrorKind::NotFound,
                    "'" + nameOrPath + "' is neither a built-in chain (" + names + ") nor a chain file");
    }
    return loadChainFile(nameOrPath);
}

std::string describeChainNodes() {
    std::ostringstream out;
    for (const auto& t : chain_file::nodeTypes()) {
        out << "  " << t.type << ": " << t.summary << "\n    inputs:";
        for (const auto& p : t.inputs) out << " " << p.name << (p.optional ? " (optional)" : "");
        out << "\n    outputs:";
        for (const auto& p : t.outputs) out << " " << p.name;
        out << "\n";
    }
    return out.str();
}

} // namespace hush::passes
