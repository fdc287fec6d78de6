#include <hush/passes/chain_file.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include <hush/core/error.hpp>
#include <hush/core/read_file.hpp>
#include <hush/passes/bmfr/chain.hpp>
#include <hush/passes/eaw/chain.hpp>
#include <hush/passes/mara/chain.hpp>
#include <hush/passes/rdae/chain.hpp>
#include <hush/passes/settings_json.hpp>
#include <hush/passes/svgf/chain.hpp>

#include "chain_file/graph_chain.hpp"

namespace hush::passes {

using core::Json;
using core::JsonObject;

namespace {

// A built-in chain: its name and how it is made from its settings object (absent:
// the paper's defaults). Settings are read through the settings struct's describe().
struct BuiltinChain {
    std::string_view name;
    std::function<std::unique_ptr<Chain>(JsonObject* settings)> make;
};

template <class C, class S> BuiltinChain builtin(std::string_view name) {
    return {name, [](JsonObject* object) -> std::unique_ptr<Chain> {
                S settings;
                if (object) readSettings(*object, settings);
                return std::make_unique<C>(settings);
            }};
}

const std::vector<BuiltinChain>& builtinChains() {
    static const std::vector<BuiltinChain> chains{builtin<SvgfChain, SvgfSettings>("svgf"),
                                                  builtin<EawChain, EawChainSettings>("eaw"),
                                                  builtin<BmfrChain, BmfrSettings>("bmfr"),
                                                  builtin<MaraChain, MaraSettings>("mara"),
                                                  builtin<RdaeChain, RdaeSettings>("rdae")};
    return chains;
}

const BuiltinChain* findBuiltin(std::string_view name) {
    for (const auto& c : builtinChains())
        if (c.name == name) return &c;
    return nullptr;
}

std::string builtinList() {
    std::string names;
    for (const auto& c : builtinChains()) names += (names.empty() ? "" : ", ") + std::string(c.name);
    return names;
}

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
    std::vector<InputChannel> optionalInputs() const override { return inner_->optionalInputs(); }
    ChainOutputs build(NodeContext& ctx, const DenoiseInputs& inputs) override { return inner_->build(ctx, inputs); }
    const Chain& inner() const { return *inner_; }

private:
    std::string name_;
    std::unique_ptr<Chain> inner_;
};

std::unique_ptr<Chain> presetChain(JsonObject& root, const std::string& base) {
    const BuiltinChain* chain = findBuiltin(base);
    if (!chain) core::failAt(root.source(), "base", "unknown chain '" + base + "'; built-in chains: " + builtinList());
    auto settings = root.get("settings");
    if (!settings) return chain->make(nullptr);
    JsonObject object(*settings);
    return chain->make(&object);
}

std::string nodeTypeList() {
    std::string names;
    for (const auto& t : chain_file::nodeTypes()) names += (names.empty() ? "" : ", ") + std::string(t.type);
    return names;
}

// "name", else the file's stem; it becomes a folder name, so it is checked here.
std::string chainName(JsonObject& root) {
    std::string name = std::filesystem::path(root.source()).stem().string();
    const bool given = root.has("name");
    root.read("name", name);
    if (!isValidChainName(name))
        core::failAt(root.source(), "name",
                     "'" + name + "' is not a valid chain name (" + std::string(kChainNameRule) + ")" +
                         (given ? "" : "; it comes from the file name: give \"name\" in the file"));
    return name;
}

chain_file::NodeInstance readNode(const core::JsonValue& value) {
    JsonObject r(value);
    chain_file::NodeInstance node;
    node.path = value.path();
    std::string type;
    r.read("id", node.id);
    r.read("node", type);
    if (!validId(node.id))
        core::failAt(value.source(), r.path("id"),
                     node.id.empty() ? "missing (every node needs an id)"
                                     : "'" + node.id + "' is not a valid id (letters, digits, _ and -; not 'input')");
    if (type.empty()) core::failAt(value.source(), r.path("node"), "missing (the node type)");
    node.type = chain_file::findNodeType(type);
    if (!node.type)
        core::failAt(value.source(), r.path("node"), "unknown node type '" + type + "'; node types: " + nodeTypeList());
    node.inputs.assign(node.type->inputs.size(), {});
    if (auto inputs = r.get("inputs")) {
        JsonObject in(*inputs);
        for (size_t p = 0; p < node.type->inputs.size(); ++p) in.read(node.type->inputs[p].name, node.inputs[p]);
        in.finish();
    }
    static const Json empty = Json::object();
    const auto settings = r.get("settings");
    JsonObject s = settings ? JsonObject(*settings) : JsonObject(empty, value.source(), r.path("settings"));
    node.settings = node.type->readSettings(s);
    s.finish();
    r.finish();
    return node;
}

std::unique_ptr<Chain> customChain(JsonObject& root, const core::JsonValue& nodes) {
    chain_file::ChainDescription d;
    d.source = root.source();
    d.name = chainName(root);
    if (auto sanitize = root.get("sanitize")) {
        JsonObject object(*sanitize);
        readSettings(object, d.sanitize);
    }
    if (!nodes.json().is_array() || nodes.json().empty()) nodes.fail("expected a non-empty array of nodes");
    std::set<std::string> ids;
    for (size_t i = 0; i < nodes.arraySize(); ++i) {
        auto node = readNode(nodes[i]);
        if (!ids.insert(node.id).second) core::failAt(d.source, node.path + ".id", "'" + node.id + "' is already used");
        d.nodes.push_back(std::move(node));
    }
    const auto outputs = root.get("outputs");
    if (!outputs) core::failAt(d.source, "", "missing 'outputs' ({\"display\": ..., \"radiance\": ...})");
    JsonObject out(*outputs);
    out.read("display", d.displayOutput);
    out.read("radiance", d.radianceOutput);
    out.finish();
    return std::make_unique<chain_file::GraphChain>(std::move(d));
}

} // namespace

