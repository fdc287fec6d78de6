// OBJ parsing: v, vn, vt, f, o, g, usemtl, mtllib; other statements are skipped.
// Vertices live in one pool per file (indices are global), while hush's meshes are
// self-contained, so faces are collected per (object/group, material) and each mesh
// gets its own compacted vertex arrays at the end.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>

#include <hush/core/error.hpp>
#include <hush/tracer/obj_loader.hpp>

#include "text_parse.hpp"

namespace hush::tracer {

namespace {

using detail::quote;

constexpr std::uint32_t kNoNormal = UINT32_MAX;

struct Corner {
    std::uint32_t v;
    std::uint32_t n;   // kNoNormal: the corner names no vn
};

struct MeshBuilder {
    std::string base;            // the o/g name
    std::uint32_t material;
    std::vector<Corner> corners; // three per triangle
    bool allNormals = true;
};

class ObjParser {
public:
    ObjParser(const std::string& name, std::vector<Material>& materials, const ObjOptions& options,
              const FileReader& readFile)
        : name_(name), materials_(materials), options_(options), readFile_(readFile) {}

    std::vector<Mesh> run(std::string_view text) {
        detail::LineReader lines(text);
        std::string_view line;
        while (lines.next(line)) {
            line_ = lines.lineNumber();
            std::string_view rest = detail::stripComment(line);
            const std::string_view keyword = detail::nextToken(rest);
            if (keyword.empty()) continue;
            if (keyword == "v") vertex(rest);
            else if (keyword == "vn") normal(rest);
            else if (keyword == "vt") texcoord(rest);
            else if (keyword == "f") face(rest);
            else if (keyword == "o") setName(object_, rest, true);
            else if (keyword == "g") setName(group_, rest, false);
            else if (keyword == "usemtl") useMaterial(rest);
            else if (keyword == "mtllib") materialLibrary(rest);
            // Anything else (s, l, p, vp, curves, ...) has no meaning for a triangle
            // tracer; skipping it lets files from any exporter load.
        }
        return finish();
    }

private:
    [[noreturn]] void fail(const std::string& what, ErrorKind kind = ErrorKind::InvalidArgument) const {
        detail::failAt(kind, name_, line_, what);
    }

    float number(std::string_view token, const char* statement) const {
        float v = 0.0f;
        if (!detail::parseFloat(token, v))
            fail(std::string(statement) + ": bad number " + quote(token) + " (expected a finite decimal number)");
        return v;
    }

    // Up to `capacity` numbers from the rest of the line; returns how many there were
    // (more than `capacity` returns capacity + 1 without parsing the extra ones).
    int numbers(std::string_view rest, const char* statement, float* out, int capacity) const {
        int count = 0;
        for (std::string_view t = detail::nextToken(rest); !t.empty(); t = detail::nextToken(rest)) {
            if (count == capacity) return capacity + 1;
            out[count++] = number(t, statement);
        }
        return count;
    }

    void checkCount(std::size_t count, const char* what) const {
        if (count >= options_.maxVertices)
            fail("more than " + std::to_string(options_.maxVertices) + " " + what + " (ObjOptions limit)");
    }

    void vertex(std::string_view rest) {
        float v[7];
        const int n = numbers(rest, "v", v, 7);
        if (n != 3 && n != 4 && n != 6)   // x y z, x y z w, or x y z r g b (w and colour unused)
            fail("v needs 3 coordinates (optionally followed by w or an RGB colour), got " +
                 (n > 6 ? std::string("more than 6 numbers") : std::to_string(n)));
        checkCount(positions_.size(), "vertices");
        positions_.emplace_back(v[0], v[1], v[2]);
    }

    void normal(std::string_view rest) {
        float v[3];
        const int n = numbers(rest, "vn", v, 3);
        if (n != 3) fail("vn needs 3 numbers, got " + (n > 3 ? std::string("more") : std::to_string(n)));
        // In double: the squared length of a float vector can overflow a float.
        const double len = std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]);
        if (!(len > 1e-30)) fail("vn has zero length: a normal needs a direction");
        checkCount(normals_.size(), "normals");
        normals_.emplace_back(float(v[0] / len), float(v[1] / len), float(v[2] / len));
    }

    void texcoord(std::string_view rest) {
        float v[3];
        const int n = numbers(rest, "vt", v, 3);
        if (n < 1 || n > 3) fail("vt needs 1 to 3 numbers, got " + (n > 3 ? std::string("more") : std::to_string(n)));
        checkCount(texcoords_, "texture coordinates");
        ++texcoords_;   // parsed for validation and for vt indices in faces; not used by the tracer
    }

