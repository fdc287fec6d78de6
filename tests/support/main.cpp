// The test binary's main: runs the Catch2 session, then fails the process if any
// validation message was recorded at all, by any test or by tearing the shared
// device down (leaked objects are reported when a VkDevice is destroyed).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <iostream>

#include "support/gpu_context.hpp"

int main(int argc, char* argv[]) {
    Catch::Session session;
    if (int rc = session.applyCommandLine(argc, argv); rc != 0) return rc;
    int rc = session.run();

    hush::test::releaseGpu();
    const auto messages = hush::test::validationMessagesSince(0);
    if (!messages.empty()) {
        std::cerr << "\nFAILED: " << messages.size() << " Vulkan validation message(s) during this run:\n"
                  << hush::test::joinMessages(messages);
        if (rc == 0) rc = 1;
    }
    return rc;
}