bool isValidChainName(std::string_view name) {
    if (name.empty() || name.size() > 64 || name.front() == '.') return false;
    return std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
               c == '.';
    });
}

std::vector<std::string> builtinChainNames() {
    std::vector<std::string> names;
    for (const auto& c : builtinChains()) names.emplace_back(c.name);
    return names;
}

std::unique_ptr<Chain> makeBuiltinChain(std::string_view name) {
    const BuiltinChain* chain = findBuiltin(name);
    return chain ? chain->make(nullptr) : nullptr;
}

const Chain& unwrapChain(const Chain& chain) {
    if (const auto* named = dynamic_cast<const NamedChain*>(&chain)) return named->inner();
    return chain;
}

std::unique_ptr<Chain> parseChainJson(std::string_view text, const std::string& source) {
    const Json json = core::parseJson(text, source);
    JsonObject root(json, source, "");
    std::string base;
    root.read("base", base);
    const auto nodes = root.get("nodes");
    if (!base.empty() && nodes) core::failAt(source, "", "give either 'base' (a built-in chain) or 'nodes', not both");
    std::unique_ptr<Chain> chain;
    if (!base.empty()) {
        chain = std::make_unique<NamedChain>(chainName(root), presetChain(root, base));
    } else if (nodes) {
        chain = customChain(root, *nodes);
    } else {
        core::failAt(source, "", "expected 'base' (" + builtinList() + ") or 'nodes'");
    }
    root.finish();
    return chain;
}

std::unique_ptr<Chain> loadChainFile(const std::string& path) {
    return parseChainJson(core::readFile(path, "chain file"), path);
}

std::unique_ptr<Chain> makeChain(const std::string& nameOrPath) {
    if (auto chain = makeBuiltinChain(nameOrPath)) return chain;
    if (!std::filesystem::exists(nameOrPath))
        throw Error(ErrorKind::NotFound,
                    "'" + nameOrPath + "' is neither a built-in chain (" + builtinList() + ") nor a chain file");
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
