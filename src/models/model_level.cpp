#include "models/model_level.hpp"

#include "common/petsc_handle.hpp"

namespace coremodal {

void warn_about_model(const std::string& source, const std::string& warning, std::vector<std::string>& warnings) {
    if (mpi_rank() == 0) std::cerr << "coremodal: warning: " << source << ": " << warning << std::endl;
    warnings.push_back(warning);
}

}  // namespace coremodal
