#include <hush/core/atomic_file.hpp>

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>

#include <hush/core/error.hpp>

namespace hush::core {

namespace fs = std::filesystem;

namespace {

// The temporaries being written now, for the signal handler: fixed storage, claimed
// and released with atomics, read with nothing but unlink() (async-signal-safe).
constexpr int kSlots = 32;
constexpr size_t kPathBytes = 4096;
char gTemporaries[kSlots][kPathBytes];
std::atomic<bool> gInUse[kSlots];

class TemporaryRecord {
public:
    explicit TemporaryRecord(const std::string& path) {
        if (path.size() >= kPathBytes) return;
        for (int i = 0; i < kSlots; ++i) {
            bool expected = false;
            if (gInUse[i].load() || !gInUse[i].compare_exchange_strong(expected, true)) continue;
            std::memcpy(gTemporaries[i], path.c_str(), path.size() + 1);
            slot_ = i;
            return;
        }
    }
    ~TemporaryRecord() {
        if (slot_ >= 0) gInUse[slot_].store(false);
    }
    TemporaryRecord(const TemporaryRecord&) = delete;
    TemporaryRecord& operator=(const TemporaryRecord&) = delete;

private:
    int slot_ = -1;
};

extern "C" void removeTemporariesAndDie(int signal) {
    for (int i = 0; i < kSlots; ++i)
        if (gInUse[i].load()) ::unlink(gTemporaries[i]);
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

} // namespace

void removeTemporariesOnSignal() {
    std::signal(SIGINT, removeTemporariesAndDie);
    std::signal(SIGTERM, removeTemporariesAndDie);
}

void writeAtomically(const fs::path& target, const std::function<void(const std::string& temporary)>& write) {
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::error_code ignored;
    if (!fs::is_directory(folder, ignored))
        throw Error(ErrorKind::NotFound,
                    "cannot write '" + target.string() + "': the folder '" + folder.string() + "' does not exist");
    const std::string temporary = target.string() + ".tmp-" + std::to_string(::getpid());
    const TemporaryRecord record(temporary);
    std::string failure;
    try {
        write(temporary);
        std::error_code error;
        fs::rename(temporary, target, error);
        if (!error) return;
        failure = error.message();
    } catch (const std::exception& e) {
        failure = e.what();
    }
    fs::remove(temporary, ignored);
    throw Error(ErrorKind::Io, "cannot write '" + target.string() + "': " + failure);
}

void writeFileAtomically(const fs::path& target, std::string_view bytes) {
    writeAtomically(target, [&](const std::string& temporary) {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) throw std::runtime_error(std::string("cannot create it: ") + std::strerror(errno));
        out.write(bytes.data(), std::streamsize(bytes.size()));
        out.close();
        // Only a closed stream tells that the last block reached the disk.
        if (!out) throw std::runtime_error(std::string("writing failed (disk full?): ") + std::strerror(errno));
    });
}

} // namespace hush::core
