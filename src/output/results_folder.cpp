#include "output/results_folder.hpp"

#include <unistd.h>

namespace coremodal {
namespace fs = std::filesystem;

ResultsFolder::ResultsFolder(fs::path final_path) : final_(std::move(final_path)) {
    partial_ = final_;
    partial_ += ".partial-" + std::to_string(::getpid());
    fs::remove_all(partial_);
    fs::create_directories(partial_);
}

ResultsFolder::~ResultsFolder() {
    if (!committed_) {
        std::error_code ignored;
        fs::remove_all(partial_, ignored);
    }
}

std::string ResultsFolder::file(const std::string& name) const { return (partial_ / name).string(); }

void ResultsFolder::commit() {
    fs::path old = final_;
    old += ".old-" + std::to_string(::getpid());
    const bool had_old = fs::exists(final_);
    if (had_old) fs::rename(final_, old);
    fs::rename(partial_, final_);
    if (had_old) fs::remove_all(old);
    committed_ = true;
}

}  // namespace coremodal
