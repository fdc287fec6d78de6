// MTL parsing: newmtl, Kd, Ks, Ns, Pr, Ke; everything else is skipped. The
// conversions to hush's layered Lambert + GGX material are in docs/scene-format.md.
#include <cmath>
#include <cstdint>
#include <map>

#include <hush/core/error.hpp>
#include <hush/tracer/obj_loader.hpp>

#include "text_parse.hpp"

namespace hush::tracer {

namespace {

using detail::failAt;
using detail::quote;

struct MtlParser {
    const std::string& name;
    std::size_t line = 0;

    [[noreturn]] void fail(const std::string& what) const { failAt(ErrorKind::InvalidArgument, name, line, what); }

    float number(std::string_view token, const std::string& statement) const {
        float v = 0.0f;
        if (!detail::parseFloat(token, v))
            fail(statement + ": bad number " + quote(token) + " (expected a finite decimal number)");
        return v;
    }

    // Kd, Ks, Ke: one number (grey) or three (RGB), none negative. "Kd spectral ..."
    // and "Kd xyz ..." name other colour spaces hush does not read.
    glm::vec3 colour(std::string_view rest, const std::string& statement) const {
        float v[3] = {0.0f, 0.0f, 0.0f};
        int count = 0;
        for (std::string_view t = detail::nextToken(rest); !t.empty(); t = detail::nextToken(rest)) {
            if (count == 3) fail(statement + " needs 1 or 3 numbers, got more");
            if (t == "spectral" || t == "xyz")
                fail(statement + " " + std::string(t) + " is not supported: give an RGB colour");
            v[count] = number(t, statement);
            if (v[count] < 0.0f) fail(statement + ": " + quote(t) + " is negative (colours must be >= 0)");
            ++count;
        }
        if (count == 0) fail(statement + " needs 1 or 3 numbers, got none");
        if (count == 2) fail(statement + " needs 1 or 3 numbers, got 2");
        return count == 1 ? glm::vec3(v[0]) : glm::vec3(v[0], v[1], v[2]);
    }

    float scalar(std::string_view rest, const std::string& statement) const {
        const std::string_view t = detail::nextToken(rest);
        if (t.empty()) fail(statement + " needs a number");
        const float v = number(t, statement);
        if (!detail::nextToken(rest).empty()) fail(statement + " takes one number, got more");
        return v;
    }
};

} // namespace

std::vector<Material> parseMtl(std::string_view text, const std::string& name) {
    std::vector<Material> materials;
    // Per material: the line where it was defined (duplicate names are an error) and
    // whether Pr was given (Pr wins over Ns whatever their order).
    std::map<std::string, std::size_t, std::less<>> definedAt;
    // Negative: not given in the current material (valid values are >= 0).
    float ns = -1.0f, pr = -1.0f;
    auto finishRoughness = [&] {
        if (materials.empty()) return;
        if (pr >= 0.0f) materials.back().roughness = pr * pr;
        else if (ns >= 0.0f) materials.back().roughness = std::sqrt(2.0f / (ns + 2.0f));
    };

    MtlParser p{name};
    detail::LineReader lines(text);
    std::string_view line;
    while (lines.next(line)) {
        p.line = lines.lineNumber();
        std::string_view rest = detail::stripComment(line);
        const std::string_view keyword = detail::nextToken(rest);
        if (keyword.empty()) continue;

        if (keyword == "newmtl") {
            finishRoughness();
            ns = pr = -1.0f;
            const std::string_view matName = detail::trim(rest);
            if (matName.empty()) p.fail("newmtl needs a material name");
            if (const auto it = definedAt.find(matName); it != definedAt.end())
                p.fail("material " + quote(matName) + " is defined twice (first at line " + std::to_string(it->second) +
                       ")");
            definedAt.emplace(std::string(matName), p.line);
            materials.push_back(Material{.name = std::string(matName)});
            continue;
        }

        const bool known = keyword == "Kd" || keyword == "Ks" || keyword == "Ke" || keyword == "Ns" || keyword == "Pr";
        if (!known) continue;   // Ka, d, Tr, Ni, illum, map_*, bump, ...: not part of hush's material model
        const std::string statement(keyword);
        if (materials.empty()) p.fail(statement + " before any newmtl");
        Material& m = materials.back();
        if (keyword == "Kd") {
            m.albedo = p.colour(rest, statement);
        } else if (keyword == "Ks") {
            m.specular = p.colour(rest, statement);
        } else if (keyword == "Ke") {
            m.emission = p.colour(rest, statement);
        } else if (keyword == "Ns") {
            const float v = p.scalar(rest, statement);
            if (v < 0.0f) p.fail("Ns must be >= 0, got " + std::to_string(v));
            ns = v;
        } else {
            const float v = p.scalar(rest, statement);
            if (v < 0.0f || v > 1.0f) p.fail("Pr must be in [0, 1], got " + std::to_string(v));
            pr = v;
        }
    }
    finishRoughness();
    return materials;
}

std::vector<Material> loadMtl(const std::string& path) {
    const FileText file = readTextFile(path);
    return parseMtl(file.text, file.name);
}

} // namespace hush::tracer
