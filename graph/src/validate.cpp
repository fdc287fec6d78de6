// Step 1: validate. Every problem is collected and reported at once, each naming the
// pass, the port and the resource, so one compile tells the user all that is wrong.
#include <algorithm>
#include <functional>
#include <map>
#include <string>

#include <hush/graph/compile_steps.hpp>
#include <hush/core/error.hpp>

#include "dependencies.hpp"

namespace hush::graph {

namespace {

std::string sizeText(rhi::Extent2D e) { return std::to_string(e.width) + "x" + std::to_string(e.height); }

std::string producerText(const GraphModel& m, const detail::Dependencies& deps, uint32_t r, uint32_t v) {
    const auto& res = m.resources[r];
    if (v == 0) {
        if (res.origin == ResourceOrigin::Imported) return "imported";
        if (res.origin == ResourceOrigin::History) return "last frame's value";
        return "created, not yet written";
    }
    const auto& p = deps.producers[r][v];
    return p.empty() ? "written by no pass" : "written by pass '" + m.passes[p.front()].name + "'";
}

void findCycles(const GraphModel& m, const detail::Dependencies& deps, std::vector<std::string>& errors) {
    enum Mark : uint8_t { White, Grey, Black };
    std::vector<Mark> mark(m.passes.size(), White);
    std::vector<uint32_t> stack;
    std::function<bool(uint32_t)> visit = [&](uint32_t p) {
        mark[p] = Grey;
        stack.push_back(p);
        for (uint32_t next : deps.edges[p]) {
            if (mark[next] == Grey) {
                std::string cycle;
                auto it = std::find(stack.begin(), stack.end(), next);
                for (; it != stack.end(); ++it) cycle += "'" + m.passes[*it].name + "' -> ";
                errors.push_back("cycle between passes: " + cycle + "'" + m.passes[next].name + "'");
                return true;
            }
            if (mark[next] == White && visit(next)) return true;
        }
        stack.pop_back();
        mark[p] = Black;
        return false;
    };
    for (uint32_t p = 0; p < m.passes.size(); ++p)
        if (mark[p] == White && visit(p)) return;   // one cycle is enough to act on
}

} // namespace

void validate(const GraphModel& m) {
    std::vector<std::string> errors;
    const detail::Dependencies deps(m);

    std::map<std::string, uint32_t> passNames;
    for (uint32_t p = 0; p < m.passes.size(); ++p) {
        auto [it, fresh] = passNames.emplace(m.passes[p].name, p);
        if (!fresh) errors.push_back("two passes are named '" + m.passes[p].name + "'; pass names must be unique");
    }

    for (uint32_t p = 0; p < m.passes.size(); ++p) {
        const auto& pass = m.passes[p];
        std::map<uint32_t, std::vector<Access>> perResource;
        for (const auto& a : pass.accesses) {
            const std::string kind = isWrite(a.access) ? "output" : "input";
            const std::string port = kind + " '" + a.port + "' of pass '" + pass.name + "'";
            if (a.resource == kNone) {
                if (!a.optional) errors.push_back(port + " is not connected");
                continue;
            }
            if (a.resource >= m.resources.size()) {
                errors.push_back(port + " uses an unknown resource handle (#" + std::to_string(a.resource) +
                                 "): it does not come from this graph");
                continue;
            }
            const auto& res = m.resources[a.resource];
            const std::string what = "'" + res.name + "'";
            if (a.version >= res.versionCount) {
                errors.push_back(port + " uses version " + std::to_string(a.version) + " of " + what +
                                 ", which does not exist");
                continue;
            }
            if (a.version < a.latestAtDeclaration)
                errors.push_back(port + " uses a stale handle: version " + std::to_string(a.version) + " of " + what +
                                 ", but version " + std::to_string(a.latestAtDeclaration) + " was already " +
                                 producerText(m, deps, a.resource, a.latestAtDeclaration) +
                                 "; use the handle that write returned");
            const bool textureAccess = a.access == Access::SampledRead || a.access == Access::CopySrc ||
                                       a.access == Access::CopyDst;
            if (res.kind == ResourceKind::Buffer && textureAccess)
                errors.push_back(port + " uses buffer " + what + " as a texture (" + toString(a.access) + ")");
            if (res.kind == ResourceKind::Texture && a.access == Access::UniformRead)
                errors.push_back(port + " uses texture " + what + " as a uniform buffer");
            if (isWrite(a.access) && res.origin == ResourceOrigin::History)
                errors.push_back(port + " writes history " + what + ", which is read-only (write the texture '" +
                                 res.name + "' this frame instead)");
            if (isRead(a.access) && a.version == 0 && res.origin == ResourceOrigin::Transient)
                errors.push_back(port + " reads " + what + ", which no pass writes before it");
            if (a.expectFormat && res.kind == ResourceKind::Texture && *a.expectFormat != res.texture.format)
                errors.push_back(port + " expects format " + std::string(rhi::toString(*a.expectFormat)) + ", but " +
                                 what + " (" + producerText(m, deps, a.resource, a.version) + ") is " +
                                 std::string(rhi::toString(res.texture.format)));
            if (a.expectSize && res.kind == ResourceKind::Texture) {
                const auto want = a.expectSize->resolve(m.outputSize), have = res.texture.size.resolve(m.outputSize);
                if (!(want == have))
                    errors.push_back(port + " expects extent " + sizeText(want) + ", but " + what + " (" +
                                     producerText(m, deps, a.resource, a.version) + ") is " + sizeText(have));
            }
            perResource[a.resource].push_back(a.access);
        }
        // One pass may not use a texture in two image layouts at once.
        for (const auto& [r, accesses] : perResource) {
            bool sampled = false, storage = false, copy = false;
            for (Access a : accesses) {
                sampled |= a == Access::SampledRead;
                storage |= a == Access::StorageRead || a == Access::StorageWrite || a == Access::StorageReadWrite;
                copy |= a == Access::CopySrc || a == Access::CopyDst;
            }
            if (int(sampled) + int(storage) + int(copy) > 1 ||
                (copy && std::count(accesses.begin(), accesses.end(), Access::CopySrc) &&
                 std::count(accesses.begin(), accesses.end(), Access::CopyDst)))
                errors.push_back("pass '" + pass.name + "' uses '" + m.resources[r].name +
                                 "' in two incompatible ways (e.g. sampled and storage) at once");
        }
    }

    for (uint32_t r = 0; r < m.resources.size(); ++r) {
        const auto& res = m.resources[r];
        for (uint32_t v = 1; v < deps.producers[r].size(); ++v) {
            const auto& writers = deps.producers[r][v];
            if (writers.size() > 1)
                errors.push_back("passes '" + m.passes[writers[0]].name + "' and '" + m.passes[writers[1]].name +
                                 "' both write version " + std::to_string(v - 1) + " of '" + res.name +
                                 "' with no order between them; chain the second write on the first's result");
        }
        if (res.origin == ResourceOrigin::Imported && res.initialState == rhi::ResourceState::Undefined) {
            // Allowed: the frame then ignores what was in it before.
        }
        if (res.origin == ResourceOrigin::History) {
            bool read = false;
            for (const auto& readers : deps.readers[r]) read = read || !readers.empty();
            if (!read) continue;
            const uint32_t source = m.historySource(r);
            if (source == kNone) {
                errors.push_back("history '" + res.name + "' is read, but bound to no texture to come from "
                                 "(RenderGraph::bindHistory, or history(source))");
                continue;
            }
            if (source >= m.resources.size() || m.resources[source].origin != ResourceOrigin::Transient ||
                m.resources[source].kind != ResourceKind::Texture) {
                errors.push_back("history '" + res.name + "' is bound to a resource that is not a texture some pass "
                                 "creates");
                continue;
            }
            const auto& src = m.resources[source];
            if (!(src.texture == res.texture))
                errors.push_back("history '" + res.name + "' is declared as " +
                                 std::string(rhi::toString(res.texture.format)) + " " +
                                 sizeText(res.texture.size.resolve(m.outputSize)) + ", but the texture it comes from ('" +
                                 src.name + "') is " + std::string(rhi::toString(src.texture.format)) + " " +
                                 sizeText(src.texture.size.resolve(m.outputSize)));
        }
    }

    findCycles(m, deps, errors);

    if (errors.empty()) return;
    std::string message = "render graph is invalid (" + std::to_string(errors.size()) +
                          (errors.size() == 1 ? " problem):" : " problems):");
    for (const auto& e : errors) message += "\n  - " + e;
    throw Error(ErrorKind::InvalidArgument, message);
}

} // namespace hush::graph
