// core/atomic_file: a failed write never leaves half a file, nor a temporary.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <hush/core/atomic_file.hpp>
#include <hush/core/error.hpp>

using namespace hush;
namespace fs = std::filesystem;

namespace {
std::string readAll(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

fs::path freshFolder(const std::string& name) {
    const fs::path folder = fs::temp_directory_path() / ("hush-core-test-" + name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

size_t entries(const fs::path& folder) {
    return size_t(std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
}
} // namespace

TEST_CASE("atomic file: writes replace the whole file and leave no temporary", "[atomic]") {
    const fs::path folder = freshFolder("replace");
    const fs::path target = folder / "out.txt";
    core::writeFileAtomically(target, "first");
    core::writeFileAtomically(target, "second, longer");
    CHECK(readAll(target) == "second, longer");
    CHECK(entries(folder) == 1);
}

TEST_CASE("atomic file: a writer that fails keeps the old file and removes the temporary", "[atomic]") {
    const fs::path folder = freshFolder("fail");
    const fs::path target = folder / "out.bin";
    core::writeFileAtomically(target, "old");
    try {
        core::writeAtomically(target, [](const std::string& temporary) {
            std::ofstream(temporary) << "half";
            throw std::runtime_error("disk full");
        });
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::Io);
        CHECK(std::string(e.what()) == "cannot write '" + target.string() + "': disk full");
    }
    CHECK(readAll(target) == "old");
    CHECK(entries(folder) == 1);
}

TEST_CASE("atomic file: a missing folder is NotFound naming it, and nothing is created", "[atomic]") {
    const fs::path folder = freshFolder("missing");
    const fs::path target = folder / "no" / "such" / "out.txt";
    try {
        core::writeFileAtomically(target, "x");
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::NotFound);
        CHECK_THAT(e.what(), Catch::Contains((folder / "no" / "such").string()) && Catch::Contains("does not exist"));
    }
    CHECK(entries(folder) == 0);
}

TEST_CASE("atomic file: SIGTERM in the middle of a write leaves no temporary and the old file", "[atomic][signal]") {
    const fs::path folder = freshFolder("signal");
    const fs::path target = folder / "out.bin";
    core::writeFileAtomically(target, "old");
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {   // the child: a write that is stopped halfway
        core::removeTemporariesOnSignal();
        core::writeAtomically(target, [](const std::string& temporary) {
            std::ofstream(temporary) << "half";
            std::raise(SIGTERM);
        });
        std::_Exit(0);   // not reached: the signal ends the process
    }
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == SIGTERM);
    CHECK(readAll(target) == "old");
    CHECK(entries(folder) == 1);   // no "out.bin.tmp-<pid>"
}
