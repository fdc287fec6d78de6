#include "hazard_check.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

namespace hush::passes_test {

namespace {

using Json = nlohmann::json;

bool writes(const std::string& state) {
    return state == "storage-write" || state == "storage-read-write" || state == "copy-dst" || state == "general";
}
bool reads(const std::string& state) { return state != "storage-write" && state != "copy-dst"; }

// Bytes per texel of the formats the graphs use; an unknown one stops the check
// rather than guess a size for the aliasing rule.
uint64_t texelBytes(const std::string& format) {
    static const std::map<std::string, uint64_t> kBytes = {
        {"rgba32float", 16}, {"rgba16float", 8}, {"rg32float", 8}, {"rg16float", 4}, {"r32float", 4},
        {"r16float", 2},     {"r32uint", 4},     {"r32sint", 4},   {"rgba8unorm", 4}, {"rgba32uint", 16},
        {"rg32uint", 8},     {"r8unorm", 1},     {"rgba8uint", 4}, {"rg16uint", 4}};
    const auto it = kBytes.find(format);
    if (it == kBytes.end()) throw std::runtime_error("hazard check: no texel size for format '" + format + "'");
    return it->second;
}

struct Resource {
    std::string name, origin;
    bool placed = false;   // in the transient memory block
    uint64_t offset = 0, bytes = 0;
    uint32_t first = 0, last = 0;
    int64_t historySource = -1;   // a history: the transient it holds last frame's value of
};

constexpr int kNoWriter = -1;
constexpr int kLastFrame = -2;   // written by the previous frame, no barrier since

struct Track {
    bool seen = false;         // a barrier or an access earlier this frame
    std::string state;         // "" until known
    int writer = kNoWriter;    // position of the last writer since the last barrier
    std::set<int> readers;     // positions of readers since the last barrier
    bool firstBarrierAliased = false;
    bool hadBarrier = false;
};

std::vector<Resource> readResources(const Json& dump) {
    std::vector<Resource> out;
    for (const Json& r : dump.at("resources")) {
        Resource res;
        res.name = r.at("name");
        res.origin = r.at("origin");
        if (r.contains("memoryOffset")) {
            res.placed = true;
            res.offset = r.at("memoryOffset");
            res.bytes = r.contains("bytes") ? r.at("bytes").get<uint64_t>()
                                            : uint64_t(r.at("extent")[0]) * uint64_t(r.at("extent")[1]) *
                                                  texelBytes(r.at("format"));
        }
        if (r.contains("historySource")) res.historySource = r.at("historySource");
        if (r.contains("lifetime")) {
            res.first = r.at("lifetime")[0];
            res.last = r.at("lifetime")[1];
        }
        out.push_back(res);
    }
    return out;
}

std::vector<const Json*> livePassesInOrder(const Json& dump) {
    std::vector<const Json*> live;
    for (const Json& p : dump.at("passes"))
        if (!p.at("culled").get<bool>()) live.push_back(&p);
    std::sort(live.begin(), live.end(),
              [](const Json* a, const Json* b) { return a->at("order").get<int>() < b->at("order").get<int>(); });
    return live;
}

class Replay {
public:
    explicit Replay(const Json& dump) : resources_(readResources(dump)), tracks_(resources_.size()) {}

    void pass(int position, const Json& pass) {
        const std::string name = pass.at("name");
        for (const Json& b : pass.at("barriers")) barrier(name, b);
        for (const Json& a : pass.at("accesses"))
            if (a.at("resource").get<int64_t>() >= 0) access(position, name, a.at("resource"), a.at("access"));
    }

    // Transients that reuse memory an earlier one used must say so in their first barrier.
    void checkAliasing() {
        for (size_t b = 0; b < resources_.size(); ++b) {
            const Resource& later = resources_[b];
            if (!later.placed || tracks_[b].firstBarrierAliased) continue;
            for (const Resource& earlier : resources_) {
                if (!earlier.placed || earlier.last >= later.first) continue;
                const bool overlap = earlier.offset < later.offset + later.bytes &&
                                     later.offset < earlier.offset + earlier.bytes;
                if (overlap) {
                    problems_.push_back(later.name + ": placed over " + earlier.name +
                                        "'s memory, but its first barrier is not marked aliased");
                    break;
                }
            }
        }
    }

    // A history texture is what its source was at the end of the previous frame:
    // that state, and a write no barrier covered yet.
    void startAfter(const Replay& previousFrame) {
        for (size_t h = 0; h < resources_.size(); ++h) {
            if (resources_[h].historySource < 0) continue;
            const Track& source = previousFrame.tracks_[size_t(resources_[h].historySource)];
            tracks_[h].seen = source.seen;
            tracks_[h].state = source.state;
            tracks_[h].writer = source.writer == kNoWriter ? kNoWriter : kLastFrame;
        }
    }

    std::vector<std::string> problems() const { return problems_; }

private:
    void barrier(const std::string& pass, const Json& b) {
        // By index: a history carries its source's name.
        const size_t r = b.at("resourceIndex");
        Track& t = tracks_[r];
        const std::string before = b.at("before"), after = b.at("after");
        if (t.seen && !t.state.empty() && before != t.state)
            problems_.push_back(pass + ": barrier on " + resources_[r].name + " from '" + before +
                                "', but the resource is in '" + t.state + "' (the earlier accesses are not covered)");
        if (!t.hadBarrier) t.firstBarrierAliased = b.at("aliased").get<bool>();
        t.hadBarrier = t.seen = true;
        t.state = after;
        t.writer = kNoWriter;
        t.readers.clear();
    }

    void access(int position, const std::string& pass, size_t r, const std::string& state) {
        Track& t = tracks_[r];
        const std::string& resource = resources_[r].name;
        if (!t.seen && resources_[r].origin != "imported")
            problems_.push_back(pass + ": first use of " + resource +
                                " this frame without a barrier (the previous frame used its memory)");
        if (!t.state.empty() && state != t.state)
            problems_.push_back(pass + ": uses " + resource + " as '" + state + "' while it is in '" + t.state + "'");
        if (reads(state) && t.writer != kNoWriter && t.writer != position)
            problems_.push_back(pass + ": reads " + resource + " after a write with no barrier between");
        if (writes(state)) {
            if (t.writer != kNoWriter && t.writer != position)
                problems_.push_back(pass + ": writes " + resource + " after a write with no barrier between");
            for (const int reader : t.readers)
                if (reader != position) {
                    problems_.push_back(pass + ": writes " + resource + " after a read with no barrier between");
                    break;
                }
            t.writer = position;
        }
        if (reads(state)) t.readers.insert(position);
        if (t.state.empty()) t.state = state;
        t.seen = true;
    }

    std::vector<Resource> resources_;
    std::vector<Track> tracks_;
    std::vector<std::string> problems_;
};

} // namespace

std::vector<std::string> findHazards(const nlohmann::json& graphDump) {
    const auto live = livePassesInOrder(graphDump);
    // Two frames: the first gives the state each history starts the second in.
    Replay first(graphDump), second(graphDump);
    for (size_t i = 0; i < live.size(); ++i) first.pass(int(i), *live[i]);
    second.startAfter(first);
    for (size_t i = 0; i < live.size(); ++i) second.pass(int(i), *live[i]);
    second.checkAliasing();
    return second.problems();
}

} // namespace hush::passes_test
