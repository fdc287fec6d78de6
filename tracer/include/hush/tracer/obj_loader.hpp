#pragma once
// Wavefront OBJ + MTL loading into hush::tracer::Mesh / Material (docs/scene-format.md).
// Our own parser, strict about what it understands: a malformed statement it knows
// (v, vn, vt, f, o, g, usemtl, mtllib; newmtl, Kd, Ks, Ns, Pr, Ke) throws hush::Error
// naming "file:line"; statements it does not use (s, l, p, illum, map_Kd, ...) are
// skipped. No input makes it crash or read out of bounds (it is fuzzed: scripts/fuzz.sh).
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <hush/tracer/scene.hpp>

namespace hush::tracer {

// The text of a file another file refers to (an OBJ's mtllib, a scene's "obj").
struct FileText {
    std::string name;   // how errors name it, e.g. the path it was read from
    std::string text;
};

// Resolves a path as written in the referring file (relative to that file's folder)
// and returns its text; throws hush::Error(NotFound) when it cannot. Parsing from
// memory passes a reader so that tests and fuzzers never touch the file system.
using FileReader = std::function<FileText(const std::string& pathAsWritten)>;

// Reads a whole file; throws hush::Error(NotFound) naming it when it cannot.
FileText readTextFile(const std::string& path);

// A reader that resolves relative paths against `folder` and reads from disk.
FileReader folderReader(const std::string& folder);

struct ObjOptions {
    // Inputs past these limits are rejected (a corrupt or hostile file must not
    // exhaust memory): counts of v, vn and vt each, and of triangles after fan
    // triangulation.
    std::size_t maxVertices = 50'000'000;
    std::size_t maxTriangles = 100'000'000;
    // Faces before any usemtl use the material of this name, appended to the
    // material list (albedo 0.8, matte) when no material of that name exists yet.
    std::string defaultMaterial = "default";
    // false: mtllib and usemtl are checked for syntax but not followed, and every
    // face uses defaultMaterial (a scene file overriding the OBJ's materials).
    bool loadMaterials = true;
};

// Parses OBJ text. `name` is used in errors ("name:line: ...") and, without its
// folder and extension, as the name of meshes outside any o/g statement.
// Meshes: one per (object/group, material) pair; vertices are compacted per mesh;
// polygons are fan-triangulated; per-vertex normals are kept when every corner of
// the mesh names a vn (else the mesh has none and the tracer uses face normals).
// Materials from mtllib files are appended to `materials`, except names already
// there (the earlier definition wins); Mesh::material indexes `materials`.
// Without a reader, an mtllib statement is an error.
std::vector<Mesh> parseObj(std::string_view text, const std::string& name, std::vector<Material>& materials,
                           const ObjOptions& options = {}, const FileReader& readFile = {});

// Reads and parses an OBJ file; mtllib paths are relative to the OBJ's folder.
std::vector<Mesh> loadObj(const std::string& path, std::vector<Material>& materials, const ObjOptions& options = {});

// Parses MTL text into materials in file order. Conversions (documented in
// docs/scene-format.md): Kd -> albedo, Ks -> specular (F0), Ke -> emission,
// Ns -> roughness = sqrt(2 / (Ns + 2)) (Blinn-Phong to GGX alpha, Walter et al.
// 2007), Pr -> roughness = Pr^2 (the PBR extension's perceptual roughness; it wins
// over Ns). Texture maps (map_*, bump, disp, ...) are ignored.
std::vector<Material> parseMtl(std::string_view text, const std::string& name);
std::vector<Material> loadMtl(const std::string& path);

} // namespace hush::tracer
