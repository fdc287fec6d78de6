// White furnace: inside a closed box whose every surface emits Le and reflects with
// albedo a, the path tracer with B indirect bounces sees the truncated series
// L = Le (1 + a + ... + a^(B+1)) everywhere. Any lost or double-counted energy in
// next-event estimation, MIS, the BRDF or the geometry shows up as a bias.
#include <cmath>

#include <catch2/catch.hpp>

#include <hush/tracer/renderer.hpp>

using namespace hush::tracer;

namespace {

Scene furnace(glm::vec3 albedo, glm::vec3 emission, glm::vec3 specular = glm::vec3(0.0f), float roughness = 0.5f) {
    Scene s;
    s.name = "furnace";
    Material m;
    m.name = "wall";
    m.albedo = albedo;
    m.specular = specular;
    m.roughness = roughness;
    m.emission = emission;
    m.doubleSidedEmission = true;   // the box's faces wind outwards; they must light the inside
    s.materials = {m};
    Mesh box;
    box.name = "box";
    for (int i = 0; i < 8; ++i)
        box.positions.push_back(glm::vec3(i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f, i & 4 ? 1.0f : -1.0f));
    const int quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (const auto& q : quads) {
        box.triangles.push_back(glm::uvec3(q[0], q[1], q[2]));
        box.triangles.push_back(glm::uvec3(q[0], q[2], q[3]));
    }
    s.meshes = {box};
    s.camera.keys = {CameraKey{0.0f, {0.0f, 0.0f, 0.5f}, {0.3f, 0.2f, -1.0f}, {0.0f, 1.0f, 0.0f}, 70.0f}};
    return s;
}

struct Stats {
    double mean = 0.0, standardError = 0.0;
};

// The mean over many 1-spp frames (independent samples), with its standard error.
Stats meanColor(const Renderer& renderer, uint32_t bounces, uint32_t frames, int component = 0) {
    RenderSettings settings;
    settings.width = 48;
    settings.height = 48;
    settings.bounces = bounces;
    settings.channels = {Channel::Color};
    double sum = 0.0, squares = 0.0;
    size_t n = 0;
    for (uint32_t f = 0; f < frames; ++f) {
        const Frame frame = renderer.render(f, settings);   // keep it: get() returns a reference into it
        const Image& color = frame.get(Channel::Color);
        for (size_t i = size_t(component); i < color.pixels.size(); i += 3) {
            sum += color.pixels[i];
            squares += double(color.pixels[i]) * color.pixels[i];
            ++n;
        }
    }
    Stats s;
    s.mean = sum / double(n);
    s.standardError = std::sqrt(std::max(0.0, squares / double(n) - s.mean * s.mean) / double(n));
    return s;
}

double truncatedSeries(double emission, double albedo, uint32_t bounces) {
    double total = 0.0, term = emission;
    for (uint32_t k = 0; k <= bounces + 1; ++k, term *= albedo) total += term;
    return total;
}

} // namespace

TEST_CASE("white furnace: a closed diffuse box converges to the analytic radiance", "[tracer][furnace]") {
    const double albedo = 0.5, emission = 1.0;
    const Renderer renderer(furnace(glm::vec3(float(albedo)), glm::vec3(float(emission))));
    for (uint32_t bounces : {0u, 1u, 3u}) {
        const Stats s = meanColor(renderer, bounces, 24);
        const double expected = truncatedSeries(emission, albedo, bounces);
        INFO("bounces " << bounces << ": mean " << s.mean << " +- " << s.standardError << ", expected " << expected);
        // Five standard errors: a real bias of 0.3 % (what lost grazing energy caused)
        // is far outside it at these sample counts.
        REQUIRE(std::abs(s.mean - expected) < 5.0 * s.standardError + 1e-4);
    }
}

TEST_CASE("white furnace: per-channel albedo and emission stay separate", "[tracer][furnace]") {
    const glm::vec3 albedo(0.8f, 0.4f, 0.1f), emission(0.5f, 1.0f, 2.0f);
    const Renderer renderer(furnace(albedo, emission));
    for (int c = 0; c < 3; ++c) {
        const Stats s = meanColor(renderer, 2, 16, c);
        const double expected = truncatedSeries(emission[c], albedo[c], 2);
        INFO("channel " << c << ": mean " << s.mean << " +- " << s.standardError << ", expected " << expected);
        REQUIRE(std::abs(s.mean - expected) < 5.0 * s.standardError + 1e-4);
    }
}

TEST_CASE("white furnace: a fully reflective glossy coat conserves energy", "[tracer][furnace]") {
    // With F0 = 1 the coat reflects everything it can (1 - F = 0): a single-scattering
    // GGX reflector, whose directional albedo is at most 1 (test_brdf checks it
    // against quadrature) and, at alpha 0.3, above 0.5 at every angle. So the mean
    // lies between the series for a = 0.5 and for a = 1.
    const Renderer renderer(furnace(glm::vec3(0.0f), glm::vec3(1.0f), glm::vec3(1.0f), 0.3f));
    const Stats s = meanColor(renderer, 1, 16);
    INFO("mean " << s.mean << " +- " << s.standardError);
    REQUIRE(s.mean <= truncatedSeries(1.0, 1.0, 1) + 5.0 * s.standardError);
    REQUIRE(s.mean >= truncatedSeries(1.0, 0.5, 1) - 5.0 * s.standardError);
}
