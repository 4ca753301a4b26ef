// Errors that reach the user. An InputError carries a fully formatted message
// ("cases/x.toml:14:18: [core] inner_diameter = 0.2 m must be smaller than ...")
// and makes the program exit non-zero without writing results.
#pragma once

#include <stdexcept>
#include <string>

namespace coremodal {

// Bad input from the user: a case file, a mesh file, a command-line option.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A numerical failure the user can act on (a solve that did not converge,
// a mode count that does not match the inertia of the shifted factor).
class SolveError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Internal invariant; a bug in coremodal, never the user's fault.
#define COREMODAL_ASSERT(expr)                                                                 \
    do {                                                                                       \
        if (!(expr))                                                                           \
            throw std::logic_error(std::string("internal error: ") + __FILE__ + ":" +          \
                                   std::to_string(__LINE__) + ": assertion failed: " #expr);  \
    } while (0)

}  // namespace coremodal
