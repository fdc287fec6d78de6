// core/json: errors name the document, the JSON path and the problem; no nlohmann
// exception escapes.
#include <catch2/catch.hpp>

#include <hush/core/json.hpp>

using namespace hush;
using core::Json;
using core::JsonObject;
using core::JsonValue;

namespace {
std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}
} // namespace

TEST_CASE("json: syntax errors give source:line:column, other failures the source", "[json]") {
    CHECK(errorOf([] { core::parseJson("{\n  \"a\": tru\n}", "x.json"); }).rfind("x.json:2:11: JSON syntax error: ", 0) == 0);
    CHECK(errorOf([] { core::parseJson("", "x.json"); }).rfind("x.json:1:1: JSON syntax error: ", 0) == 0);
    CHECK(errorOf([] { core::parseJson("{\"a\": 1e999}", "x.json"); }).rfind("x.json: JSON error: number overflow", 0) == 0);
    // Comments are allowed.
    CHECK(core::parseJson("// note\n{\"a\": /* one */ 1}", "x.json")["a"] == 1);
}

TEST_CASE("json: a key given twice in one object is an error naming the key and the object", "[json]") {
    CHECK(errorOf([] { core::parseJson(R"({"base": "svgf", "base": "eaw"})", "c.json"); }) ==
          "c.json: key 'base' appears twice in one object");
    CHECK(errorOf([] { core::parseJson(R"({"settings": {"atrous": {"sigmaL": 1, "sigmaL": 2}}})", "c.json"); }) ==
          "c.json: settings.atrous: key 'sigmaL' appears twice in one object");
    // Equal keys in different objects, in sibling objects of an array, and after a
    // nested object closes are fine.
    const Json ok = core::parseJson(R"({"a": {"x": 1}, "b": {"x": 2}, "list": [{"x": 1}, {"x": 2}], "c": 3})", "c.json");
    CHECK(ok["b"]["x"] == 2);
    CHECK(ok["list"][1]["x"] == 2);
}

TEST_CASE("json: positions count lines and columns from 1", "[json]") {
    const auto p = core::positionOf("ab\ncd\nef", 4);
    CHECK(p.line == 2);
    CHECK(p.column == 2);
    CHECK(core::positionOf("abc", 99).column == 4);   // clamped to the end
}

TEST_CASE("json: typed accessors name the path of the value", "[json]") {
    const Json doc = core::parseJson(R"({"a": {"b": [1, "s", -2, 0.5, true, 1e39]}})", "d.json");
    const JsonValue list = JsonObject(doc, "d.json", "").require("a");
    const JsonValue b = JsonObject(list).require("b");
    CHECK(b.arraySize() == 6);
    CHECK(b[0].number() == 1.0f);
    CHECK(errorOf([&] { b[1].number(); }) == "d.json: a.b[1]: must be a number");
    CHECK(errorOf([&] { b[2].nonNegative(); }) == "d.json: a.b[2]: must be >= 0, got -2.000000");
    CHECK(errorOf([&] { b[3].index(); }) == "d.json: a.b[3]: must be a non-negative integer");
    CHECK(errorOf([&] { b[4].string(); }) == "d.json: a.b[4]: must be a string");
    CHECK(errorOf([&] { b[5].number(); }) == "d.json: a.b[5]: number out of range for a float");
    CHECK(errorOf([&] { b[0].number(2.0f, 3.0f); }).find("a.b[0]: must be in [2.000000, 3.000000], got 1") != std::string::npos);
    CHECK(errorOf([&] { b.arraySize(7); }) == "d.json: a.b: must have at least 7 items, has 6");
    CHECK(errorOf([&] { b[0].arraySize(); }) == "d.json: a.b[0]: must be an array");
    CHECK(b[0].integer(0, 5) == 1u);
    CHECK(errorOf([&] { b[3].integer(0, 5); }).find("must be an integer in [0, 5], got 0.5") != std::string::npos);
}

TEST_CASE("json: an object rejects unknown keys, listing the known ones", "[json]") {
    const Json doc = core::parseJson(R"({"alpha": 0.5, "sigma": 2, "flag": true, "name": "n", "typo": 1})", "c.json");
    JsonObject o(doc, "c.json", "settings");
    float alpha = 0, sigma = 0;
    bool flag = false;
    std::string name;
    o.read("alpha", alpha, 0.0f, 1.0f);
    o.read("sigma", sigma, 0.0f, 10.0f);
    o.read("flag", flag);
    o.read("name", name);
    o.read("absent", alpha, 0.0f, 1.0f);   // absent: unchanged, but known
    CHECK(alpha == 0.5f);
    CHECK(sigma == 2.0f);
    CHECK(flag);
    CHECK(name == "n");
    CHECK(errorOf([&] { o.finish(); }) ==
          "c.json: settings: unknown field 'typo' (known fields: alpha, sigma, flag, name, absent)");
    CHECK(errorOf([&] { o.require("missing"); }) == "c.json: settings: missing field 'missing'");

    JsonObject early(doc, "c.json", "");
    CHECK(errorOf([&] { early.only({"alpha", "sigma", "flag", "name"}); }) ==
          "c.json: unknown field 'typo' (known fields: alpha, sigma, flag, name)");
    CHECK(errorOf([] {
              const Json a = Json::array();
              JsonObject bad(a, "c.json", "");
          }) == "c.json: (top level): must be a JSON object");
}
