#pragma once
// The frame format's conventions, checked on an integrator's frames (`hush check`).
// Integrations fail most often silently, on conventions: motion with the wrong sign,
// in NDC or pointing forward; normals in view space; a z-buffer value for depth;
// lighting in the albedo; sRGB radiance; a normalised meshid; a camera that does not
// match the pixels. Each check compares the data with what docs/frame-format.md says
// and with the plausible mistakes, and reports the evidence with its verdict.
#include <span>
#include <string>
#include <vector>

#include <hush/tracer/frame.hpp>

namespace hush::tracer {

enum class CheckVerdict { Pass, Fail, Skipped };

struct ConventionCheck {
    std::string convention;   // "motion", "camera", "normal", "depth", "meshid", "albedo", "radiance"
    CheckVerdict verdict = CheckVerdict::Skipped;
    std::string evidence;     // what was measured, and what it means; for Skipped, why
};

// Checks consecutive frames of one sequence (frames[i] follows frames[i - 1]; one
// frame is enough for every check but motion's). Checks needing a layer the frames
// lack are Skipped with the layer named. Throws hush::Error if the frames are empty
// or differ in size.
std::vector<ConventionCheck> checkFrameConventions(std::span<const Frame> frames);

const char* verdictName(CheckVerdict verdict);   // "pass", "FAIL", "skip"

} // namespace hush::tracer
