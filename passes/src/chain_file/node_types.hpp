#pragma once
// The node types a chain file can name, each with its ports and a function that adds
// it to a graph. Each method registers its own in chain_file/nodes_<method>.cpp;
// nodeTypes() gathers them, so `describeChainNodes()` and the loader's errors list
// exactly what exists. A node type's settings are its settings struct, read through
// the struct's describe() (settings.hpp), so every field is reachable.
#include <any>
#include <array>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <hush/core/json.hpp>
#include <hush/passes/common/surface.hpp>
#include <hush/passes/node_context.hpp>
#include <hush/passes/settings_json.hpp>

namespace hush::passes::chain_file {

// The kind of value a port carries: one texture, or a node's bundle of textures (a
// surface, SVGF's temporal state). Connecting two kinds is an error naming both.
struct ValueKind {
    std::string_view name;
    std::string_view description;   // for errors: "surface (a 'surface' node)"
};
inline constexpr ValueKind kTextureKind{"texture", "texture"};
inline constexpr ValueKind kSurfaceKind{"surface", "surface (a 'surface' node)"};

// What flows along a connection.
struct Value {
    const ValueKind* kind = &kTextureKind;
    std::array<graph::TextureHandle, 4> textures{};
};
Value textureValue(graph::TextureHandle texture);
Value surfaceValue(const Surface& surface);
Surface surfaceOf(const Value& value);

struct PortSpec {
    std::string_view name;
    const ValueKind* kind = &kTextureKind;
    bool optional = false;
};

// What a node's build function gets.
struct NodeBuild {
    NodeContext& ctx;
    const std::string& name;                 // the node's id: its passes' name prefix
    std::span<const Value* const> inputs;    // by input port, nullptr when not connected
    const std::any& settings;

    // Input `port`'s texture, invalid when the port is not connected.
    graph::TextureHandle texture(size_t port) const { return inputs[port] ? inputs[port]->textures[0] : graph::TextureHandle{}; }
    const Value& value(size_t port) const { return *inputs[port]; }
    template <class S> const S& settingsAs() const { return std::any_cast<const S&>(settings); }
};

struct NodeType {
    std::string_view type;      // "svgf.atrous"
    std::string_view summary;
    std::vector<PortSpec> inputs;
    std::vector<PortSpec> outputs;   // the first one is what "<id>" alone refers to
    std::function<std::any(core::JsonObject&)> readSettings;
    std::function<std::vector<Value>(const NodeBuild&)> build;
};

// A settings reader for a node whose settings are one struct with a describe().
template <class S> std::function<std::any(core::JsonObject&)> settingsOf() {
    return [](core::JsonObject& object) -> std::any {
        S settings;
        readSettings(object, settings);
        return settings;
    };
}
std::any noSettings(core::JsonObject& object);

// Each method's node types (chain_file/nodes_<method>.cpp).
void addCommonNodeTypes(std::vector<NodeType>& types);
void addSvgfNodeTypes(std::vector<NodeType>& types);
void addEawNodeTypes(std::vector<NodeType>& types);
void addBmfrNodeTypes(std::vector<NodeType>& types);

const std::vector<NodeType>& nodeTypes();
const NodeType* findNodeType(std::string_view type);

} // namespace hush::passes::chain_file
