#include "durability/quantiles.hpp"

#include "common/error.hpp"

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>

namespace coremodal {

double student_t_upper_limit(double confidence, int dof) {
    COREMODAL_ASSERT(confidence > 0 && confidence < 1 && dof >= 1);
    return boost::math::quantile(boost::math::students_t(dof), confidence);
}

double chi_squared_quantile(double p, int dof) {
    COREMODAL_ASSERT(p > 0 && p < 1 && dof >= 1);
    return boost::math::quantile(boost::math::chi_squared(dof), p);
}

double chi_squared_lower_limit(double confidence, int dof) { return chi_squared_quantile(1 - confidence, dof); }

double normal_quantile(double p) {
    COREMODAL_ASSERT(p > 0 && p < 1);
    return boost::math::quantile(boost::math::normal(), p);
}

}  // namespace coremodal
