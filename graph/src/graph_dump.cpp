// dump: the compiled graph as Graphviz DOT (to look at) and JSON (to process).
#include <cstdio>
#include <sstream>

#include <hush/core/atomic_file.hpp>
#include <hush/core/error.hpp>
#include <hush/graph/render_graph.hpp>

#include "compiled_graph.hpp"

namespace hush::graph {

namespace {

std::string escape(const std::string& s) {
    std::string out;
    for (char ch : s) {
        if (ch == '"' || ch == '\\') out += '\\';
        if (ch == '\n') {
            out += "\\n";
            continue;
        }
        out += ch;
    }
    return out;
}

const char* originName(ResourceOrigin o) {
    switch (o) {
    case ResourceOrigin::Transient: return "transient";
    case ResourceOrigin::Imported: return "imported";
    case ResourceOrigin::History: return "history";
    }
    return "?";
}

std::string extentText(rhi::Extent2D e) { return std::to_string(e.width) + "x" + std::to_string(e.height); }

} // namespace

std::string RenderGraph::dumpDot() const {
    const auto& c = compiled();
    std::ostringstream o;
    o << "digraph \"" << escape(desc_.label) << "\" {\n  rankdir=LR;\n  node [fontname=\"monospace\", fontsize=10];\n";
    std::vector<int> position(model_.passes.size(), -1);
    for (size_t i = 0; i < c.order.size(); ++i) position[c.order[i]] = int(i);
    for (uint32_t p = 0; p < model_.passes.size(); ++p) {
        const auto& pass = model_.passes[p];
        const bool alive = c.cull.passAlive[p];
        o << "  p" << p << " [shape=box, style=filled, ";
        if (!alive) {
            o << "fillcolor=\"#dddddd\", fontcolor=\"#888888\", label=\"" << escape(pass.name) << "\\n(culled)\"];\n";
            continue;
        }
        const int pos = position[p];
        o << "fillcolor=\"#cfe2ff\", label=\"" << pos << ": " << escape(pass.name);
        if (timings_.valid) o << "\\n" << timings_.passes[size_t(pos)].gpuMs << " ms";
        for (const auto& b : c.barriers.beforePass[size_t(pos)])
            o << "\\nbarrier " << escape(model_.resources[b.resource].name) << ": " << rhi::toString(b.before) << " -> "
              << rhi::toString(b.after) << (b.discard ? " (discard)" : "");
        o << "\"];\n";
    }
    for (uint32_t r = 0; r < model_.resources.size(); ++r) {
        const auto& res = model_.resources[r];
        const bool used = c.cull.resourceUsed[r];
        o << "  r" << r << " [shape=ellipse, style=filled, fillcolor=\"" << (used ? "#fff3cd" : "#eeeeee") << "\", label=\""
          << escape(res.name) << "\\n" << originName(res.origin);
        if (res.kind == ResourceKind::Texture)
            o << " " << rhi::toString(res.texture.format) << " " << extentText(c.extents[r]);
        else
            o << " buffer " << (c.buffers[r] ? c.buffers[r].size() : res.buffer.size) << " B";
        if (c.lifetimes[r].used()) o << "\\nlife " << c.lifetimes[r].first << ".." << c.lifetimes[r].last;
        if (c.memoryOffset[r] != kNone)
            o << "\\noffset " << c.memoryOffset[r] << (c.aliased[r] ? " (aliased)" : "");
        o << "\"];\n";
    }
    for (uint32_t p = 0; p < model_.passes.size(); ++p)
        for (const auto& a : model_.passes[p].accesses) {
            if (a.resource >= model_.resources.size()) continue;
            if (isRead(a.access)) o << "  r" << a.resource << " -> p" << p << " [label=\"" << escape(a.port) << "\"];\n";
            if (isWrite(a.access)) o << "  p" << p << " -> r" << a.resource << " [label=\"" << escape(a.port) << "\"];\n";
        }
    o << "}\n";
    return o.str();
}

std::string RenderGraph::dumpJson() const {
    const auto& c = compiled();
    std::ostringstream o;
    o << "{\n  \"label\": \"" << escape(desc_.label) << "\",\n  \"outputSize\": [" << c.outputSize.width << ", "
      << c.outputSize.height << "],\n  \"passes\": [\n";
    std::vector<int> position(model_.passes.size(), -1);
    for (size_t i = 0; i < c.order.size(); ++i) position[c.order[i]] = int(i);
    for (uint32_t p = 0; p < model_.passes.size(); ++p) {
        const auto& pass = model_.passes[p];
        const int pos = position[p];
        o << "    {\"name\": \"" << escape(pass.name) << "\", \"culled\": " << (pos < 0 ? "true" : "false")
          << ", \"order\": " << pos << ", \"sideEffect\": " << (pass.sideEffect ? "true" : "false");
        if (pos >= 0 && timings_.valid) o << ", \"gpuMs\": " << timings_.passes[size_t(pos)].gpuMs;
        o << ", \"accesses\": [";
        for (size_t i = 0; i < pass.accesses.size(); ++i) {
            const auto& a = pass.accesses[i];
            o << (i ? ", " : "") << "{\"port\": \"" << escape(a.port) << "\", \"resource\": "
              << (a.resource == kNone ? -1 : int64_t(a.resource)) << ", \"version\": " << a.version
              << ", \"access\": \"" << toString(a.access) << "\"}";
        }
        o << "], \"barriers\": [";
        if (pos >= 0) {
            const auto& list = c.barriers.beforePass[size_t(pos)];
            for (size_t i = 0; i < list.size(); ++i)
                o << (i ? ", " : "") << "{\"resource\": \"" << escape(model_.resources[list[i].resource].name)
                  << "\", \"resourceIndex\": " << list[i].resource << ", \"before\": \"" << rhi::toString(list[i].before) << "\", \"after\": \""
                  << rhi::toString(list[i].after) << "\", \"discard\": " << (list[i].discard ? "true" : "false")
                  << ", \"aliased\": " << (list[i].aliased ? "true" : "false") << "}";
        }
        o << "]}" << (p + 1 < model_.passes.size() ? "," : "") << "\n";
    }
    o << "  ],\n  \"resources\": [\n";
    for (uint32_t r = 0; r < model_.resources.size(); ++r) {
        const auto& res = model_.resources[r];
        o << "    {\"name\": \"" << escape(res.name) << "\", \"origin\": \"" << originName(res.origin)
          << "\", \"kind\": \"" << (res.kind == ResourceKind::Texture ? "texture" : "buffer") << "\"";
        if (res.kind == ResourceKind::Texture)
            o << ", \"format\": \"" << rhi::toString(res.texture.format) << "\", \"extent\": [" << c.extents[r].width
              << ", " << c.extents[r].height << "]";
        else
            o << ", \"bytes\": " << (c.buffers[r] ? c.buffers[r].size() : res.buffer.size);
        o << ", \"used\": " << (c.cull.resourceUsed[r] ? "true" : "false") << ", \"output\": "
          << (res.output ? "true" : "false") << ", \"versions\": " << res.versionCount;
        if (c.lifetimes[r].used()) o << ", \"lifetime\": [" << c.lifetimes[r].first << ", " << c.lifetimes[r].last << "]";
        if (c.memoryOffset[r] != kNone)
            o << ", \"memoryOffset\": " << c.memoryOffset[r] << ", \"aliasSlot\": " << c.aliasSlot[r]
              << ", \"aliased\": " << (c.aliased[r] ? "true" : "false");
        if (res.origin == ResourceOrigin::History && res.historySource != kNone)
            o << ", \"historySource\": " << res.historySource;
        o << ", \"historyPair\": " << (c.historyPair[r] ? "true" : "false") << "}"
          << (r + 1 < model_.resources.size() ? "," : "") << "\n";
    }
    o << "  ],\n  \"frameEndBarriers\": " << c.barriers.frameEnd.size() << ",\n  \"barriersPerFrame\": "
      << c.barriers.count() << ",\n  \"memory\": {\"transientAliasedBytes\": " << c.memory.transientAliasedBytes
      << ", \"transientUnaliasedBytes\": " << c.memory.transientUnaliasedBytes << ", \"historyBytes\": "
      << c.memory.historyBytes << ", \"outputBytes\": " << c.memory.outputBytes << "},\n  \"timings\": {\"valid\": "
      << (timings_.valid ? "true" : "false") << ", \"frame\": " << timings_.frame << ", \"totalGpuMs\": "
      << timings_.totalGpuMs << ", \"cpuRecordMs\": " << timings_.cpuRecordMs << "}\n}\n";
    return o.str();
}

void RenderGraph::writeDump(const std::string& pathWithoutExtension) const {
    core::writeFileAtomically(pathWithoutExtension + ".dot", dumpDot());
    core::writeFileAtomically(pathWithoutExtension + ".json", dumpJson());
}

} // namespace hush::graph
