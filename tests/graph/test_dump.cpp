// dump(): Graphviz DOT and JSON of the compiled graph. The JSON is parsed by a small
// strict parser below, then checked field by field.
#include <catch2/catch.hpp>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include <unistd.h>

#include "graph/graph_test_util.hpp"

using namespace hush;
using namespace hush::graph;
using namespace hush::graph_test;
using hush::test::gpu;
using hush::test::ValidationScope;
using Catch::Matchers::Contains;

namespace {

// A JSON value, as parsed; only what the checks below need.
struct Json {
    enum class Type { Null, Bool, Number, String, Array, Object } type = Type::Null;
    bool boolean = false;
    double number = 0.0;
    std::string string;
    std::vector<Json> array;
    std::map<std::string, Json> object;

    bool has(const std::string& key) const { return type == Type::Object && object.count(key) != 0; }
    const Json& operator[](const std::string& key) const {
        const auto it = object.find(key);
        if (it == object.end()) throw std::runtime_error("JSON: no key '" + key + "'");
        return it->second;
    }
};

// RFC 8259, strictly: throws std::runtime_error naming the offset of the first error.
class JsonParser {
public:
    explicit JsonParser(std::string_view text) : s_(text) {}
    Json parse() {
        Json v = value();
        space();
        if (i_ != s_.size()) fail("trailing characters");
        return v;
    }

private:
    [[noreturn]] void fail(const std::string& what) {
        throw std::runtime_error("JSON: " + what + " at offset " + std::to_string(i_));
    }
    void space() {
        while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\n' || s_[i_] == '\t' || s_[i_] == '\r')) ++i_;
    }
    bool eat(char c) {
        space();
        if (i_ < s_.size() && s_[i_] == c) {
            ++i_;
            return true;
        }
        return false;
    }
    void expect(char c) {
        if (!eat(c)) fail(std::string("expected '") + c + "'");
    }
    void literal(std::string_view word) {
        if (s_.substr(i_, word.size()) != word) fail("bad literal");
        i_ += word.size();
    }
    std::string str() {
        expect('"');
        std::string out;
        while (true) {
            if (i_ >= s_.size()) fail("unterminated string");
            const char c = s_[i_++];
            if (c == '"') return out;
            if (static_cast<unsigned char>(c) < 0x20) fail("control character in string");
            if (c != '\\') {
                out += c;
                continue;
            }
            if (i_ >= s_.size()) fail("unterminated escape");
            const char e = s_[i_++];
            if (e == 'u') {
                if (i_ + 4 > s_.size()) fail("short \\u escape");
                for (int k = 0; k < 4; ++k)
                    if (!std::isxdigit(static_cast<unsigned char>(s_[i_ + size_t(k)]))) fail("bad \\u escape");
                out += '?';
                i_ += 4;
            } else if (std::string_view("\"\\/bfnrt").find(e) != std::string_view::npos) {
                out += e == 'n' ? '\n' : e == 't' ? '\t' : e;
            } else {
                fail("bad escape");
            }
        }
    }
    Json value() {
        space();
        if (i_ >= s_.size()) fail("unexpected end");
        Json v;
        const char c = s_[i_];
        if (c == '{') {
            ++i_;
            v.type = Json::Type::Object;
            if (eat('}')) return v;
            do {
                space();
                std::string key = str();
                expect(':');
                if (!v.object.emplace(key, value()).second) fail("duplicate key '" + key + "'");
            } while (eat(','));
            expect('}');
        } else if (c == '[') {
            ++i_;
            v.type = Json::Type::Array;
            if (eat(']')) return v;
            do v.array.push_back(value());
            while (eat(','));
            expect(']');
        } else if (c == '"') {
            v.type = Json::Type::String;
            v.string = str();
        } else if (c == 't' || c == 'f') {
            v.type = Json::Type::Bool;
            v.boolean = c == 't';
            literal(c == 't' ? "true" : "false");
        } else if (c == 'n') {
            literal("null");
        } else {
            // -? (0 | [1-9][0-9]*) (.[0-9]+)? ([eE][+-]?[0-9]+)?
            const size_t start = i_;
            auto digits = [&] {
                const size_t from = i_;
                while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_;
                if (i_ == from) fail("expected a digit");
            };
            if (s_[i_] == '-') ++i_;
            if (i_ < s_.size() && s_[i_] == '0') {
                ++i_;
            } else {
                digits();
            }
            if (i_ < s_.size() && s_[i_] == '.') {
                ++i_;
                digits();
            }
            if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
                ++i_;
                if (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) ++i_;
                digits();
            }
            v.type = Json::Type::Number;
            v.number = std::strtod(std::string(s_.substr(start, i_ - start)).c_str(), nullptr);
        }
        return v;
    }