    // OBJ indices start at 1; negative ones count back from the latest element (-1 = last).
    std::uint32_t resolve(std::string_view token, std::size_t count, const char* kind, const char* plural) const {
        std::int64_t raw = 0;
        if (!detail::parseInt(token, raw))
            fail(std::string(kind) + " index " + quote(token) + " is not an integer");
        const std::string defined = std::to_string(count) + " " + plural + " defined so far";
        if (raw == 0) fail(std::string(kind) + " index 0 is invalid (OBJ indices start at 1; -1 is the last)");
        if (raw > 0) {
            if (static_cast<std::uint64_t>(raw) > count)
                fail(std::string(kind) + " index " + std::to_string(raw) + " is past the " + defined);
            return static_cast<std::uint32_t>(raw - 1);
        }
        // raw < 0; -raw cannot overflow once raw is known to be >= -count.
        if (raw < -static_cast<std::int64_t>(count))
            fail(std::string(kind) + " index " + std::to_string(raw) + " reaches before the first of the " + defined);
        return static_cast<std::uint32_t>(static_cast<std::int64_t>(count) + raw);
    }

    Corner corner(std::string_view token) const {
        // v, v/vt, v//vn or v/vt/vn.
        std::string_view parts[3];
        int count = 0;
        std::size_t start = 0;
        while (true) {
            const std::size_t slash = token.find('/', start);
            if (count == 3) fail("bad face vertex " + quote(token) + " (expected v, v/vt, v//vn or v/vt/vn)");
            parts[count++] = token.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
            if (slash == std::string_view::npos) break;
            start = slash + 1;
        }
        if (parts[0].empty()) fail("bad face vertex " + quote(token) + " (the vertex index is missing)");
        Corner c{resolve(parts[0], positions_.size(), "face", "vertices"), kNoNormal};
        if (!parts[1].empty()) resolve(parts[1], texcoords_, "texture coordinate", "texture coordinates");
        if (!parts[2].empty()) c.n = resolve(parts[2], normals_.size(), "normal", "normals");
        return c;
    }

    void face(std::string_view rest) {
        polygon_.clear();
        for (std::string_view t = detail::nextToken(rest); !t.empty(); t = detail::nextToken(rest)) {
            polygon_.push_back(corner(t));
            // A face cannot add more triangles than the limit allows; stop before the
            // corner list itself grows past it.
            if (polygon_.size() > 2 && polygon_.size() - 2 > options_.maxTriangles) break;
        }
        if (polygon_.size() < 3)
            fail("face needs at least 3 vertices, got " + std::to_string(polygon_.size()));
        const std::size_t triangles = polygon_.size() - 2;
        if (triangles > options_.maxTriangles - triangles_)
            fail("more than " + std::to_string(options_.maxTriangles) + " triangles (ObjOptions limit)");
        triangles_ += triangles;
        MeshBuilder& mesh = currentMesh();
        // Fan triangulation: exact for convex polygons, which is what exporters write.
        for (std::size_t i = 1; i + 1 < polygon_.size(); ++i) {
            for (const Corner& c : {polygon_[0], polygon_[i], polygon_[i + 1]}) {
                mesh.corners.push_back(c);
                mesh.allNormals = mesh.allNormals && c.n != kNoNormal;
            }
        }
    }

    void setName(std::string& target, std::string_view rest, bool isObject) {
        const std::string_view n = detail::trim(rest);
        if (isObject) {
            if (n.empty()) fail("o needs an object name");
            group_.clear();   // groups belong to the object they appear in
        }
        target = std::string(n);   // "g" alone returns to the default (unnamed) group
        current_.reset();
    }

    std::uint32_t findMaterial(std::string_view n) const {
        for (std::size_t i = 0; i < materials_.size(); ++i)
            if (materials_[i].name == n) return static_cast<std::uint32_t>(i);
        return UINT32_MAX;
    }

    void useMaterial(std::string_view rest) {
        const std::string_view n = detail::trim(rest);
        if (n.empty()) fail("usemtl needs a material name");
        if (!options_.loadMaterials) return;   // the caller overrides every material
        const std::uint32_t index = findMaterial(n);
        if (index == UINT32_MAX) {
            std::string known;
            for (std::size_t i = 0; i < materials_.size() && i < 20; ++i)
                known += (i ? ", " : "") + quote(materials_[i].name);
            fail("usemtl " + quote(n) + ": no material of that name (known so far: " +
                 (known.empty() ? std::string("none; is an mtllib missing?") : known) + ")");
        }
        material_ = index;
        current_.reset();
    }

