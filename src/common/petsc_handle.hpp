// Owning handles for PETSc/SLEPc objects and error checking that throws, so
// every object is destroyed on every path (a failed solve must not leak a
// factor of several GiB before the error reaches the user).
#pragma once

#include <petscksp.h>

#include <stdexcept>
#include <string>
#include <utility>

namespace coremodal {

#define COREMODAL_PETSC(call)                                                                  \
    do {                                                                                       \
        PetscErrorCode coremodal_ierr_ = (call);                                               \
        if (coremodal_ierr_)                                                                   \
            throw std::runtime_error(std::string("PETSc error ") +                             \
                                     std::to_string(int(coremodal_ierr_)) + " in " #call);     \
    } while (0)

template <class T, PetscErrorCode (*Destroy)(T*)>
class PetscHandle {
public:
    PetscHandle() = default;
    explicit PetscHandle(T object) : object_(object) {}
    ~PetscHandle() { reset(); }
    PetscHandle(PetscHandle&& other) noexcept : object_(std::exchange(other.object_, nullptr)) {}
    PetscHandle& operator=(PetscHandle&& other) noexcept {
        if (this != &other) {
            reset();
            object_ = std::exchange(other.object_, nullptr);
        }
        return *this;
    }
    PetscHandle(const PetscHandle&) = delete;
    PetscHandle& operator=(const PetscHandle&) = delete;

    T get() const { return object_; }
    T* out() { reset(); return &object_; }  // for PETSc's Create(..., &object) calls
    operator T() const { return object_; }
    void reset() {
        if (object_) Destroy(&object_);
        object_ = nullptr;
    }

private:
    T object_ = nullptr;
};

using PetscMatrix = PetscHandle<Mat, MatDestroy>;
using PetscVector = PetscHandle<Vec, VecDestroy>;
using PetscIndexSet = PetscHandle<IS, ISDestroy>;
using PetscScatter = PetscHandle<VecScatter, VecScatterDestroy>;

inline int mpi_rank(MPI_Comm comm = PETSC_COMM_WORLD) {
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    return rank;
}
inline int mpi_size(MPI_Comm comm = PETSC_COMM_WORLD) {
    int size = 1;
    MPI_Comm_size(comm, &size);
    return size;
}

}  // namespace coremodal
