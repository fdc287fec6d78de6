#pragma once
// The node types a chain file can name, each with its ports and a function that
// adds it to a graph. One table (node_types.cpp), so `describeChainNodes()` and
// the loader's errors list exactly what exists.
#include <any>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <hush/passes/common/surface.hpp>
#include <hush/passes/node_context.hpp>
#include <hush/passes/svgf/temporal_accumulation.hpp>

#include "chain_file/json_reader.hpp"

namespace hush::passes::chain_file {

// What flows along a connection: a texture, or a node's bundle of textures.
enum class PortKind { Texture, Surface, Temporal };
using Value = std::variant<graph::TextureHandle, Surface, SvgfTemporal>;
std::string_view toString(PortKind kind);
PortKind kindOf(const Value& value);

struct PortSpec {
    std::string_view name;
    PortKind kind = PortKind::Texture;
    bool optional = false;
};

// What a node's build function gets.
struct NodeBuild {
    NodeContext& ctx;
    const std::string& name;                 // the node's id: its passes' name prefix
    std::span<const Value* const> inputs;    // by input port, nullptr when not connected
    const std::any& settings;
};

struct NodeType {
    std::string_view type;      // "svgf.atrous"
    std::string_view summary;
    std::vector<PortSpec> inputs;
    std::vector<PortSpec> outputs;   // the first one is what "<id>" alone refers to
    std::function<std::any(ObjectReader&)> readSettings;
    std::function<std::vector<Value>(const NodeBuild&)> build;
};

// svgf.temporal's settings: its own, and the svgf.atrous node that feeds back.
struct TemporalNodeSettings {
    SvgfTemporalSettings temporal;
    std::string colorHistory;
};

const std::vector<NodeType>& nodeTypes();
const NodeType* findNodeType(std::string_view type);

} // namespace hush::passes::chain_file
