// A results folder that appears complete or not at all: files are written
// into "<path>.partial-<pid>" and the folder is renamed into place by
// commit(). A run that fails leaves nothing behind (the destructor removes
// the partial folder), and an older result at <path> survives until the new
// one is complete.
#pragma once

#include <filesystem>
#include <string>

namespace coremodal {

class ResultsFolder {
public:
    explicit ResultsFolder(std::filesystem::path final_path);
    ~ResultsFolder();
    ResultsFolder(const ResultsFolder&) = delete;
    ResultsFolder& operator=(const ResultsFolder&) = delete;

    // Path of a file inside the (partial) folder.
    std::string file(const std::string& name) const;
    void commit();
    const std::filesystem::path& final_path() const { return final_; }

private:
    std::filesystem::path final_, partial_;
    bool committed_ = false;
};

}  // namespace coremodal
