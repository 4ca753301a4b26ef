// Cylindrically orthotropic linear elastic materials.
//
// Axes: r (radial), theta (circumferential), z (axial), about the global z
// axis through x = y = 0. Voigt order in the cylindrical frame:
//   (rr, tt, zz, tz, rz, rt) with engineering shear strains,
// and in the global frame (xx, yy, zz, yz, xz, xy).
// Poisson convention: nu_ij = -eps_j / eps_i under uniaxial sigma_i, so
// nu_ij / E_i = nu_ji / E_j (Jones 1999, ch. 2).
#pragma once

#include <Eigen/Dense>
#include <optional>
#include <string>

namespace coremodal {

using Matrix6 = Eigen::Matrix<double, 6, 6>;

struct OrthotropicMaterial {
    std::string name;
    double E_r = 0, E_theta = 0, E_z = 0;           // Pa
    double G_rtheta = 0, G_rz = 0, G_thetaz = 0;    // Pa
    double nu_rtheta = 0, nu_rz = 0, nu_thetaz = 0;  // nu_ij, convention above
    double density = 0;                               // kg/m^3
    std::string source;  // where the values come from, or "user"

    static OrthotropicMaterial isotropic(std::string name, double E, double nu, double density,
                                         std::string source = "user");
    bool is_isotropic() const;
};

// 6x6 compliance S (strain = S * stress) in the cylindrical frame.
Matrix6 compliance_cylindrical(const OrthotropicMaterial& m);
// 6x6 stiffness C = S^-1 in the cylindrical frame.
Matrix6 stiffness_cylindrical(const OrthotropicMaterial& m);
// Empty when the compliance matrix is positive definite (and all moduli and the
// density positive); otherwise a sentence saying why not, e.g.
// "compliance matrix is not positive definite: 1 - nu_rz*nu_zr - ... = -0.2 <= 0".
std::optional<std::string> why_not_admissible(const OrthotropicMaterial& m);
// The stiffness given in the cylindrical frame, expressed in the global frame
// at a point with polar angle theta (radians) about the z axis.
Matrix6 rotate_to_global(const Matrix6& C_cylindrical, double theta);

}  // namespace coremodal