    std::string_view s_;
    size_t i_ = 0;
};

Json parseJson(const std::string& text) { return JsonParser(text).parse(); }

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// The DOT line of the node whose label starts with `name`.
std::string dotLineOf(const std::string& dot, const std::string& labelStart) {
    std::istringstream lines(dot);
    for (std::string line; std::getline(lines, line);)
        if (line.find("label=\"" + labelStart) != std::string::npos) return line;
    return {};
}

} // namespace

TEST_CASE("dump: the JSON parser used below rejects what is not JSON", "[graph][dump]") {
    CHECK_NOTHROW(parseJson(R"({"a": [1, -2.5e3, true, null, "x\"y"], "b": {}})"));
    CHECK_THROWS(parseJson(R"({"a": 1,})"));
    CHECK_THROWS(parseJson(R"({"a": nan})"));
    CHECK_THROWS(parseJson(R"({"a": 1} x)"));
    CHECK_THROWS(parseJson(R"({"a": 01})"));
    CHECK_THROWS(parseJson(R"({"a": 1, "a": 2})"));
}

TEST_CASE("dump: DOT and JSON describe passes, resources, lifetimes, memory, barriers and timings",
          "[graph][dump][gpu]") {
    ValidationScope validation;
    const auto p = makePipelines();
    constexpr uint32_t kW = 48, kH = 32;
    auto target = makeTexture("target", kW, kH);
    RenderGraph g(gpu().device, {.label = "dump \"test\""});
    g.setOutputSize({kW, kH});
    const auto out = g.importTexture("target", target,
                                     {.initialState = ResourceState::Undefined, .finalState = ResourceState::CopySrc});
    const auto a = addFill(g, p, "a", 1);
    const auto b = addCopy(g, p, "b", a, 1);
    const auto c = addCopy(g, p, "c", b, 2);   // a's lifetime is over: c can take its memory
    addCopy(g, p, "unused", a, 3);
    addCopyInto(g, p, "present", c, out, 0);
    for (int frame = 0; frame < 3; ++frame) g.execute();
    g.waitIdle();
    REQUIRE(g.timings().valid);
    REQUIRE(g.culledPasses() == std::vector<std::string>{"unused"});

    const auto dot = g.dumpDot();
    CHECK_THAT(dot, Contains("digraph \"dump \\\"test\\\"\" {"));
    for (const auto* name : {"a", "b", "c", "present"}) {
        INFO("pass " << name);
        CHECK_THAT(dot, Contains(std::string(": ") + name + "\\n"));   // "<position>: <name>\n<ms> ms"
    }
    const auto culledLine = dotLineOf(dot, "unused\\n(culled)");
    CHECK_THAT(culledLine, Contains("fillcolor=\"#dddddd\""));   // grey
    CHECK_THAT(culledLine, Contains("fontcolor=\"#888888\""));
    const auto liveLine = dotLineOf(dot, "0: a\\n");
    CHECK_THAT(liveLine, Contains("fillcolor=\"#cfe2ff\""));
    CHECK_THAT(liveLine, Contains(" ms"));
    CHECK_THAT(liveLine, Contains("barrier a: "));
    CHECK_THAT(dot, Contains("r32uint 48x32"));
    CHECK_THAT(dot, Contains("\\nlife 0..1"));   // a: written by pass 0, read by pass 1

    const auto text = g.dumpJson();
    Json json;
    REQUIRE_NOTHROW(json = parseJson(text));
    INFO(text);
    CHECK(json["label"].string == "dump \"test\"");
    CHECK(json["outputSize"].array.size() == 2);
    CHECK(json["outputSize"].array[0].number == kW);
    const auto& passes = json["passes"].array;
    REQUIRE(passes.size() == 5);
    const std::vector<std::string> names = {"a", "b", "c", "unused", "present"};
    for (size_t i = 0; i < passes.size(); ++i) {
        INFO("pass " << names[i]);
        const auto& pass = passes[i];
        CHECK(pass["name"].string == names[i]);
        const bool culled = names[i] == "unused";
        CHECK(pass["culled"].boolean == culled);
        CHECK(pass["order"].number == (culled ? -1 : i < 3 ? double(i) : 3.0));
        CHECK(pass["accesses"].array.size() >= 1);
        CHECK(pass["barriers"].type == Json::Type::Array);
        CHECK(pass.has("gpuMs") == !culled);
        if (!culled) CHECK(pass["gpuMs"].number >= 0.0);
    }
    // a's first write is preceded by a discarding barrier.
    REQUIRE(passes[0]["barriers"].array.size() == 1);
    const auto& barrier = passes[0]["barriers"].array[0];
    CHECK(barrier["resource"].string == "a");
    CHECK(barrier["after"].string == "storage-write");
    CHECK(barrier["discard"].boolean);
    CHECK(barrier.has("before"));
    CHECK(barrier.has("aliased"));

    const auto& resources = json["resources"].array;
    REQUIRE(resources.size() == g.model().resources.size());
    auto resource = [&](const std::string& name) -> const Json& {
        for (const auto& r : resources)
            if (r["name"].string == name) return r;
        FAIL("no resource '" << name << "' in the JSON");
        return resources.front();
    };
    const auto& ra = resource("a");
    CHECK(ra["origin"].string == "transient");
    CHECK(ra["kind"].string == "texture");
    CHECK(ra["format"].string == "r32uint");
    CHECK(ra["extent"].array[0].number == kW);
    CHECK(ra["extent"].array[1].number == kH);
    CHECK(ra["used"].boolean);
    CHECK(ra["lifetime"].array[0].number == 0);
    CHECK(ra["lifetime"].array[1].number == 1);
    CHECK(ra.has("memoryOffset"));
    CHECK(ra.has("aliasSlot"));
    CHECK(resource("c")["memoryOffset"].number == ra["memoryOffset"].number);   // disjoint lifetimes share
    CHECK(resource("c")["aliased"].boolean);
    CHECK(resource("target")["origin"].string == "imported");
    CHECK_FALSE(resource("target").has("memoryOffset"));   // imported: never aliased
    CHECK_FALSE(resource("unused")["used"].boolean);
    CHECK_FALSE(resource("unused").has("lifetime"));

    CHECK(json["barriersPerFrame"].number == double(g.barrierCount()));
    CHECK(json["frameEndBarriers"].number == 1);
    const auto memory = g.memory();
    CHECK(json["memory"]["transientAliasedBytes"].number == double(memory.transientAliasedBytes));
    CHECK(json["memory"]["transientUnaliasedBytes"].number == double(memory.transientUnaliasedBytes));
    CHECK(json["timings"]["valid"].boolean);
    CHECK(json["timings"]["frame"].number == double(g.timings().frame));
    CHECK(json["timings"]["totalGpuMs"].number >= 0.0);
    CHECK(json["timings"]["cpuRecordMs"].number >= 0.0);

    // writeDump: both files, exactly the two dumps, no temporary left behind.
    const auto dir = std::filesystem::temp_directory_path() / ("hush_graph_dump_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    g.writeDump((dir / "graph").string());
    CHECK(readFile(dir / "graph.dot") == dot);
    CHECK(readFile(dir / "graph.json") == text);
    size_t files = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++files;
    CHECK(files == 2);
    CHECK_THROWS_AS(g.writeDump((dir / "missing" / "graph").string()), Error);
    std::filesystem::remove_all(dir);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}
