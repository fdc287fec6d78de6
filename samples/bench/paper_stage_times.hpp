#pragma once
// The stage times a paper publishes for its own implementation, mapped onto hush's
// passes, so that a benchmark can set each stage's share of the frame beside the
// paper's. Mara et al. 2017, Table 1: 1280x720, NVIDIA Titan X (Maxwell or Pascal:
// the paper says "Titan X"), Horse Room under fast camera motion.
#include <string>
#include <string_view>
#include <vector>

namespace hush::bench {

struct PaperStage {
    std::string_view label;                  // "3. Matte Temporal"
    std::vector<std::string_view> passes;    // hush's passes for it
    double paperMs = 0.0;
};

inline const std::vector<PaperStage>& paperStages(std::string_view chain) {
    static const std::vector<PaperStage> mara{
        {"3. Matte Temporal", {"mara.matte.temporal"}, 0.18},
        {"4. Matte Pre-Bilateral", {"mara.matte.pre_bilateral"}, 3.32},
        {"5. Disocclusion Detection", {"mara.matte.disocclusion.horizontal", "mara.matte.disocclusion.vertical"}, 0.76},
        {"6. Firefly Suppression", {"mara.matte.firefly"}, 0.55},
        {"7. Matte Bilateral", {"mara.matte.bilateral"}, 3.36},
        {"8. Glossy Temporal", {"mara.glossy.temporal"}, 0.23},
        {"9. Glossy H. Bilateral", {"mara.glossy.bilateral.horizontal"}, 0.34},
        {"10. Glossy V. Bilateral", {"mara.glossy.bilateral.vertical"}, 0.43},
    };
    static const std::vector<PaperStage> none;
    return chain == "mara" ? mara : none;
}

} // namespace hush::bench
