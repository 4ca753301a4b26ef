// A named stage of our own code in PETSc's profile (-log_view): the time
// spent between construction and destruction, summed per name, beside
// PETSc's and SLEPc's own events. Costs nothing measurable when -log_view
// is not given (PETSc's default logging records a counter and a time).
#pragma once

#include "common/petsc_handle.hpp"

#include <petsclog.h>

namespace coremodal {

class LogEvent {
public:
    // `name`: a string literal, at most 32 characters (PETSc's event names).
    explicit LogEvent(const char* name) : id_(registered(name)) { COREMODAL_PETSC(PetscLogEventBegin(id_, 0, 0, 0, 0)); }
    ~LogEvent() { PetscLogEventEnd(id_, 0, 0, 0, 0); }
    LogEvent(const LogEvent&) = delete;
    LogEvent& operator=(const LogEvent&) = delete;

private:
    static PetscLogEvent registered(const char* name) {
        PetscLogEvent id = -1;
        if (PetscLogEventGetId(name, &id) == 0 && id >= 0) return id;
        static const PetscClassId cls = [] {
            PetscClassId c;
            COREMODAL_PETSC(PetscClassIdRegister("coremodal", &c));
            return c;
        }();
        COREMODAL_PETSC(PetscLogEventRegister(name, cls, &id));
        return id;
    }
    PetscLogEvent id_;
};

}  // namespace coremodal