    void materialLibrary(std::string_view rest) {
        if (detail::trim(rest).empty()) fail("mtllib needs a file name");
        if (!options_.loadMaterials) return;
        for (std::string_view t = detail::nextToken(rest); !t.empty(); t = detail::nextToken(rest)) {
            const std::string file(t);
            if (!loadedLibraries_.insert(file).second) continue;
            if (!readFile_) fail("mtllib " + quote(t) + ": no file access when parsing from memory", ErrorKind::NotFound);
            std::vector<Material> loaded;
            try {
                const FileText mtl = readFile_(file);
                loaded = parseMtl(mtl.text, mtl.name);
            } catch (const Error& e) {
                fail("mtllib " + quote(t) + ": " + e.what(), e.kind());
            }
            for (Material& m : loaded)
                if (findMaterial(m.name) == UINT32_MAX) materials_.push_back(std::move(m));
        }
    }

    MeshBuilder& currentMesh() {
        if (current_) return builders_[*current_];
        std::uint32_t material = material_ ? *material_ : findMaterial(options_.defaultMaterial);
        if (material == UINT32_MAX) {
            material = static_cast<std::uint32_t>(materials_.size());
            materials_.push_back(Material{.name = options_.defaultMaterial});
        }
        std::string base = object_.empty() ? group_ : group_.empty() ? object_ : object_ + "/" + group_;
        if (base.empty()) base = detail::fileStem(name_);
        // Returning to an earlier (group, material) pair continues that mesh.
        const auto [it, added] = meshIndex_.try_emplace({base, material}, builders_.size());
        if (added) builders_.push_back(MeshBuilder{std::move(base), material, {}});
        current_ = it->second;
        return builders_[it->second];
    }

    std::vector<Mesh> finish() {
        std::map<std::string, int> perBase;
        for (const MeshBuilder& b : builders_)
            if (!b.corners.empty()) ++perBase[b.base];
        std::vector<Mesh> meshes;
        for (MeshBuilder& b : builders_) {
            if (b.corners.empty()) continue;
            Mesh mesh;
            // A group with several materials becomes several meshes: tell them apart.
            mesh.name = perBase[b.base] > 1 ? b.base + ":" + materials_[b.material].name : b.base;
            mesh.material = b.material;
            // Compact: each distinct (position, normal) pair becomes one mesh vertex.
            std::unordered_map<std::uint64_t, std::uint32_t> remap;
            auto vertexOf = [&](const Corner& c) {
                const std::uint32_t n = b.allNormals ? c.n : 0;
                const auto [it, added] = remap.try_emplace((std::uint64_t(c.v) << 32) | n,
                                                           static_cast<std::uint32_t>(mesh.positions.size()));
                if (added) {
                    mesh.positions.push_back(positions_[c.v]);
                    if (b.allNormals) mesh.normals.push_back(normals_[c.n]);
                }
                return it->second;
            };
            mesh.triangles.reserve(b.corners.size() / 3);
            for (std::size_t i = 0; i + 2 < b.corners.size(); i += 3) {
                // One statement per corner: argument evaluation order is unspecified,
                // and the order decides the vertex numbering.
                const std::uint32_t a = vertexOf(b.corners[i]);
                const std::uint32_t c1 = vertexOf(b.corners[i + 1]);
                const std::uint32_t c2 = vertexOf(b.corners[i + 2]);
                mesh.triangles.emplace_back(a, c1, c2);
            }
            std::vector<Corner>().swap(b.corners);   // free as we go: large files hold both copies otherwise
            meshes.push_back(std::move(mesh));
        }
        return meshes;
    }

    const std::string& name_;
    std::vector<Material>& materials_;
    const ObjOptions& options_;
    const FileReader& readFile_;

    std::size_t line_ = 0;
    std::vector<glm::vec3> positions_, normals_;
    std::size_t texcoords_ = 0;
    std::size_t triangles_ = 0;
    std::string object_, group_;
    std::optional<std::uint32_t> material_;
    std::optional<std::size_t> current_;
    std::map<std::pair<std::string, std::uint32_t>, std::size_t> meshIndex_;
    std::vector<MeshBuilder> builders_;
    std::vector<Corner> polygon_;
    std::set<std::string> loadedLibraries_;
};

} // namespace

std::vector<Mesh> parseObj(std::string_view text, const std::string& name, std::vector<Material>& materials,
                           const ObjOptions& options, const FileReader& readFile) {
    return ObjParser(name, materials, options, readFile).run(text);
}

std::vector<Mesh> loadObj(const std::string& path, std::vector<Material>& materials, const ObjOptions& options) {
    const FileText file = readTextFile(path);
    const std::string folder = std::filesystem::path(path).parent_path().string();
    return parseObj(file.text, file.name, materials, options, folderReader(folder.empty() ? "." : folder));
}

} // namespace hush::tracer
